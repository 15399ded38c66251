; expected: unsat,unsat
; Remark13.WorseTriangleByTangents (Remark13.WorseTriangleByTangents), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun y1 () Real)
(declare-fun y2 () Real)
(declare-fun x1 () Real)
(declare-fun x2 () Real)
(assert
 (> y1 0.0))
(assert
 (< y2 0.0))
(assert
 (and (<= (+ (* (- 1.0 x1) (- 1.0 x1)) (* y1 y1)) 1.0) (<= (+ (* x1 x1) (* y1 y1)) 1.0)))
(assert
 (and (<= (+ (* (- 1.0 x2) (- 1.0 x2)) (* y2 y2)) 1.0) (<= (+ (* x2 x2) (* y2 y2)) 1.0)))
(assert
 (let ((?x35 (- (* y2 (- (+ (* x1 x1) (* y1 y1)) x1)) (* y1 (- (+ (* x2 x2) (* y2 y2)) x2)))))
 (<= ?x35 0.0)))
(assert
 (<= x1 (/ 1.0 2.0)))
(assert
 (let (($x51 (< (* (* x1 x1) (+ (* x2 x2) (* y2 y2))) (* (* x2 x2) (+ (* x1 x1) (* y1 y1))))))
 (let ((?x12 (* y1 y1)))
 (let ((?x18 (* x1 x1)))
 (let ((?x19 (+ ?x18 ?x12)))
 (let ((?x23 (- 1.0 x2)))
 (let ((?x24 (* ?x23 ?x23)))
 (let ((?x22 (* y2 y2)))
 (let ((?x27 (* x2 x2)))
 (let ((?x28 (+ ?x27 ?x22)))
 (let ((?x14 (- 1.0 x1)))
 (let ((?x15 (* ?x14 ?x14)))
 (let (($x45 (or (< (* ?x15 (+ ?x24 ?x22)) (* ?x24 (+ ?x15 ?x12))) (< (* ?x15 ?x28) (* ?x27 (+ ?x15 ?x12))))))
 (not (and $x45 (or (< (* ?x18 (+ ?x24 ?x22)) (* ?x24 ?x19)) $x51))))))))))))))))
(push 1)
(assert (not (>= (* (- y2) (- 1.0 x1)) (* y1 (- 1.0 x2)))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (not (>= (* (- y2) (- 1.0 x1)) (* y1 x2))))
(check-sat-using qfnra-nlsat)
(pop 1)
