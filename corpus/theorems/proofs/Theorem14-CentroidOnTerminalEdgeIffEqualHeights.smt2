; expected: unsat,unsat
; Theorem 14 (narrowed) (Theorem14.CentroidOnTerminalEdgeIffEqualHeights), written by `lepp theorems --prove`.
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
(push 1)
(assert (not (= (= (+ y1 y2) 0.0) (= y1 (- y2)))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (and (> (/ (+ 1.0 x1 x2) 4.0) 0.0) (< (/ (+ 1.0 x1 x2) 4.0) 1.0))))
  (not (=> (= (+ y1 y2) 0.0) a!1))))
(check-sat-using qfnra-nlsat)
(pop 1)
