; expected: unsat,unsat,unsat,unsat,unsat
; Lemma 4 (narrowed) (Lemma4.HoldsWhenBCShorterThanCA), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun caC () Real)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun cosa0C () Real)
(declare-fun cmC () Real)
(declare-fun cosbC () Real)
(declare-fun cosa1C () Real)
(declare-fun bcC () Real)
(assert
 (>= caC 0.0))
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x13 (- 1.0 x1)))
 (let ((?x14 (* ?x13 ?x13)))
 (let ((?x15 (+ ?x14 ?x11)))
 (let ((?x24 (* caC caC)))
 (= ?x24 ?x15)))))))
(assert
 (let ((?x13 (- 1.0 x1)))
 (= (* cosa0C caC) ?x13)))
(assert
 (>= cmC 0.0))
(assert
 (let ((?x34 (* cmC cmC)))
 (= ?x34 (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1)))))
(assert
 (let ((?x29 (- (/ 1.0 2.0) x1)))
 (= (* cosbC cmC) ?x29)))
(assert
 (= (* cosa1C (* cmC caC)) (+ (* (- (/ 1.0 2.0) x1) (- 1.0 x1)) (* y1 y1))))
(assert
 (>= bcC 0.0))
(assert
 (let ((?x49 (* bcC bcC)))
 (= ?x49 (+ (* x1 x1) (* y1 y1)))))
(assert
 (> y1 0.0))
(assert
 (<= x1 (/ 1.0 2.0)))
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x13 (- 1.0 x1)))
 (let ((?x14 (* ?x13 ?x13)))
 (let ((?x15 (+ ?x14 ?x11)))
 (<= ?x15 1.0))))))
(assert
 (let ((?x13 (- 1.0 x1)))
 (let ((?x14 (* ?x13 ?x13)))
 (> ?x14 (* (* 3.0 y1) y1)))))
(assert
 (< x1 (/ 1.0 2.0)))
(push 1)
(assert (not (< x1 (* cosa0C bcC))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (not (< cosbC cosa0C)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (< (+ (- (* x1 x1) (/ x1 2.0)) (* y1 y1)) (* cosa0C bcC cmC))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (let ((a!1 (and (> (- cosbC) 0.0) (> (* 4.0 (- cosbC) (- cosbC)) 3.0))))
(let ((a!2 (or (and (> cosa0C 0.0) (> (* 4.0 cosa0C cosa0C) 3.0))
               a!1
               (and (> cosa1C 0.0) (> (* 4.0 cosa1C cosa1C) 3.0)))))
  (not a!2))))
(check-sat-using qfnra-nlsat)
(pop 1)
(push 1)
(assert (not (> cosbC 0.0)))
(check-sat-using qfnra-nlsat)
(pop 1)
