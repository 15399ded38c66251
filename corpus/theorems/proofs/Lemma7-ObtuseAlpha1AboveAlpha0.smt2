; expected: unsat
; Lemma 7 (II) (Lemma7.ObtuseAlpha1AboveAlpha0), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun caC () Real)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun cosa0C () Real)
(declare-fun cmC () Real)
(declare-fun cosa1C () Real)
(declare-fun y2 () Real)
(declare-fun x2 () Real)
(assert
 (>= caC 0.0))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x16 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x12)))
 (let ((?x44 (* caC caC)))
 (= ?x44 ?x16)))))
(assert
 (let ((?x14 (- 1.0 x1)))
 (= (* cosa0C caC) ?x14)))
(assert
 (>= cmC 0.0))
(assert
 (let ((?x54 (* cmC cmC)))
 (= ?x54 (+ (* (- (/ 1.0 2.0) x1) (- (/ 1.0 2.0) x1)) (* y1 y1)))))
(assert
 (= (* cosa1C (* cmC caC)) (+ (* (- (/ 1.0 2.0) x1) (- 1.0 x1)) (* y1 y1))))
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
 (< (+ (- (* x1 x1) x1) (* y1 y1)) 0.0))
(push 1)
(assert (not (< cosa1C cosa0C)))
(check-sat-using qfnra-nlsat)
(pop 1)
