; expected: unsat,unsat,unsat,unsat
; Remark 13 (2) (narrowed) (Remark13.NonObtuseCaseDistanceAbove061), written by `lepp theorems --prove`.
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
 (and (>= (* (- y2) (- 1.0 x1)) (* y1 (- 1.0 x2))) (>= (* (- y2) (- 1.0 x1)) (* y1 x2))))
(assert
 (let ((?x15 (- 1.0 x1)))
 (let ((?x16 (* ?x15 ?x15)))
 (>= ?x16 (* (* 3.0 y1) y1)))))
(assert
 (not (< (+ (- (* x1 x1) x1) (* y1 y1)) 0.0)))
(push 1)
(assert (let ((a!1 (* (- (/ (+ 1.0 x1 x2) 4.0) 0.0) (- (/ (+ 1.0 x1 x2) 4.0) 0.0)))
      (a!2 (* (- (/ (+ y1 y2) 4.0) 0.0) (- (/ (+ y1 y2) 4.0) 0.0))))
(let ((a!3 (>= (+ a!1 a!2)
               (* (/ 61.0 100.0) (/ 61.0 100.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!3))))
(check-sat-using (using-params qfnra-nlsat :shuffle_vars true :seed 4))
(pop 1)
(push 1)
(assert (let ((a!1 (* (- (/ (+ 1.0 x1 x2) 4.0) 1.0) (- (/ (+ 1.0 x1 x2) 4.0) 1.0)))
      (a!2 (* (- (/ (+ y1 y2) 4.0) 0.0) (- (/ (+ y1 y2) 4.0) 0.0))))
(let ((a!3 (>= (+ a!1 a!2)
               (* (/ 61.0 100.0) (/ 61.0 100.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!3))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (* (- (/ (+ 1.0 x1 x2) 4.0) x1) (- (/ (+ 1.0 x1 x2) 4.0) x1)))
      (a!2 (* (- (/ (+ y1 y2) 4.0) y1) (- (/ (+ y1 y2) 4.0) y1))))
(let ((a!3 (>= (+ a!1 a!2)
               (* (/ 61.0 100.0) (/ 61.0 100.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!3))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (* (- (/ (+ 1.0 x1 x2) 4.0) x2) (- (/ (+ 1.0 x1 x2) 4.0) x2)))
      (a!2 (* (- (/ (+ y1 y2) 4.0) y2) (- (/ (+ y1 y2) 4.0) y2))))
(let ((a!3 (>= (+ a!1 a!2)
               (* (/ 61.0 100.0) (/ 61.0 100.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!3))))
(check-sat-using qfnra-nlsat)
(pop 1)
