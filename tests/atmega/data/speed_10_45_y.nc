(seed 003 eqs. 5.1-5.2 on Y: one Y move at 10.45 mm/s, F in mm/s as CAD2G reads it: host.feed_unit = "mm/s")
G21 G90
G1 Y20.000 F10.45
M30
