(10 mm at 0.00001 mm/min: 1.9 years)
G21 G90
G1 X10 F0.00001
M30
