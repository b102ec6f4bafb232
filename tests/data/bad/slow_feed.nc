(0.01 mm/min: one step every 37.5 s at 160 steps/mm)
G21 G90
G1 X1 F0.01
M30
