(seed 000 sec. 6.3.1: the six moves of six_segment.steps as G-code, at 160 steps/mm every end point is a whole step)
(F of each G1 is the steps file's PathFeed, so the seed 000 CAM makes the same packets; the G0 packets match)
(with host.correct_rapid_feed = false, as the log's rapids carry F1200 uncorrected)
G21 G90
G0 X26.60625 Y99.30625
M3
G1 X26.60625 Y149.30625 F800
M5
G0 X41.0875 Y117.84375
M3
G1 X66.9125 Y141.99375 F1095.2954
M5
G0 X43.11875 Y99.3125
M3
G1 X80.61875 Y99.3125 F800
M5
M30
