#!/usr/bin/env python3
"""Peak memory does not grow with the job (bounded-memory issue, check 1).

Generates a 10,000-line and a 100,000-line laser raster (bench/make_raster_job.py), runs each on the given
architecture (VCD off) and requires the peak RSS of the child process (wait4's ru_maxrss) on the larger job to be
within 1.5x of the smaller's: memory may not grow with the steps or the servo periods, and what grows with the
moves must be small against the program's own footprint.

Usage: peak_rss.py CNCSIM SOURCE_DIR WORKDIR ARCHITECTURE
"""
import os
import subprocess
import sys

MAX_RATIO = 1.5
SMALL, LARGE = 10_000, 100_000


def peak_rss_mib(cncsim, scenario, report):
    child = subprocess.Popen([cncsim, "run", scenario, "--report", report, "--progress", "off"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("cncsim failed on %s" % scenario)
    return usage.ru_maxrss / 1024.0


def main():
    cncsim, source, workdir, arch = sys.argv[1:5]
    sys.path.insert(0, os.path.join(source, "bench"))
    from make_raster_job import raster
    os.makedirs(workdir, exist_ok=True)
    rss = {}
    for lines in (SMALL, LARGE):
        job = os.path.join(workdir, "raster_%d.nc" % lines)
        with open(job, "w") as f:
            f.write(raster(lines))
        scenario = os.path.join(workdir, "raster_%d.toml" % lines)
        with open(scenario, "w") as f:
            f.write('[scenario]\njob = "%s"\narchitecture = "%s"\n' % (job, arch))
        rss[lines] = peak_rss_mib(cncsim, scenario, os.path.join(workdir, "report.json"))
    ratio = rss[LARGE] / rss[SMALL]
    print("%s: peak RSS %.1f MiB at %d lines, %.1f MiB at %d lines: %.2fx (at most %.1fx)" %
          (arch, rss[SMALL], SMALL, rss[LARGE], LARGE, ratio, MAX_RATIO))
    return 1 if ratio > MAX_RATIO else 0


if __name__ == "__main__":
    sys.exit(main())
