; expected: sat
; Theorem 14 (Theorem14.CentroidNotCollinearExceptRightIsosceles), written by `lepp theorems --prove`.
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
 (let ((?x22 (* y2 y2)))
 (let ((?x27 (* x2 x2)))
 (let ((?x28 (+ ?x27 ?x22)))
 (let ((?x25 (+ (* (- 1.0 x2) (- 1.0 x2)) ?x22)))
 (let ((?x12 (* y1 y1)))
 (let ((?x18 (* x1 x1)))
 (let ((?x19 (+ ?x18 ?x12)))
 (let ((?x16 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x12)))
 (let (($x49 (and (and (= (+ (- ?x18 x1) ?x12) 0.0) (= ?x16 ?x19)) (and (= (+ (- ?x27 x2) ?x22) 0.0) (= ?x25 ?x28)))))
 (let (($x38 (= (+ y1 y2) 0.0)))
 (let (($x50 (=> $x38 $x49)))
 (not $x50)))))))))))))
(check-sat-using qfnra-nlsat)
