#!/usr/bin/env bash
# Writes a 4,379-line milling job in the style of a CAM post (header, tool change, three Z passes of a serpentine
# of 0.5 mm G1 segments over a 20 x 37 mm pocket, retracts, footer) to stdout: the benchmark's "milling-style
# job" for the atmega core, whose host sends every short segment as its own command.
set -euo pipefail
awk 'BEGIN {
    print "(bench milling job: 3 passes, 1453 segments each)"
    print "G21 G90 G17 G94"
    print "G40 G49 G80"
    print "T1 M6"
    print "S10000 M3"
    print "G0 Z5"
    print "F600"
    print "M8"
    print "G0 X20 Y20"
    for (pass = 1; pass <= 3; pass++) {
        printf "G0 X20 Y20\nG1 Z%.1f F100\nF600\n", -0.5 * pass
        x = 20; y = 20; dir = 1; n = 0
        while (n < 1452) {
            for (k = 0; k < 40 && n < 1452; k++) { x += 0.5 * dir; printf "G1 X%.1f\n", x; n++ }
            if (n < 1452) { y += 1; printf "G1 Y%.1f\n", y; n++; dir = -dir }
        }
        print "G0 Z5"
    }
    print "M5"
    print "M30"
}'
