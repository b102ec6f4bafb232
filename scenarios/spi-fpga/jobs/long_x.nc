(one 40 mm move along X at F1200: 20 mm/s = 3200 steps/s at 160 steps/mm, a rate word of 15,625 clocks at 50 MHz;)
(about 2 s of it at constant rate)
G21 G90
G1 X40.000 F1200
M30
