; expected: unsat,unsat,unsat,unsat
; Lemma 11 (narrowed) (Lemma11.CentroidBoundsWithCornerEquality), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun oy () Real)
(declare-fun t () Real)
(declare-fun y2 () Real)
(declare-fun x2 () Real)
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x40 (+ (- (* x1 x1) x1) ?x12)))
 (= (* oy (* 2.0 y1)) ?x40))))
(assert
 (= (* t (+ (/ 1.0 4.0) (* oy oy))) (/ 1.0 2.0)))
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
 (let ((?x12 (* y1 y1)))
 (let ((?x40 (+ (- (* x1 x1) x1) ?x12)))
 (< ?x40 0.0))))
(push 1)
(assert (let ((a!1 (< (+ (/ (- 2.0 t) 4.0) (/ 1.0 4.0)) (/ (+ 1.0 x1 x2) 4.0)))
      (a!2 (< (+ (/ (- t 1.0) 4.0) (/ 1.0 4.0)) (/ (+ 1.0 x1 x2) 4.0))))
  (not (or a!1 a!2))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (< (/ (+ 1.0 x1 x2) 4.0) (+ (/ (- 2.0 t) 4.0) (/ 1.0 2.0))))
      (a!2 (< (/ (+ 1.0 x1 x2) 4.0) (+ (/ (- t 1.0) 4.0) (/ 1.0 2.0)))))
  (not (or a!1 a!2))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (not (< (/ y2 4.0) (/ (+ y1 y2) 4.0))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (<= (/ (+ y1 y2) 4.0) (/ (+ y1 (* 2.0 t oy)) 4.0))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
