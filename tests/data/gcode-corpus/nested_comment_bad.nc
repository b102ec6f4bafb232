(cncsim G-code corpus: nested_comment_bad.nc, deliberately bad, RS274NGC/LinuxCNC dialect, for error tests)
G21 G90 (Exercises: a nested comment on line 3, an unclosed comment on line 5, otherwise G1 moves, F, M2)
G1 X10 Y10 F500 ( outer ( inner ) )
G1 X20 Y10
G1 X20 Y20 ( never closed
G1 X10 Y20
M2
