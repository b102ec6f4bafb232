(one 100 mm move at F500: 12 s, longer than send_steps.py's 10 s ACK timeout; seed 000 App. A.2)
G21 G90
M3
G1 X100.000 F500
M5
M30
