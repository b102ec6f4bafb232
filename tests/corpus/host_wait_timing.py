#!/usr/bin/env python3
"""The time a G-code word that is not an XY move adds to a job, on one architecture.

The same two-move job runs twice: without and with the word between the moves. The job time must grow by the
word's own time, derived here from the G-code alone, plus at most the architecture's overhead:
- G4 P2.5: 2.5 s;
- G1 Z5 F300 (no Z STEP pins on any of these architectures): 5 mm / 300 mm/min = 1 s;
- M0: host.operator_pause_s (set to 7 s here).
Overhead bounds: fpga-uart and atmega sleep on the host between a finished move and the next write, so the
wait adds nothing else (bound: one 1 ms USB frame, as writes leave at frame boundaries, and never less); spi-fpga
runs in exact stop so that only the rest differs, and its STEP edges follow the trajectory at servo-period
boundaries with a random wake-up latency (bound: two 1 ms servo periods either way).

Usage: host_wait_timing.py CNCSIM ARCH WORKDIR
"""
import json
import os
import subprocess
import sys

BASE = "G21 G90\nM3 S1000\nG1 X10 F600\n%sG1 Y10\nM5\nM2\n"
# F is modal: the Z move's F300 is put back to F600 so that the second XY move is the same in both jobs.
CASES = [("dwell", "G4 P2.5\n", 2.5), ("z_move", "G1 Z5 F300\nF600\n", 5.0 / 300.0 * 60.0), ("pause", "M0\n", 7.0)]
OVERHEAD_S = {"fpga-uart": 0.001, "atmega": 0.001, "spi-fpga": 0.002}
EARLY_S = {"fpga-uart": 0.0, "atmega": 0.0, "spi-fpga": 0.002}


def job_time(cncsim, arch, workdir, name, gcode):
    job = os.path.join(workdir, name + ".nc")
    with open(job, "w") as f:
        f.write(gcode)
    scenario = os.path.join(workdir, name + ".toml")
    with open(scenario, "w") as f:
        f.write('[scenario]\njob = "%s"\narchitecture = "%s"\n[host]\noperator_pause_s = 7.0\n'
                '[planner]\nmode = "exact-stop"\n' % (job, arch))
    report = os.path.join(workdir, name + ".json")
    # The firmware times its waits with its own clock: exact here, so a wait adds exactly its length.
    run = subprocess.run([cncsim, "run", scenario, "--report", report, "--set", "clock.ideal=true"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("%s: exit %d\n%s" % (name, run.returncode, run.stderr))
    with open(report) as f:
        return json.load(f)["metrics"]["job"]["job_time_s"]


def main():
    cncsim, arch, workdir = sys.argv[1:4]
    os.makedirs(workdir, exist_ok=True)
    base = job_time(cncsim, arch, workdir, "base", BASE % "")
    failed = 0
    for name, word, added_s in CASES:
        grown = job_time(cncsim, arch, workdir, name, BASE % word) - base
        ok = added_s - EARLY_S[arch] - 1e-9 <= grown <= added_s + OVERHEAD_S[arch]
        print("%s %s: job grows by %.6f s, expected %.3f s + at most %.3f s" %
              ("ok" if ok else "FAIL", name, grown, added_s, OVERHEAD_S[arch]))
        failed += 0 if ok else 1
    print("%d passed, %d failed" % (len(CASES) - failed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
