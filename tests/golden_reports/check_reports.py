#!/usr/bin/env python3
"""Every shipped scenario's report equals its committed golden.

The goldens in tests/data/golden_reports were captured from the metrics that measure feed error, motion and dead
time on programmed moves, reviewed, before the metrics were made to stream, so that the streaming
code must give the same reports. One golden per scenarios/**/*.toml run on its own architecture, and one per compare
run below: {"exit": exit code, "report": the JSON report}. Numbers must agree to a relative 1e-9 (an absolute
1e-12 near 0): the same definitions summed in another order may differ in the last bits, nothing more. No report
field is wall-clock time; the build directory's paths (the firmware it built) read <build>.

Usage: check_reports.py CNCSIM SOURCE_DIR WORKDIR [--update]
  --update writes the goldens instead (review the diff before committing it).
"""
import glob
import json
import math
import os
import subprocess
import sys

REL_TOL = 1e-9
ABS_TOL = 1e-12
COMPARES = {"compare_square_20mm": "scenarios/fpga-uart/square_20mm.toml",
            "compare_circle_r10": "scenarios/fpga-uart/circle_r10.toml"}


def runs(source):
    """{golden name: cncsim arguments (paths relative to SOURCE_DIR)}."""
    out = {}
    for scenario in sorted(glob.glob(os.path.join(source, "scenarios", "**", "*.toml"), recursive=True)):
        rel = os.path.relpath(scenario, source)
        out[rel[len("scenarios/"):-len(".toml")].replace("/", "_")] = ["run", rel]
    for name, scenario in COMPARES.items():
        out[name] = ["compare", scenario]
    return out


def differences(golden, got, where="", out=None):
    out = [] if out is None else out
    if isinstance(golden, dict) and isinstance(got, dict):
        for key in sorted(set(golden) | set(got)):
            if key not in golden or key not in got:
                out.append("%s/%s: %s" % (where, key, "not in the golden" if key not in golden else "missing"))
            else:
                differences(golden[key], got[key], where + "/" + key, out)
    elif isinstance(golden, list) and isinstance(got, list):
        if len(golden) != len(got):
            out.append("%s: %d entries, golden %d" % (where, len(got), len(golden)))
        for i, (a, b) in enumerate(zip(golden, got)):
            differences(a, b, "%s[%d]" % (where, i), out)
    elif isinstance(golden, (int, float)) and isinstance(got, (int, float)) and not isinstance(golden, bool):
        if not math.isclose(golden, got, rel_tol=REL_TOL, abs_tol=ABS_TOL):
            out.append("%s: %r, golden %r" % (where, got, golden))
    elif golden != got:
        out.append("%s: %r, golden %r" % (where, got, golden))
    return out


def main():
    cncsim, source, workdir = sys.argv[1:4]
    cncsim, source = os.path.abspath(cncsim), os.path.abspath(source)
    build = os.path.dirname(os.path.dirname(cncsim))  # BUILD/sim/cncsim
    update = "--update" in sys.argv[4:]
    golden_dir = os.path.join(source, "tests", "data", "golden_reports")
    os.makedirs(workdir, exist_ok=True)
    failures = []
    for name, args in runs(source).items():
        report = os.path.join(workdir, name + ".json")
        if os.path.exists(report):
            os.remove(report)
        run = subprocess.run([cncsim] + args + ["--report", report] +
                             (["--progress", "off"] if args[0] == "run" else []),
                             cwd=source, capture_output=True, text=True)
        got = {"exit": run.returncode, "report": None}
        if os.path.exists(report):
            with open(report) as f:
                # The build's own paths (the firmware it built) differ between checkouts.
                got["report"] = json.loads(f.read().replace(build + "/", "<build>/").replace(source + "/", ""))
        path = os.path.join(golden_dir, name + ".json")
        if update:
            with open(path, "w") as f:
                json.dump(got, f, indent=1, sort_keys=True)
                f.write("\n")
            continue
        if not os.path.exists(path):
            print("%s: no golden" % name)
            failures.append("%s: no golden %s (write it with --update and review it)" % (name, path))
            continue
        with open(path) as f:
            golden = json.load(f)
        diff = differences(golden, got)
        print("%s: %s" % (name, "same" if not diff else "%d differences" % len(diff)))
        failures += ["%s: %s" % (name, d) for d in diff[:20]]
    print("\n".join(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
