(45 degree line at F127: 2.117 mm/s along the path, 1.497 mm/s and 239.5 steps/s on each axis at 160 steps/mm)
G21 G90
M3 S255
G1 X20.000 Y20.000 F127
M5
M30
