(cncsim G-code corpus: dwell_toolchange.nc)
(A two-tool milling job in the LinuxCNC dialect, with pauses, dwells and coolant. Written by hand for cncsim.)
(Exercises: G4 P0.5 and G4 P2.5 dwells, P in seconds as in LinuxCNC and grbl, and G4 S1, the Marlin form with S in)
(seconds, T1 M6 and T2 M6 tool changes, G43 H1 and G43 H2 tool length offsets and G49, M3 S10000 and M5, M7 mist,)
(M8 flood and M9 coolant off, M1 optional stop, M0 program pause and M60 pallet-change pause, G0 and G1 moves, M30)
(Machine time excludes the operator pauses M0, M1 and M60.)
G21 G90 G17 G94
G0 Z5
T1 M6 (tool 1: 3 mm flat end mill)
G43 H1 (tool length offset of tool 1)
M3 S10000
G4 P0.5 (spindle spin-up, 0.5 s)
M8 (flood coolant on)
G0 X20 Y20
G1 Z-0.5 F200
G1 X60 Y20 F800
G1 X60 Y40
G1 X20 Y40
G1 X20 Y20
G0 Z5
M9 (coolant off)
M5
G49 (cancel the tool length offset)
G0 X10 Y10 (tool change position)
M1 (optional stop: inspect the first pocket)
T2 M6 (tool 2: 1 mm engraving cutter)
G43 H2
M3 S10000
G4 P2.5 (longer spin-up, 2.5 s)
M7 (mist coolant on)
G0 X80 Y20
G1 Z-0.3 F200
G1 X110 Y20 F600
G1 X110 Y50
G4 S1 (Marlin form: S in seconds, LinuxCNC and grbl take only P)
G1 X80 Y50
G1 X80 Y20
G0 Z5
M0 (program pause: turn the part over, then cycle start)
G0 X90 Y30
G1 Z-0.3 F200
G1 X100 Y40 F600
G0 Z5
M9
M5
G49
M60 (pallet change pause)
G0 X0 Y0
M30
