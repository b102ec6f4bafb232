; 460 mm at F100 with a small Y component: (NUMERATOR/feed) x 73 600 steps = 1.38e10 clocks
; does not fit the appendix step_gen's 32-bit product (seed 000 sec. 5.2.4); the move takes 276 s
G21 G90
M3
G1 X460.000 Y10.000 F100
M5
M30
