(cncsim G-code corpus: inch_circle.nc)
(An inch program in the plain RS274 dialect of LinuxCNC and Mach3 posts. Written by hand for cncsim.)
(Exercises: G20 inch units for X Y I J and F, G90 G17 G94, a full circle as five G2 arcs with incremental I J,)
(one arc end at 45 degrees given to 5 decimals, G1 square at F30, M3 S M5, M30)
(1 inch radius circle about X2 Y2 inch = machine X50.8 Y50.8 mm, square X0.75..3.25 Y0.75..3.25 inch)
G20 G90 G17 G94
G0 X3.0 Y2.0
M3 S1000
G2 X2.0 Y1.0 I-1.0 J0.0 F20.0
G2 X1.0 Y2.0 I0.0 J1.0
G2 X2.0 Y3.0 I1.0 J0.0
G2 X2.70711 Y2.70711 I0.0 J-1.0
G2 X3.0 Y2.0 I-0.70711 J-0.70711
M5
G0 X0.75 Y0.75
M3 S1000
G1 X3.25 F30.0
G1 Y3.25
G1 X0.75
G1 Y0.75
M5
G0 X0.0 Y0.0
M30
