; expected: unsat
; Lemma 8 (b)(i) (Lemma8.ObtuseBelow14DistanceAboveBC), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun y1 () Real)
(declare-fun y2 () Real)
(declare-fun x1 () Real)
(declare-fun x2 () Real)
(declare-fun y3 () Real)
(declare-fun x3 () Real)
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
 (let ((?x47 (- (* y1 (- (+ (* x3 x3) (* y3 y3)) x3)) (* y3 (- (+ (* x1 x1) (* y1 y1)) x1)))))
 (>= ?x47 0.0)))
(assert
 (let ((?x51 (- (* y2 (- (+ (* x3 x3) (* y3 y3)) x3)) (* y3 (- (+ (* x2 x2) (* y2 y2)) x2)))))
 (<= ?x51 0.0)))
(assert
 (< (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
(assert
 (let ((?x14 (- 1.0 x1)))
 (let ((?x15 (* ?x14 ?x14)))
 (>= ?x15 (* (/ 9409.0 10000.0) (+ ?x15 (* y1 y1)))))))
(push 1)
(assert (let ((a!1 (> (+ (* (- x3 (/ 1.0 2.0)) (- x3 (/ 1.0 2.0))) (* y3 y3))
              (* 1.0 1.0 (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
