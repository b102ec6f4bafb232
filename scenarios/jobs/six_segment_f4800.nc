(the seed 000 sec. 6.3.1 six-segment shape, every move at the seed's target speed: 80 mm/s = F4800)
(rapids too: the scenario sets host.rapid_feed_mm_per_min = 4800)
G21 G90
G0 X26.60625 Y99.30625
M3
G1 X26.60625 Y149.30625 F4800
M5
G0 X41.0875 Y117.84375
M3
G1 X66.9125 Y141.99375 F4800
M5
G0 X43.11875 Y99.3125
M3
G1 X80.61875 Y99.3125 F4800
M5
M30
