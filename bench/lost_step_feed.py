#!/usr/bin/env python3
"""The six-segment shape on seed 000's machine with the dynamic mechanics.

For each architecture: the full steps lost at F4800 (80 mm/s, the seed's target speed) and, when some are
lost, the highest feed at which none are, found by bisection on the model (every move of the job, rapids
included, at that feed; resolution --resolution mm/min). Bisection assumes that a feed without losses has
none below it, which the runs printed along the way show.

usage: bench/lost_step_feed.py build/sim/cncsim [--arch fpga-uart,atmega,spi-fpga] [--resolution 60]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIO = os.path.join(ROOT, "scenarios", "mechanics", "six_segment_f4800.toml")
JOB = os.path.join(ROOT, "scenarios", "jobs", "six_segment_f4800.nc")
TARGET_FEED = 4800


def lost_steps(cncsim, arch, feed, tmp):
    """Full steps lost on X and Y with every move at `feed` mm/min."""
    with open(JOB) as f:
        text = re.sub(r"F4800", "F%g" % feed, f.read())
    job = os.path.join(tmp, "six_segment_f%g.nc" % feed)
    with open(job, "w") as f:
        f.write(text)
    report = os.path.join(tmp, "%s_f%g.json" % (arch, feed))
    cmd = [cncsim, "run", SCENARIO, "--set", "scenario.architecture=" + arch, "--set", "scenario.job=" + job,
           "--set", "machine.rapid_feed_mm_per_min=%g" % feed, "--set", "clock.ideal=true", "--progress", "off",
           "--report", report]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(report) as f:
        mech = json.load(f)[arch]["mechanics"]
    return mech["x"]["lost_full_steps"], mech["y"]["lost_full_steps"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cncsim")
    ap.add_argument("--arch", default="fpga-uart,atmega,spi-fpga")
    ap.add_argument("--resolution", type=float, default=60.0, help="feed resolution of the search, mm/min")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="lost_step_feed_") as tmp:
        for arch in args.arch.split(","):
            x, y = lost_steps(args.cncsim, arch, TARGET_FEED, tmp)
            line = "%s: F%d loses %d full steps on X, %d on Y" % (arch, TARGET_FEED, x, y)
            if x + y == 0:
                print(line + "; highest feed without lost steps: F%d or more" % TARGET_FEED)
                continue
            good, bad = 0.0, float(TARGET_FEED)
            lo = args.resolution
            while bad - good > args.resolution:
                mid = max(lo, round((good + bad) / 2 / args.resolution) * args.resolution)
                if mid >= bad:
                    break
                lx, ly = lost_steps(args.cncsim, arch, mid, tmp)
                print("  %s F%g: lost %d on X, %d on Y" % (arch, mid, lx, ly), file=sys.stderr)
                if lx + ly == 0:
                    good = mid
                else:
                    bad = mid
            print(line + "; highest feed without lost steps: F%g (F%g loses steps)" % (good, bad))


if __name__ == "__main__":
    main()
