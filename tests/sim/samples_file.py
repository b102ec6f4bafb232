#!/usr/bin/env python3
"""`cncsim run --samples FILE` writes the tool samples as a CSV a user can load.

Runs scenarios/fpga-uart/square_20mm.toml with the ideal mechanics (one microstep per step, so the rows follow from
the step counts) and loads the file with the csv module. Goldens from the job
(scenarios/jobs/square_20mm.nc) on the scenario's 160 steps/mm machine, starting at 0,0: G0 to 10,10 is 1,600 steps
on each axis at one rate (equal counts, equal NUMERATOR and feed: step_gen gives both the same period, so X and Y
step at the same instants and the carriage takes one sample per instant), the four 20 mm sides 3,200 steps each on
one axis, G0 back to 0,0 as the first rapid: 1 (t = 0) + 1,600 + 4 x 3,200 + 1,600 = 16,001 rows.

Usage: samples_file.py CNCSIM SOURCE_DIR WORKDIR
"""
import csv
import os
import subprocess
import sys

STEPS_PER_MM = 160
ROWS = 1 + 1600 + 4 * 3200 + 1600


def main():
    cncsim, source, workdir = sys.argv[1:4]
    os.makedirs(workdir, exist_ok=True)
    path = os.path.join(workdir, "square_samples.csv")
    if os.path.exists(path):
        os.remove(path)
    subprocess.run([cncsim, "run", os.path.join(source, "scenarios/fpga-uart/square_20mm.toml"), "--samples", path,
                    "--set", "mechanics.model=ideal", "--progress", "off"], check=True, stdout=subprocess.DEVNULL)
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [tuple(float(v) for v in row) for row in reader]
    failures = []
    if header != ["t_s", "x_mm", "y_mm"]:
        failures.append("header %r" % header)
    if len(rows) != ROWS:
        failures.append("%d rows, expected %d" % (len(rows), ROWS))
    if rows[0] != (0.0, 0.0, 0.0):
        failures.append("first row %r, expected the start 0,0 at t = 0" % (rows[0],))
    if any(b[0] <= a[0] for a, b in zip(rows, rows[1:])):
        failures.append("times are not strictly increasing")
    # Every position is a whole number of microsteps, inside the square's 0..30 mm and back at 0,0 at the end.
    for t, x, y in rows:
        if any(abs(v * STEPS_PER_MM - round(v * STEPS_PER_MM)) > 1e-6 for v in (x, y)):
            failures.append("t = %.12f s: %r, %r is not on the microstep grid" % (t, x, y))
            break
    if max(r[1] for r in rows) != 30.0 or max(r[2] for r in rows) != 30.0 or rows[-1][1:] != (0.0, 0.0):
        failures.append("extremes %r, %r and end %r: expected 30, 30 and 0,0" %
                        (max(r[1] for r in rows), max(r[2] for r in rows), rows[-1][1:]))
    print("%d rows, last at %.6f s" % (len(rows), rows[-1][0]))
    print("\n".join(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
