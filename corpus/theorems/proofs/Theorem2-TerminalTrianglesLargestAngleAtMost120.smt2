; expected: unsat
; Theorem 2 (Theorem2.TerminalTrianglesLargestAngleAtMost120), written by `lepp theorems --prove`.
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
(push 1)
(assert (let ((a!1 (>= (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
      (a!2 (* (- (/ 1.0 2.0))
              (- (/ 1.0 2.0))
              (+ (* (- 1.0 x1) (- 1.0 x1)) (* y1 y1))
              (+ (* x1 x1) (* y1 y1))))
      (a!3 (* (+ (- (* x1 x1) x1) (* y1 y1)) (+ (- (* x1 x1) x1) (* y1 y1)))))
  (not (or a!1 (>= a!2 a!3)))))
(check-sat-using qfnra-nlsat)
(pop 1)
