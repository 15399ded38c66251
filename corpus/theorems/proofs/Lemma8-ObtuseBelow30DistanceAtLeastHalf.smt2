; expected: unsat
; Lemma 8 (b)(iii) (Lemma8.ObtuseBelow30DistanceAtLeastHalf), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun oyC () Real)
(declare-fun RC () Real)
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x19 (+ (- (* x1 x1) x1) ?x11)))
 (= (* oyC (* 2.0 y1)) ?x19))))
(assert
 (>= RC 0.0))
(assert
 (let ((?x43 (* RC RC)))
 (= ?x43 (+ (/ 1.0 4.0) (* oyC oyC)))))
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
 (let ((?x11 (* y1 y1)))
 (let ((?x17 (* x1 x1)))
 (let ((?x21 (+ ?x17 ?x11)))
 (let ((?x13 (- 1.0 x1)))
 (let ((?x14 (* ?x13 ?x13)))
 (let ((?x15 (+ ?x14 ?x11)))
 (let (($x26 (<= (* (* 4.0 (+ (- ?x17 x1) ?x11)) (+ (- ?x17 x1) ?x11)) (* ?x15 ?x21))))
 (or (>= (+ (- ?x17 x1) ?x11) 0.0) $x26)))))))))
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x19 (+ (- (* x1 x1) x1) ?x11)))
 (< ?x19 0.0))))
(assert
 (let ((?x13 (- 1.0 x1)))
 (let ((?x14 (* ?x13 ?x13)))
 (>= ?x14 (* (* 3.0 y1) y1)))))
(push 1)
(assert (let ((a!1 (>= (* (+ RC oyC) (+ RC oyC))
               (* (/ 1.0 2.0) (/ 1.0 2.0) (+ (* x1 x1) (* y1 y1))))))
  (not a!1)))
(check-sat-using (using-params qfnra-nlsat :shuffle_vars true :seed 3))
(pop 1)
