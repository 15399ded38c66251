; expected: sat
; Corollary 12 (Corollary12.CentroidInsideBetterTriangle), written by `lepp theorems --prove`.
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
(push 1)
(assert (let ((a!1 (+ (* (- 1.0 x2) (- 1.0 x2)) (* y2 y2)))
      (a!2 (+ (* (- 1.0 x1) (- 1.0 x1)) (* y1 y1)))
      (a!4 (* (* (- 1.0 x1) (- 1.0 x1)) (+ (* x2 x2) (* y2 y2))))
      (a!6 (* (* (- 1.0 x2) (- 1.0 x2)) (+ (* x1 x1) (* y1 y1))))
      (a!7 (* (* x1 x1) (+ (* x2 x2) (* y2 y2))))
      (a!8 (* (* x2 x2) (+ (* x1 x1) (* y1 y1))))
      (a!10 (- (* 1.0 (/ (+ y1 y2) 4.0)) (* 0.0 (/ (+ 1.0 x1 x2) 4.0))))
      (a!11 (* y1 (- (/ (+ 1.0 x1 x2) 4.0) 1.0)))
      (a!13 (* (- x1) (- (/ (+ y1 y2) 4.0) y1)))
      (a!14 (* (- y1) (- (/ (+ 1.0 x1 x2) 4.0) x1)))
      (a!19 (* y2 (- (/ (+ 1.0 x1 x2) 4.0) 1.0)))
      (a!21 (* (- x2) (- (/ (+ y1 y2) 4.0) y2)))
      (a!22 (* (- y2) (- (/ (+ 1.0 x1 x2) 4.0) x2))))
(let ((a!3 (< (* (* (- 1.0 x1) (- 1.0 x1)) a!1)
              (* (* (- 1.0 x2) (- 1.0 x2)) a!2)))
      (a!9 (or (< (* (* x1 x1) a!1) a!6) (< a!7 a!8)))
      (a!12 (- (* (- x1 1.0) (/ (+ y1 y2) 4.0)) a!11))
      (a!16 (< (* (* (- 1.0 x2) (- 1.0 x2)) a!2)
               (* (* (- 1.0 x1) (- 1.0 x1)) a!1)))
      (a!18 (or (< (* (* x2 x2) a!2) a!4) (< a!8 a!7)))
      (a!20 (- (* (- x2 1.0) (/ (+ y1 y2) 4.0)) a!19)))
(let ((a!5 (or a!3 (< a!4 (* (* x2 x2) a!2))))
      (a!15 (and (> a!10 0.0) (> a!12 0.0) (> (- a!13 a!14) 0.0)))
      (a!17 (or a!16 (< a!6 (* (* x1 x1) a!1))))
      (a!23 (and (< a!10 0.0) (< a!20 0.0) (< (- a!21 a!22) 0.0))))
(let ((a!24 (=> (and (not (and a!5 a!9)) (not (and a!17 a!18))) (or a!15 a!23))))
  (not (and (=> (and a!5 a!9) a!15) (=> (and a!17 a!18) a!23) a!24)))))))
(check-sat-using qfnra-nlsat)
(pop 1)
