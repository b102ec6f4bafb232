(seed 000 sec. 3.4.7 worked example, from the origin at 160 steps/mm)
G21 G90
M3
G1 X10.000 Y5.000 F1000
G1 X10.000 Y0.000 F1000
M5
M30
