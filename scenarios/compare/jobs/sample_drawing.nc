(seed 000 sec. 3.3 worked example: the 19 entities of T3.1 in the order its Path Optimize routes them)
(route 1 from 250,100 around the closed contour and back, route 2 the circle about 250,200; r = entity reversed)
(arcs are AutoCAD arcs, counter-clockwise start to end: a reversed arc runs clockwise, G2)
G21 G90 G17 G94
G0 X250 Y100
M3 S255
G1 X200 Y100 F1200 (E3r)
G2 X175 Y125 I0 J25 (E9r, centre 200,125)
G1 X175 Y175 (E2r)
G3 X125 Y175 I-25 J0 (E8, centre 150,175)
G1 X125 Y125 (E1r)
G1 X75 Y100 (E7r)
G1 X75 Y50 (E0r)
G1 X25 Y50 (E17r)
G1 X25 Y225 (E15)
G1 X200 Y225 (E16)
G2 X250 Y250 I50 J-37.5 (E14r, centre 250,187.5)
G1 X300 Y250 (E6r)
G3 X350 Y225 I50 J37.5 (E13, centre 350,287.5)
G1 X350 Y150 (E5r)
G1 X325 Y175 (E12)
G1 X275 Y125 (E4r)
G1 X250 Y125 (E11r)
G1 X250 Y100 (E10r)
M5
G0 X275 Y200
M3 S255
G2 X275 Y200 I-25 J0 (E18r, full circle about 250,200)
M5
G0 X0 Y0
M30
