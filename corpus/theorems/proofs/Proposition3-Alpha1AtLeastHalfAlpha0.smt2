; expected: unsat,unsat
; Proposition 3 (a) (Proposition3.Alpha1AtLeastHalfAlpha0), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun caC () Real)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun cosa0C () Real)
(declare-fun ch () Real)
(declare-fun cmC () Real)
(declare-fun cosa1C () Real)
(declare-fun cosbC () Real)
(assert
 (>= caC 0.0))
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x15 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x11)))
 (let ((?x19 (* caC caC)))
 (= ?x19 ?x15)))))
(assert
 (let ((?x13 (- 1.0 x1)))
 (= (* cosa0C caC) ?x13)))
(assert
 (>= ch 0.0))
(assert
 (let ((?x29 (* ch ch)))
 (= ?x29 (/ (+ 1.0 cosa0C) 2.0))))
(assert
 (>= cmC 0.0))
(assert
 (let ((?x36 (* cmC cmC)))
 (= ?x36 (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1)))))
(assert
 (= (* cosa1C (* cmC caC)) (+ (* (- (/ 1.0 2.0) x1) (- 1.0 x1)) (* y1 y1))))
(assert
 (let ((?x31 (- (/ 1.0 2.0) x1)))
 (= (* cosbC cmC) ?x31)))
(assert
 (> y1 0.0))
(assert
 (<= x1 (/ 1.0 2.0)))
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x15 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x11)))
 (<= ?x15 1.0))))
(push 1)
(assert (not (<= cosa1C ch)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (not (<= cosbC (- (* 4.0 ch ch ch) (* 3.0 ch)))))
(check-sat-using qfnra-nlsat)
(pop 1)
