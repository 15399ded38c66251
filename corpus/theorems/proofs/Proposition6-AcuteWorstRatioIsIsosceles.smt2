; expected: unsat,unsat
; Proposition 6 (b) (Proposition6.AcuteWorstRatioIsIsosceles), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun caC () Real)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun cosa0C () Real)
(declare-fun y2 () Real)
(declare-fun x2 () Real)
(assert
 (>= caC 0.0))
(assert
 (let ((?x13 (* y1 y1)))
 (let ((?x14 (- 1.0 x1)))
 (let ((?x15 (* ?x14 ?x14)))
 (let ((?x16 (+ ?x15 ?x13)))
 (let ((?x48 (* caC caC)))
 (= ?x48 ?x16)))))))
(assert
 (let ((?x14 (- 1.0 x1)))
 (= (* cosa0C caC) ?x14)))
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
 (> (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
(push 1)
(assert (let ((a!1 (>= (/ (* 8.0 (- 1.0 cosa0C)) 4.0)
               (* 1.0 1.0 (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (* 8.0
              (- 1.0 cosa0C)
              (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1)))))
(let ((a!2 (>= a!1 (* 1.0 1.0 (+ (* x1 x1) (* y1 y1))))))
  (not a!2))))
(check-sat-using qfnra-nlsat)
(pop 1)
