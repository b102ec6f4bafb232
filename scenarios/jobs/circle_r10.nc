(full circle of radius 10 mm about 10,10, clockwise, at F600)
G21 G90
G0 X20.000 Y10.000
M3
G2 X20.000 Y10.000 I-10.000 J0 F600
M5
M30
