(relative rapid of 2.9e13 mm: no step counter holds it)
G21 G91
G0 X28888888888885
M30
