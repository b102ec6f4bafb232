; Three 1 mm cuts at F1200 for the laser's PWM: part power, above full power (held to it), and none.
G21 G90
M3
G1 X1 F1200 S600
G0 X0 Y0.2
G1 X1 S1500
G0 X0 Y0.4
G1 X1 S0
M5
