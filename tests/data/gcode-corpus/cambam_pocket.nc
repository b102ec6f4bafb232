( cncsim G-code corpus: cambam_pocket.nc )
( Imitates the dialect of CamBam's default Mach3-style post processor. Written by hand for cncsim: not CamBam output. )
( Exercises: G21 G90 G64 G40 G49 G80 G17, T1 M6, S12000 M3, G0 Z retracts, G1 Z plunges at F100, G1 XY with )
( modal axis words left out, G3 corner arcs with incremental I J, two depth passes Z-0.5 and Z-1.0, M5, M30 )
( Made using CamBam - http://www.cambam.co.uk )
( cambam_pocket 2025-01-15 10:30:00 )
( T1 : 3.0 )
G21 G90 G64 G40 G49 G80 G17
G0 Z5.0
( T1 : 3.0 )
T1 M6
( Pocket1 )
S12000 M3
( Pocket1 depth -0.5 )
G0 X35.0 Y33.0
G0 Z1.0
G1 F100.0 Z-0.5
G1 F1200.0 X85.0
G3 X87.0 Y35.0 I0.0 J2.0
G1 Y65.0
G3 X85.0 Y67.0 I-2.0 J0.0
G1 X35.0
G3 X33.0 Y65.0 I0.0 J-2.0
G1 Y35.0
G3 X35.0 Y33.0 I2.0 J0.0
G1 Y30.0
G1 F1200.0 X85.0
G3 X90.0 Y35.0 I0.0 J5.0
G1 Y65.0
G3 X85.0 Y70.0 I-5.0 J0.0
G1 X35.0
G3 X30.0 Y65.0 I0.0 J-5.0
G1 Y35.0
G3 X35.0 Y30.0 I5.0 J0.0
G0 Z5.0
( Pocket1 depth -1.0 )
G0 X35.0 Y33.0
G0 Z1.0
G1 F100.0 Z-1.0
G1 F1200.0 X85.0
G3 X87.0 Y35.0 I0.0 J2.0
G1 Y65.0
G3 X85.0 Y67.0 I-2.0 J0.0
G1 X35.0
G3 X33.0 Y65.0 I0.0 J-2.0
G1 Y35.0
G3 X35.0 Y33.0 I2.0 J0.0
G1 Y30.0
G1 F1200.0 X85.0
G3 X90.0 Y35.0 I0.0 J5.0
G1 Y65.0
G3 X85.0 Y70.0 I-5.0 J0.0
G1 X35.0
G3 X30.0 Y65.0 I0.0 J-5.0
G1 Y35.0
G3 X35.0 Y30.0 I5.0 J0.0
G0 Z5.0
M5
M30
