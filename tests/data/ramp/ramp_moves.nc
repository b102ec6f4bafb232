(the trapezoidal ramp's cases, each move from and to the 5 mm/s start speed at 1000 mm/s^2)
G21 G90
M3
(X dominant, Y with it: up to 80 mm/s, a cruise, down)
G1 X10 Y2 F4800
(short: turns round before its cruise)
G1 X9 Y2.5 F3000
(Y dominant, backwards in X)
G1 X7 Y8 F1200
(slower than the start speed: every step at the packet's rate)
G1 X8 Y8 F240
M5
G0 X0 Y0
M30
