;cncsim G-code corpus: pycam_calib.nc
;Imitates the dialect of PyCAM's LinuxCNC exporter. Written by hand for cncsim: not PyCAM output.
;Exercises: ;-comment lines, G40 G49 G80 G54 G17 G21 G90, G64 P0.05 (LinuxCNC blending with a tolerance),
;T1 M6, S M3, G04 P3, F on its own line, straight G1 zigzags with Z plunges and G0 Z lifts, words followed by
;(comments), M5, M2
;PYCAM-META-DATA: Filename: calibration_pattern.stl
;PYCAM-META-DATA: Timestamp: 2025-01-15 10:31:00
;PYCAM-META-DATA: Version: 0.6.0
;PYCAM_TOOLPATH_SETTINGS: START
;[Bounds]
;minx = 20.0
;miny = 20.0
;maxx = 90.0
;maxy = 60.0
;[Tool]
;shape = CylindricalCutter
;tool_radius = 1.5
;[Process]
;path_strategy = ZigZagCutter
;step_down = 0.5
;PYCAM_TOOLPATH_SETTINGS: END
G40 (disable tool radius compensation)
G49 (disable tool length compensation)
G80 (cancel modal motion)
G54 (select coordinate system 1)
G17 (select XY plane)
G21 (metric)
G90 (disable incremental moves)
G64 P0.0500 (continuous mode with path tolerance)
;Estimated machine time: 1 minutes
F1000.00000
S10000.00000
T1 M6
G0 Z5.0000
M3 (start spindle)
G04 P3 (wait for 3 seconds)
G0 X20.0000 Y20.0000 Z5.0000
G1 Z-0.5000
G1 X60.0000 Y20.0000 Z-0.5000
G1 X60.0000 Y60.0000 Z-0.5000
G1 X20.0000 Y60.0000 Z-0.5000
G1 X20.0000 Y20.0000 Z-0.5000
G0 Z5.0000
G0 X25.0000 Y25.0000
G1 Z-0.5000
G1 X55.0000 Y25.0000 Z-0.5000
G1 X55.0000 Y30.0000 Z-0.5000
G1 X25.0000 Y30.0000 Z-0.5000
G1 X25.0000 Y35.0000 Z-0.5000
G1 X55.0000 Y35.0000 Z-0.5000
G1 X55.0000 Y40.0000 Z-0.5000
G1 X25.0000 Y40.0000 Z-0.5000
G1 X25.0000 Y45.0000 Z-0.5000
G1 X55.0000 Y45.0000 Z-0.5000
G1 X55.0000 Y50.0000 Z-0.5000
G1 X25.0000 Y50.0000 Z-0.5000
G1 X25.0000 Y55.0000 Z-0.5000
G1 X55.0000 Y55.0000 Z-0.5000
G0 Z5.0000
G0 X70.0000 Y20.0000
G1 Z-0.5000
G1 X70.0000 Y30.0000 Z-0.5000
G0 Z5.0000
G0 X80.0000 Y20.0000
G1 Z-0.5000
G1 X80.0000 Y40.0000 Z-0.5000
G0 Z5.0000
G0 X90.0000 Y20.0000
G1 Z-0.5000
G1 X90.0000 Y50.0000 Z-0.5000
G0 Z5.0000
M5 (stop spindle)
G0 Z5.0000
M2 (end program)
