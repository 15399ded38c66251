; expected: unsat,unsat,unsat,unsat
; Theorem 2 (equality) (Theorem2.EqualityCaseCocircularWithEquilateral), written by `lepp theorems --prove`.
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
 (let ((?x12 (* y1 y1)))
 (let ((?x18 (* x1 x1)))
 (let ((?x19 (+ ?x18 ?x12)))
 (let ((?x16 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x12)))
 (let (($x44 (= (* (* 4.0 (+ (- ?x18 x1) ?x12)) (+ (- ?x18 x1) ?x12)) (* ?x16 ?x19))))
 (and (< (+ (- ?x18 x1) ?x12) 0.0) $x44)))))))
(push 1)
(assert (let ((a!1 (= (+ (* (- 1.0 x2) (- 1.0 x2)) (* y2 y2)) 1.0)))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (not (= (+ (* x2 x2) (* y2 y2)) 1.0)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (* y2 (- (+ (* x1 x1) (* y1 y1)) x1)))
      (a!2 (* y1 (- (+ (* x2 x2) (* y2 y2)) x2))))
  (not (= (- a!1 a!2) 0.0))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (* 3.0 (+ (- (* x1 x1) x1) (* y1 y1)) (+ (- (* x1 x1) x1) (* y1 y1)))))
  (not (= a!1 (* y1 y1)))))
(check-sat-using qfnra-nlsat)
(pop 1)
