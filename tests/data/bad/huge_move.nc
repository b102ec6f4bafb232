(14 000 km at 160 steps/mm: 2.24e9 steps, outside int32)
G21 G90
G1 X14000000 F1000
M30
