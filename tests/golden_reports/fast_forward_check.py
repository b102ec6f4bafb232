#!/usr/bin/env python3
"""Fast-forwarding changes nothing: every shipped scenario of the given architectures (the ones whose goldens are in
tests/data/golden_reports), and the grbl square with the given firmwares, give byte-identical reports with the AVR's
polling-loop fast-forward on (the default) and off (avr.fast_forward / lathe.fast_forward = false).

Usage: fast_forward_check.py CNCSIM SOURCE_DIR WORKDIR WHAT[,WHAT...] [GRBL_FIRMWARE...]
  WHAT: an architecture (atmega, lathe-sync: all its shipped scenarios) or one scenario (scenarios/....toml); a
  GRBL_FIRMWARE (ELF or HEX) runs tests/data/grbl/square_20mm.toml. When GRBL_SRC is set and holds a built grbl.hex,
  real grbl 1.1h runs too.
"""
import glob
import os
import re
import subprocess
import sys

OFF_KEY = {"atmega": "avr.fast_forward", "grbl": "avr.fast_forward", "lathe-sync": "lathe.fast_forward"}


def architecture(scenario):
    with open(scenario) as f:
        m = re.search(r'^architecture\s*=\s*"([^"]+)"', f.read(), re.M)
    return m.group(1) if m else None


def report_bytes(cncsim, source, workdir, name, args):
    report = os.path.join(workdir, name + ".json")
    if os.path.exists(report):
        os.remove(report)
    run = subprocess.run([cncsim, "run"] + args + ["--report", report, "--progress", "off"], cwd=source,
                         capture_output=True, text=True)
    if not os.path.exists(report):  # a refused run: its message instead
        return run.returncode, run.stderr.encode()
    with open(report, "rb") as f:
        return run.returncode, f.read()


def main():
    cncsim, source, workdir, archs = sys.argv[1:5]
    cncsim, source = os.path.abspath(cncsim), os.path.abspath(source)
    firmwares = sys.argv[5:]
    grbl_src = os.environ.get("GRBL_SRC")
    if grbl_src and os.path.exists(os.path.join(grbl_src, "grbl.hex")):
        firmwares.append(os.path.join(grbl_src, "grbl.hex"))
    os.makedirs(workdir, exist_ok=True)
    runs = []
    for scenario in sorted(glob.glob(os.path.join(source, "scenarios", "**", "*.toml"), recursive=True)):
        arch = architecture(scenario)
        if arch in archs.split(",") or os.path.relpath(scenario, source) in archs.split(","):
            runs.append((os.path.relpath(scenario, source), arch, [os.path.relpath(scenario, source)]))
    for fw in firmwares:
        runs.append(("grbl square with " + os.path.basename(fw), "grbl",
                     ["tests/data/grbl/square_20mm.toml", "--set", "avr.firmware=" + os.path.abspath(fw)]))
    failures = []
    for i, (name, arch, args) in enumerate(runs):
        on = report_bytes(cncsim, source, workdir, "%d_on" % i, args)
        off = report_bytes(cncsim, source, workdir, "%d_off" % i, args + ["--set", OFF_KEY[arch] + "=false"])
        same = on == off and on[1] != b""
        print("%s: %s (exit %d, %d bytes)" % (name, "identical" if same else "DIFFERENT", on[0], len(on[1])))
        if not same:
            failures.append(name)
    for f in failures:
        print("FAIL: %s: the report with fast-forward on differs from the one with it off (or is empty)" % f)
    return 1 if failures or not runs else 0


if __name__ == "__main__":
    sys.exit(main())
