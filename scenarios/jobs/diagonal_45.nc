(45 degree diagonal, 20 mm on each axis at F1000: both axes equal, the feed correction's integer rounding shows)
G21 G90
M3
G1 X20.000 Y20.000 F1000
M5
M30
