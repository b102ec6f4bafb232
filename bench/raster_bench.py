#!/usr/bin/env python3
"""Wall time, simulated time per wall second and peak memory of cncsim against job length: a laser raster
(bench/make_raster_job.py) of 10^3, 10^4 and 10^5 lines on fpga-uart and spi-fpga (atmega when named: it runs
about 7x real time, so `build 1000,10000 atmega`), VCD off.
Targets: 100x real time on fpga-uart, 20x on spi-fpga, peak RSS < 200 MiB, for the 10^5-line raster.
Peak RSS is cncsim's own (child_peak_rss, built in BUILD_DIR/bench), not the script's. Each run with each carriage
model named (mechanics.model: the dynamic default, and the ideal one the targets were first met with).

Usage: bench/raster_bench.py [BUILD_DIR] [LINES,...] [ARCHITECTURES,...] [MODELS,...]
       (default: build 1000,10000,100000 fpga-uart,spi-fpga dynamic,ideal)
Prints one Markdown row per run.
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from child_rss import run_measured  # noqa: E402
from make_raster_job import raster  # noqa: E402


def run(build, scenario, model, report):
    cncsim = os.path.abspath(os.path.join(build, "sim", "cncsim"))
    launcher = os.path.abspath(os.path.join(build, "bench", "child_peak_rss"))
    code, wall_s, rss_mib, err = run_measured(
        launcher, [cncsim, "run", scenario, "--report", report, "--progress", "off", "--set",
                   "mechanics.model=" + model], stderr=subprocess.PIPE)
    if code != 0:
        sys.exit("cncsim failed on %s: %s" % (scenario, err.decode()))
    return wall_s, rss_mib


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    sizes = [int(n) for n in (sys.argv[2] if len(sys.argv) > 2 else "1000,10000,100000").split(",")]
    archs = (sys.argv[3] if len(sys.argv) > 3 else "fpga-uart,spi-fpga").split(",")
    models = (sys.argv[4] if len(sys.argv) > 4 else "dynamic,ideal").split(",")
    print("| raster lines | architecture | mechanics | simulated [s] | wall [s] | sim/wall | peak RSS [MiB] |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for lines in sizes:
            job = os.path.join(tmp, "raster_%d.nc" % lines)
            with open(job, "w") as f:
                f.write(raster(lines))
            for arch in archs:
                scenario = os.path.join(tmp, "raster_%d_%s.toml" % (lines, arch))
                with open(scenario, "w") as f:
                    f.write('[scenario]\njob = "%s"\narchitecture = "%s"\n' % (job, arch))
                report = os.path.join(tmp, "report.json")
                for model in models:
                    wall_s, rss_mib = run(build, scenario, model, report)
                    with open(report) as f:
                        sim_s = json.load(f)["metrics"]["job"]["job_time_s"]
                    print("| %d | %s | %s | %.1f | %.2f | %.0fx | %.1f |" %
                          (lines, arch, model, sim_s, wall_s, sim_s / wall_s, rss_mib), flush=True)


if __name__ == "__main__":
    main()
