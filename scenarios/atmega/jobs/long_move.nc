(420 mm in X: 67200 steps at 160 steps/mm, above the 16-bit counter of seed 003 sec. 5.5, 409.6 mm)
G21 G90
G0 X420.000
M30
