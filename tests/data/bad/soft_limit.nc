(one inch in X on an axis with 10 mm of travel)
G20 G90
G1 X1.000 F40
M30
