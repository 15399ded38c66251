; expected: unsat
; Lemma8.MeshVertexOutsideObtuseCircumcircle (Lemma8.MeshVertexOutsideObtuseCircumcircle), written by `lepp theorems --prove`.
; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.
(set-logic QF_NRA)
; 
(set-info :status unknown)
(declare-fun y1 () Real)
(declare-fun x1 () Real)
(declare-fun oyC () Real)
(declare-fun RC () Real)
(declare-fun y3 () Real)
(declare-fun x3 () Real)
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x14 (+ (- (* x1 x1) x1) ?x11)))
 (= (* oyC (* 2.0 y1)) ?x14))))
(assert
 (>= RC 0.0))
(assert
 (let ((?x36 (* RC RC)))
 (= ?x36 (+ (/ 1.0 4.0) (* oyC oyC)))))
(assert
 (> y1 0.0))
(assert
 (let ((?x11 (* y1 y1)))
 (let ((?x14 (+ (- (* x1 x1) x1) ?x11)))
 (< ?x14 0.0))))
(assert
 (let ((?x24 (- (* y1 (- (+ (* x3 x3) (* y3 y3)) x3)) (* y3 (- (+ (* x1 x1) (* y1 y1)) x1)))))
 (>= ?x24 0.0)))
(push 1)
(assert (let ((a!1 (>= (+ (* (- x3 (/ 1.0 2.0)) (- x3 (/ 1.0 2.0))) (* y3 y3))
               (* (+ RC oyC) (+ RC oyC)))))
  (not a!1)))
(check-sat-using qfnra-nlsat)
(pop 1)
