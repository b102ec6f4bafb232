#!/usr/bin/env python3
"""Timing invariants over every shipped scenario run on one architecture.

For every scenarios/*/*.toml run with scenario.architecture = ARCH (a steps-file job only on fpga-uart): a run
that ends ok has motion time <= job time, every dead time >= 0 (between moves, inside them, total), the total
dead time = between + inside, lead-in >= 0 and tail >= 0, and (G-code jobs) the
feed error of its constant-feed lines and arcs equals what the STEP edges of its VCD give (feed_from_edges.py;
at least one move compared per architecture). A run that fails (some scenarios exist to show a failure) must say
so in its report (ok false, a failure reason).

Usage: invariants.py CNCSIM SOURCE_DIR ARCH WORKDIR [short|long]: `short` leaves out the scenarios of LONG_JOBS,
`long` runs only them (on the AVR core they take minutes: the atmega test of the default suite runs `short`, the
`long` label the rest); neither runs every scenario.
"""
import glob
import json
import os
import subprocess
import sys

from feed_from_edges import compare_feeds

EPS_S = 1e-12
EPS_MS = 1e-9
# spi-fpga traces its SPI wires bit by bit in a VCD (72 bits a servo period): a VCD of the 276 s slow diagonal takes
# minutes to write. On spi-fpga the feeds are compared on jobs up to this long, rerun with the VCD.
SPI_VCD_MAX_JOB_S = 30.0
# The shipped scenarios whose jobs last more than a minute of simulated time (the 273 s slow diagonal, the 81 s
# sample drawing).
LONG_JOBS = {"scenarios/fpga-uart/overflow_slow_diagonal.toml", "scenarios/compare/sample_drawing.toml"}


def main():
    cncsim, source, arch, workdir = sys.argv[1:5]
    part = sys.argv[5] if len(sys.argv) > 5 else "all"
    os.makedirs(workdir, exist_ok=True)
    failures, refused, checked, feeds_compared = [], [], 0, 0
    for scenario in sorted(glob.glob(os.path.join(source, "scenarios", "*", "*.toml"))):
        name = os.path.relpath(scenario, source)
        if part != "all" and (name in LONG_JOBS) != (part == "long"):
            continue
        with open(scenario) as f:
            if ".steps" in f.read() and arch != "fpga-uart":
                continue  # a steps file is seed 000's format: refused elsewhere (exit 2), checked by its own test
        report = os.path.join(workdir, name.replace("/", "_") + ".json")
        vcd = os.path.join(workdir, name.replace("/", "_") + ".vcd")
        for path in (report, vcd):
            if os.path.exists(path):
                os.remove(path)
        command = [cncsim, "run", scenario, "--set", "scenario.architecture=" + arch, "--report", report,
                   "--progress", "off"]
        run = subprocess.run(command + ([] if arch == "spi-fpga" else ["--vcd", vcd]), capture_output=True, text=True)
        if run.returncode == 2:
            # Refused before simulating (e.g. an atmega scenario's 57600 Bd link against the FPGA's 115200 Bd
            # UART): no run, nothing to check; the refusals have their own tests.
            refused.append(name)
            continue
        with open(report) as f:
            r = json.load(f)
        checked += 1
        if run.returncode != 0:
            if r["ok"] or not r.get("failure"):
                failures.append("%s: exit %d but the report does not say it failed" % (name, run.returncode))
            continue
        job = r["metrics"]["job"]
        if job.get("motion_time_s") is not None and job["motion_time_s"] > job["job_time_s"] + EPS_S:
            failures.append("%s: motion %.6f s > job %.6f s" % (name, job["motion_time_s"], job["job_time_s"]))
        for key in ("lead_in_ms", "tail_ms", "dead_total_ms", "dead_max_ms", "dead_inside_total_ms",
                    "dead_inside_max_ms", "dead_all_total_ms"):
            if job.get(key) is not None and job[key] < 0:
                failures.append("%s: %s = %g < 0" % (name, key, job[key]))
        if job.get("dead_all_total_ms") is not None:
            parts = (job["dead_total_ms"] or 0.0) + job["dead_inside_total_ms"]
            if abs(job["dead_all_total_ms"] - parts) > EPS_MS:
                failures.append("%s: dead time total %g ms != between + inside %g ms"
                                % (name, job["dead_all_total_ms"], parts))
        if r["gcode"] is None:
            continue
        if arch == "spi-fpga":
            if job["job_time_s"] > SPI_VCD_MAX_JOB_S:
                continue
            subprocess.run(command + ["--vcd", vcd], capture_output=True, check=True)
        lines, fails, compared, _ = compare_feeds(scenario, arch, report, vcd, False)
        print("\n".join(lines))
        failures += fails
        feeds_compared += compared
        os.remove(vcd)
    if checked == 0:
        failures.append("no scenario ran on %s" % arch)
    if feeds_compared == 0:
        failures.append("no feed error compared with the edges on %s" % arch)
    print("\n".join(failures))
    print("refused as bad input on %s: %s" % (arch, ", ".join(refused) or "none"))
    print("%d passed, %d failed (%d scenario runs on %s)" % (checked - len(failures), len(failures), checked, arch))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
