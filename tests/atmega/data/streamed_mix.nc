(streamed against batch metrics: G00 dog-legs, G01 with the laser on, a Y-only G01 with X disabled, an arc's chords)
G21 G90
G0 X5 Y3
M3
G1 X15 Y3 F600
G1 X15 Y8 F900
G2 X20 Y13 I5 J0 F600
M5
G0 X2 Y10
M3
G1 X8 Y4 F1200
M5
G0 X0 Y0
M30
