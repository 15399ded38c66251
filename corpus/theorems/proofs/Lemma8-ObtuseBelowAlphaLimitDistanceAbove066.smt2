; expected: unsat
; Lemma 8 (b)(ii) (Lemma8.ObtuseBelowAlphaLimitDistanceAbove066), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun s5 () Real)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun oyC () Real)
(declare-fun RC () Real)
(assert
 (>= s5 0.0))
(assert
 (= (* s5 s5) 5.0))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x20 (+ (- (* x1 x1) x1) ?x12)))
 (= (* oyC (* 2.0 y1)) ?x20))))
(assert
 (>= RC 0.0))
(assert
 (let ((?x54 (* RC RC)))
 (= ?x54 (+ (/ 1.0 4.0) (* oyC oyC)))))
(assert
 (> y1 0.0))
(assert
 (<= x1 (/ 1.0 2.0)))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x16 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x12)))
 (<= ?x16 1.0))))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x18 (* x1 x1)))
 (let ((?x22 (+ ?x18 ?x12)))
 (let ((?x16 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x12)))
 (let (($x27 (<= (* (* 4.0 (+ (- ?x18 x1) ?x12)) (+ (- ?x18 x1) ?x12)) (* ?x16 ?x22))))
 (or (>= (+ (- ?x18 x1) ?x12) 0.0) $x27)))))))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x20 (+ (- (* x1 x1) x1) ?x12)))
 (< ?x20 0.0))))
(assert
 (let ((?x12 (* y1 y1)))
 (let ((?x16 (+ (* (- 1.0 x1) (- 1.0 x1)) ?x12)))
 (>= (* (* 16.0 (- 1.0 x1)) (- 1.0 x1)) (* (+ 7.0 (* 3.0 s5)) ?x16)))))
(push 1)
(assert (let ((a!1 (> (* (+ RC oyC) (+ RC oyC))
              (* (/ 33.0 50.0) (/ 33.0 50.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
