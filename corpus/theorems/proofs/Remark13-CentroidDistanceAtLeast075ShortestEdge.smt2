; expected: sat
; Remark 13 (Remark13.CentroidDistanceAtLeast075ShortestEdge), written by `lepp theorems --prove`.
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
 (let (($x52 (< (* (* x1 x1) (+ (* x2 x2) (* y2 y2))) (* (* x2 x2) (+ (* x1 x1) (* y1 y1))))))
 (let ((?x13 (* y1 y1)))
 (let ((?x19 (* x1 x1)))
 (let ((?x20 (+ ?x19 ?x13)))
 (let ((?x24 (- 1.0 x2)))
 (let ((?x25 (* ?x24 ?x24)))
 (let ((?x23 (* y2 y2)))
 (let ((?x28 (* x2 x2)))
 (let ((?x29 (+ ?x28 ?x23)))
 (let ((?x15 (- 1.0 x1)))
 (let ((?x16 (* ?x15 ?x15)))
 (let (($x46 (or (< (* ?x16 (+ ?x25 ?x23)) (* ?x25 (+ ?x16 ?x13))) (< (* ?x16 ?x29) (* ?x28 (+ ?x16 ?x13))))))
 (not (and $x46 (or (< (* ?x19 (+ ?x25 ?x23)) (* ?x25 ?x20)) $x52))))))))))))))))
(assert
 (let ((?x15 (- 1.0 x1)))
 (let ((?x16 (* ?x15 ?x15)))
 (>= ?x16 (* (* 3.0 y1) y1)))))
(push 1)
(assert (let ((a!1 (* (- (/ (+ 1.0 x1 x2) 4.0) 0.0) (- (/ (+ 1.0 x1 x2) 4.0) 0.0)))
      (a!2 (* (- (/ (+ y1 y2) 4.0) 0.0) (- (/ (+ y1 y2) 4.0) 0.0)))
      (a!3 (* (/ 3.0 4.0) (/ 3.0 4.0) (+ (* x1 x1) (* y1 y1))))
      (a!4 (* (- (/ (+ 1.0 x1 x2) 4.0) 1.0) (- (/ (+ 1.0 x1 x2) 4.0) 1.0)))
      (a!5 (* (- (/ (+ 1.0 x1 x2) 4.0) x1) (- (/ (+ 1.0 x1 x2) 4.0) x1)))
      (a!6 (* (- (/ (+ y1 y2) 4.0) y1) (- (/ (+ y1 y2) 4.0) y1)))
      (a!7 (* (- (/ (+ 1.0 x1 x2) 4.0) x2) (- (/ (+ 1.0 x1 x2) 4.0) x2)))
      (a!8 (* (- (/ (+ y1 y2) 4.0) y2) (- (/ (+ y1 y2) 4.0) y2))))
  (not (and (>= (+ a!1 a!2) a!3)
            (>= (+ a!4 a!2) a!3)
            (>= (+ a!5 a!6) a!3)
            (>= (+ a!7 a!8) a!3)))))
(check-sat-using qfnra-nlsat)
(pop 1)
