(three colinear 10 mm moves at F1200: continuous mode crosses the joins at speed, exact-stop stops at each)
G21 G90
G1 X10.000 F1200
G1 X20.000 F1200
G1 X30.000 F1200
M30
