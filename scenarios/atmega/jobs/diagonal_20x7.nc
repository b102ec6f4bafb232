(a diagonal whose axis speeds quantise differently: v_x 9.44 mm/s -> OCR0A 4, v_y 3.30 mm/s -> OCR2A 13)
G21 G90
G1 X20.000 Y7.000 F600
M30
