; A raster in five grey levels: 5 mm lines 0.2 mm apart at F1200, each at its own S of the 1000 of full power
; (fpga.laser_s_max), cut left to right with a rapid back between them.
G21 G90
M3 S0
G0 X0 Y0
G1 X5 F1200 S1000
G0 X0 Y0.2
G1 X5 S750
G0 X0 Y0.4
G1 X5 S500
G0 X0 Y0.6
G1 X5 S250
G0 X0 Y0.8
G1 X5 S100
M5
G0 X0 Y0
