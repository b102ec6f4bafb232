(short cuts that the packet queue runs back to back, the host sending ahead of them)
G21 G90
M3
G1 X1 F3000
G1 X1 Y0.5
G1 X0.5 Y1 F1800
G1 X2 Y1.2 F4800
G1 X2 Y0 F600
M5
G0 X0 Y0
M30
