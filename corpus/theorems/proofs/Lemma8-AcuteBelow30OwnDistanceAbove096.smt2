; expected: unsat,unsat
; Lemma 8 (a)(ii) (narrowed) (Lemma8.AcuteBelow30OwnDistanceAbove096), written by `lepp theorems --prove`.
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
 (let ((?x36 (- (* y2 (- (+ (* x1 x1) (* y1 y1)) x1)) (* y1 (- (+ (* x2 x2) (* y2 y2)) x2)))))
 (<= ?x36 0.0)))
(assert
 (<= x1 (/ 1.0 2.0)))
(assert
 (> (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
(assert
 (let ((?x15 (- 1.0 x1)))
 (let ((?x16 (* ?x15 ?x15)))
 (>= ?x16 (* (* 3.0 y1) y1)))))
(push 1)
(assert (let ((a!1 (> (/ 1.0 4.0)
              (* (/ 24.0 25.0) (/ 24.0 25.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (> (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1))
              (* (/ 24.0 25.0) (/ 24.0 25.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
