; expected: sat
; Lemma 4 (Lemma4.BisectionImprovesTBLeavesObtuseTA), written by `lepp theorems --prove`.
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
 (let ((?x23 (* caC caC)))
 (= ?x23 ?x15)))))))
(assert
 (let ((?x13 (- 1.0 x1)))
 (= (* cosa0C caC) ?x13)))
(assert
 (>= cmC 0.0))
(assert
 (let ((?x33 (* cmC cmC)))
 (= ?x33 (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1)))))
(assert
 (let ((?x28 (- (/ 1.0 2.0) x1)))
 (= (* cosbC cmC) ?x28)))
(assert
 (= (* cosa1C (* cmC caC)) (+ (* (- (/ 1.0 2.0) x1) (- 1.0 x1)) (* y1 y1))))
(assert
 (>= bcC 0.0))
(assert
 (let ((?x48 (* bcC bcC)))
 (= ?x48 (+ (* x1 x1) (* y1 y1)))))
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
(push 1)
(assert (let ((a!1 (< (+ (- (* x1 x1) (/ x1 2.0)) (* y1 y1)) (* (* cosa0C bcC) cmC)))
      (a!2 (and (> (- cosbC) 0.0) (> (* 4.0 (- cosbC) (- cosbC)) 3.0))))
(let ((a!3 (or (and (> cosa0C 0.0) (> (* 4.0 cosa0C cosa0C) 3.0))
               a!2
               (and (> cosa1C 0.0) (> (* 4.0 cosa1C cosa1C) 3.0)))))
  (not (and (< x1 (* cosa0C bcC)) (< cosbC cosa0C) a!1 a!3 (> cosbC 0.0))))))
(check-sat-using qfnra-nlsat)
(pop 1)
