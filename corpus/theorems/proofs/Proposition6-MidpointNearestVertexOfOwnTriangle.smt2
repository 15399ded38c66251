; expected: unsat,unsat
; Proposition 6 (a) (Proposition6.MidpointNearestVertexOfOwnTriangle), written by `lepp theorems --prove`.
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
 (let ((?x14 (- 1.0 x1)))
 (let ((?x15 (* ?x14 ?x14)))
 (>= ?x15 (* (* 3.0 y1) y1)))))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x44 (+ (- (* x1 x1) x1) ?x12)))
 (and (distinct ?x44 0.0) true))))
(push 1)
(assert (let ((a!1 (> (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
      (a!2 (<= (/ 1.0 4.0)
               (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1)))))
  (not (=> a!1 a!2))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (< (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
      (a!2 (<= (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1))
               (/ 1.0 4.0))))
  (not (=> a!1 a!2))))
(check-sat-using qfnra-nlsat)
(pop 1)
