;cncsim G-code corpus: marlin_laser.gcode
;Imitates a laser job for Marlin printer firmware where the laser hangs on the part-cooling fan output, as some
;Inkscape and Cura laser plug-ins write it. Written by hand for cncsim: not plug-in output.
;Exercises: ;FLAVOR: and ;TIME: header comments, comments after code, G21 G90, G0 and G1 with F, M106 S255 and
;M106 S128 (laser on through the fan output) and M107 (laser off): both are M100-M199 codes, a G4 P1 dwell, M2.
;G4 P: Marlin reads P as milliseconds, cncsim as seconds like LinuxCNC and grbl; P1 is short either way.
;M84 (motors off) would end such a file in Marlin. It is left out: it is outside the M100-M199 range cncsim ignores.
;FLAVOR:Marlin
;TIME:40
;Generated with a laser plug-in (fan output as laser enable)
G21 ; millimetres
G90 ; absolute positions
G0 X30 Y30 F3000
M106 S255 ; laser on, full power
G1 X70 Y30 F1200
G1 X70 Y70 F1200
G1 X30 Y70 F1200
G1 X30 Y30 F1200
M107 ; laser off
G4 P1 ; let the fan output settle
G0 X100 Y30 F3000
M106 S128 ; laser on, half power
G1 X140 Y70 F1500
G1 X100 Y70 F1500
G1 X140 Y30 F1500
M107 ; laser off
G0 X0 Y0 F3000
M2
