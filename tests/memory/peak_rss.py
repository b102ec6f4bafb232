#!/usr/bin/env python3
"""Peak memory does not grow with the job.

Generates a 10,000-line and a 100,000-line laser raster (bench/make_raster_job.py), runs each on the given
architecture (VCD off) and requires cncsim's own peak RSS (wait4's ru_maxrss, taken by bench/child_peak_rss so
that this script's memory does not count) on the larger job to be within 1.5x of the smaller's: memory may not grow with the steps or the servo periods, and what grows with the
moves must be small against the program's own footprint.

Usage: peak_rss.py CNCSIM CHILD_PEAK_RSS SOURCE_DIR WORKDIR ARCHITECTURE
"""
import os
import sys

MAX_RATIO = 1.5
SMALL, LARGE = 10_000, 100_000


def main():
    cncsim, launcher, source, workdir, arch = sys.argv[1:6]
    sys.path.insert(0, os.path.join(source, "bench"))
    from child_rss import run_measured
    from make_raster_job import raster
    workdir = os.path.abspath(workdir)  # the scenario names its job by this path
    os.makedirs(workdir, exist_ok=True)
    rss = {}
    for lines in (SMALL, LARGE):
        job = os.path.join(workdir, "raster_%d.nc" % lines)
        with open(job, "w") as f:
            f.write(raster(lines))
        scenario = os.path.join(workdir, "raster_%d.toml" % lines)
        with open(scenario, "w") as f:
            f.write('[scenario]\njob = "%s"\narchitecture = "%s"\n' % (job, arch))
        code, _, rss[lines], _ = run_measured(
            launcher, [cncsim, "run", scenario, "--report", os.path.join(workdir, "report.json"), "--progress", "off"])
        if code != 0:
            sys.exit("cncsim failed on %s" % scenario)
    ratio = rss[LARGE] / rss[SMALL]
    print("%s: peak RSS %.1f MiB at %d lines, %.1f MiB at %d lines: %.2fx (at most %.1fx)" %
          (arch, rss[SMALL], SMALL, rss[LARGE], LARGE, ratio, MAX_RATIO))
    return 1 if ratio > MAX_RATIO else 0


if __name__ == "__main__":
    sys.exit(main())
