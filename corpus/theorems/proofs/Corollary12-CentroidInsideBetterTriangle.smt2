; expected: sat
; Corollary 12 (Corollary12.CentroidInsideBetterTriangle), written by `lepp theorems --prove`.
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
 (let ((?x35 (- (* y2 (- (+ (* x1 x1) (* y1 y1)) x1)) (* y1 (- (+ (* x2 x2) (* y2 y2)) x2)))))
 (<= ?x35 0.0)))
(assert
 (<= x1 (/ 1.0 2.0)))
(assert
 (let ((?x100 (- (* (- x2) (- (/ (+ y1 y2) 4.0) y2)) (* (- y2) (- (/ (+ (+ 1.0 x1) x2) 4.0) x2)))))
 (let ((?x93 (- (* (- x2 1.0) (/ (+ y1 y2) 4.0)) (* y2 (- (/ (+ (+ 1.0 x1) x2) 4.0) 1.0)))))
 (let ((?x72 (- (* 1.0 (/ (+ y1 y2) 4.0)) (* 0.0 (/ (+ (+ 1.0 x1) x2) 4.0)))))
 (let (($x105 (and (and (< ?x72 0.0) (< ?x93 0.0)) (< ?x100 0.0))))
 (let ((?x84 (- (* (- x1) (- (/ (+ y1 y2) 4.0) y1)) (* (- y1) (- (/ (+ (+ 1.0 x1) x2) 4.0) x1)))))
 (let ((?x77 (- (* (- x1 1.0) (/ (+ y1 y2) 4.0)) (* y1 (- (/ (+ (+ 1.0 x1) x2) 4.0) 1.0)))))
 (let (($x89 (and (and (> ?x72 0.0) (> ?x77 0.0)) (> ?x84 0.0))))
 (let ((?x22 (* y2 y2)))
 (let ((?x27 (* x2 x2)))
 (let ((?x28 (+ ?x27 ?x22)))
 (let ((?x18 (* x1 x1)))
 (let ((?x50 (* ?x18 ?x28)))
 (let ((?x12 (* y1 y1)))
 (let ((?x19 (+ ?x18 ?x12)))
 (let ((?x49 (* ?x27 ?x19)))
 (let ((?x14 (- 1.0 x1)))
 (let ((?x15 (* ?x14 ?x14)))
 (let ((?x43 (* ?x15 ?x28)))
 (let ((?x16 (+ ?x15 ?x12)))
 (let ((?x42 (* ?x27 ?x16)))
 (let ((?x23 (- 1.0 x2)))
 (let ((?x24 (* ?x23 ?x23)))
 (let ((?x25 (+ ?x24 ?x22)))
 (let ((?x47 (* ?x18 ?x25)))
 (let ((?x46 (* ?x24 ?x19)))
 (let (($x60 (and (or (< (* ?x24 ?x16) (* ?x15 ?x25)) (< ?x46 ?x47)) (or (< ?x42 ?x43) (< ?x49 ?x50)))))
 (let (($x53 (and (or (< (* ?x15 ?x25) (* ?x24 ?x16)) (< ?x43 ?x42)) (or (< ?x47 ?x46) (< ?x50 ?x49)))))
 (let (($x111 (and (and (=> $x53 $x89) (=> $x60 $x105)) (=> (and (not $x53) (not $x60)) (or $x89 $x105)))))
 (not $x111))))))))))))))))))))))))))))))
(check-sat-using qfnra-nlsat)
