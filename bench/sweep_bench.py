#!/usr/bin/env python3
"""What `cncsim sweep` costs beyond its runs: 40 points of the fpga-uart square (seeds 1 .. 40), against the same 40
`cncsim run` commands timed one after the other.

Prints the sum of the single runs' wall times and CPU times (user + system), the sweep's wall time with --jobs 1 and
with --jobs 2, the overhead per point (the --jobs 1 sweep minus the sum, over 40: its own start, the check that loads
each point's scenario, the records, results and plots), and the --jobs 2 sweep against half the sum of the wall times
and against half the sum of the CPU times. A run integrates each axis's mechanics on a thread of its own
(`mechanics.worker_thread`), so it keeps more than one core busy: two cores can run the points at most
2 / (CPU / wall) times as fast as one after the other, and half the CPU sum is the bound two busy cores reach.

Usage: bench/sweep_bench.py [BUILD_DIR] (default: build)
"""
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
POINTS = 40


def timed(cmd):
    start = time.monotonic()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def children_cpu_s():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    cncsim = os.path.abspath(os.path.join(build, "sim", "cncsim"))
    scenario = os.path.join(ROOT, "scenarios", "fpga-uart", "square_20mm.toml")
    with tempfile.TemporaryDirectory(prefix="sweep_bench_") as tmp:
        sweep_file = os.path.join(tmp, "square.toml")
        with open(sweep_file, "w") as f:
            f.write('scenario = "%s"\narchitectures = ["fpga-uart"]\nseeds = %d\nmetrics = ["/metrics/job/job_time_s"]\n'
                    % (scenario, POINTS))
        cpu_before = children_cpu_s()
        singles = sum(timed([cncsim, "run", scenario, "--progress", "off", "--report", os.path.join(tmp, "r.json"),
                             "--set", "scenario.architecture=fpga-uart", "--set", "scenario.seed=%d" % seed])
                      for seed in range(1, POINTS + 1))
        singles_cpu = children_cpu_s() - cpu_before
        walls = {}
        for jobs in (1, 2):
            out = os.path.join(tmp, "out%d" % jobs)
            walls[jobs] = timed([cncsim, "sweep", sweep_file, "--out", out, "--jobs", str(jobs)])
            shutil.rmtree(out)
    print("| %d single runs, wall sum [s] | CPU sum [s] | sweep --jobs 1 [s] | overhead per point [ms] | "
          "sweep --jobs 2 [s] | --jobs 2 / (wall sum / 2) | --jobs 2 / (CPU sum / 2) |" % POINTS)
    print("|---|---|---|---|---|---|---|")
    print("| %.2f | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f |"
          % (singles, singles_cpu, walls[1], 1000 * (walls[1] - singles) / POINTS, walls[2], walls[2] / (singles / 2),
             walls[2] / (singles_cpu / 2)))


if __name__ == "__main__":
    main()
