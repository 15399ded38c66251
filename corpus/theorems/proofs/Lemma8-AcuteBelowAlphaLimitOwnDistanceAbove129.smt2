; expected: unsat,unsat
; Lemma 8 (a)(i) (narrowed) (Lemma8.AcuteBelowAlphaLimitOwnDistanceAbove129), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun s5 () Real)
(declare-fun y1 () Real)
(declare-fun y2 () Real)
(declare-fun x1 () Real)
(declare-fun x2 () Real)
(assert
 (>= s5 0.0))
(assert
 (= (* s5 s5) 5.0))
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
 (let ((?x13 (* y1 y1)))
 (let ((?x17 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x13)))
 (>= (* (* 16.0 (- 1.0 x1)) (- 1.0 x1)) (* (+ 7.0 (* 3.0 s5)) ?x17)))))
(push 1)
(assert (let ((a!1 (> (/ 1.0 4.0)
              (* (/ 129.0 100.0) (/ 129.0 100.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (> (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1))
              (* (/ 129.0 100.0) (/ 129.0 100.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
