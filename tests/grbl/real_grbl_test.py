#!/usr/bin/env python3
"""Real grbl 1.1h on the grbl architecture, when GRBL_SRC names its source tree (git clone
https://github.com/gnea/grbl): builds it with avr-gcc in a copy outside the source tree, runs the 20 mm square, and
checks grbl's own start-up message, 9600 STEP pulses on each axis that the drivers take (10 + 20 + 20 + 10 mm at
160 steps/mm, from the report's edges), every line answered with ok, and the end on Idle at machine 0,0. Without
GRBL_SRC it says so and is skipped (exit 77).

Usage: real_grbl_test.py CNCSIM SOURCE_DIR
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def main():
    cncsim, source = sys.argv[1:3]
    grbl_src = os.environ.get("GRBL_SRC")
    if not grbl_src:
        print("skipped: GRBL_SRC is not set (git clone https://github.com/gnea/grbl; GRBL_SRC=$PWD/grbl ctest ...)")
        return SKIP
    work = tempfile.mkdtemp()
    tree = os.path.join(work, "grbl")
    shutil.copytree(grbl_src, tree, ignore=shutil.ignore_patterns(".git", "*.hex", "*.o", "*.elf"))
    build = subprocess.run(["make", "-C", tree], capture_output=True, text=True)
    if build.returncode != 0:
        print("FAIL: grbl does not build:\n" + build.stdout[-2000:] + build.stderr[-2000:])
        return 1
    hex_image = os.path.join(tree, "grbl.hex")
    report = os.path.join(work, "report.json")
    run = subprocess.run([cncsim, "run", "tests/data/grbl/square_20mm.toml", "--set", "avr.firmware=" + hex_image,
                          "--report", report, "--progress", "off"], cwd=source, capture_output=True, text=True)
    failures = []
    if run.returncode != 0:
        failures.append("exit %d: %s" % (run.returncode, run.stderr.strip()))
    else:
        with open(report) as f:
            r = json.load(f)
        grbl = r["grbl"]
        if not grbl["banner"].startswith("Grbl 1.1"):
            failures.append("start-up message %r" % grbl["banner"])
        for a in r["metrics"]["axes"]:
            if a["rising_edges"] != 9600:
                failures.append("%s: %d STEP pulses, 9600 expected" % (a["axis"], a["rising_edges"]))
        sender = grbl["sender"]
        if sender["lines_answered"] != sender["lines_sent"] or sender["errors"]:
            failures.append("lines %d sent, %d answered, errors %s" % (sender["lines_sent"],
                                                                        sender["lines_answered"], sender["errors"]))
        if not sender["last_status"].startswith("<Idle|MPos:0.000,0.000,"):
            failures.append("last status %r" % sender["last_status"])
        print("grbl: %s; job %.3f s; %s" % (grbl["banner"], r["metrics"]["job"]["job_time_s"], sender["last_status"]))
    shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
