#!/usr/bin/env python3
"""A laser raster of N G-code lines (our own): 1 mm passes along X at F3000, each followed by a 0.05 mm step in Y,
200 passes (10 mm) per band before Y returns to 0, so the job stays inside any machine's travel. A pass is 20 ms
at 50 mm/s: 100,000 lines are about 17 minutes of machine time on fpga-uart (passes, steps and dead time).

Usage: make_raster_job.py LINES > job.nc
"""
import sys


def raster(lines):
    out = ["(laser raster, %d motion lines)" % lines, "G21 G90", "M3 S255"]
    row = 0
    while len(out) - 3 < lines:
        out.append("G1 X%.3f F3000" % (1.0 if row % 2 == 0 else 0.0))
        row += 1
        if len(out) - 3 < lines:
            out.append("G1 Y%.3f" % ((row % 200) * 0.05))
    out += ["M5", "M30"]
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    sys.stdout.write(raster(int(sys.argv[1])))
