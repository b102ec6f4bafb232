#!/usr/bin/env python3
"""The comparison results of the README and docs/results.md, and spi-fpga's servo-loop tables (docs/results.md and
its README), regenerated from the simulator in one command:

    scripts/update_results.py build/sim/cncsim          # rewrite the tables and docs/results/*.png
    scripts/update_results.py build/sim/cncsim --check  # exit 1 if a table differs from a fresh run

Each table sits between `<!-- results:NAME:begin -->` and `<!-- results:NAME:end -->` (README.md: the circle;
docs/results.md: every job) and is what `cncsim compare scenarios/compare/NAME.toml --arch ARCHS --format markdown`
prints; the path overlay plot of each job is copied from its `--out` folder to docs/results/NAME_path.png. The
servo-loop tables (`spi_fpga_servo_period`, `spi_fpga_latency`) are the studies of `cncsim sweep
sweeps/spi_fpga_servo_loop.toml`: following error max / RMS at each value.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
JOBS = ["circle_r10", "six_segment"]
# The tables of each file, by job.
SERVO_TABLES = ["spi_fpga_servo_period", "spi_fpga_latency"]
FILES = {"README.md": ["circle_r10"], os.path.join("docs", "results.md"): JOBS + SERVO_TABLES,
         os.path.join("sim", "architectures", "spi_fpga", "README.md"): SERVO_TABLES}
# Each servo-loop table: its study in the sweep file, the swept key, the table's first header cell.
SERVO_STUDIES = {"spi_fpga_servo_period": ("servo_period", "host.servo_period_us", "servo period (50 us exponential)"),
                 "spi_fpga_latency": ("latency", "host.latency_max_us", "latency bound (uniform)")}
ARCHS = "ideal,fpga-uart,atmega,spi-fpga"


def table(cncsim, job, out=None):
    cmd = [cncsim, "compare", os.path.join("scenarios", "compare", job + ".toml"), "--arch", ARCHS,
           "--format", "markdown"]
    if out:
        cmd += ["--out", out]
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {r.returncode}")
    return r.stdout


def servo_tables(cncsim, tmp):
    out = os.path.join(tmp, "servo_loop")
    cmd = [cncsim, "sweep", os.path.join("sweeps", "spi_fpga_servo_loop.toml"), "--out", out]
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {r.returncode}")
    with open(os.path.join(out, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    tables = {}
    for name, (study, key, head) in SERVO_STUDIES.items():
        points = [r for r in rows if r["study"] == study]
        values = [float(r[key]) for r in points]
        cells = ["%g ms" % (v / 1000) if v >= 1000 else "%g us" % v for v in values]
        figures = ["%.1f / %.1f" % (float(r["/metrics/path/following_max_um"]), float(r["/metrics/path/following_rms_um"]))
                   for r in points]
        tables[name] = ("| " + " | ".join([head] + cells) + " |\n|" + "---|" * (len(cells) + 1) + "\n" +
                        "| " + " | ".join(["following max / RMS [um]"] + figures) + " |\n")
    return tables


def block(text, job):
    begin = f"<!-- results:{job}:begin -->\n"
    end = f"<!-- results:{job}:end -->"
    i = text.index(begin) + len(begin)
    return i, text.index(end, i)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cncsim = os.path.abspath(sys.argv[1])
    check = "--check" in sys.argv[2:]
    stale = []
    with tempfile.TemporaryDirectory(prefix="cncsim-results-") as tmp:
        fresh = {}
        for job in JOBS:
            out = None if check else os.path.join(tmp, job)
            fresh[job] = table(cncsim, job, out)
            if out:
                os.makedirs(os.path.join(ROOT, "docs", "results"), exist_ok=True)
                shutil.copy(os.path.join(out, "path.png"), os.path.join(ROOT, "docs", "results", job + "_path.png"))
        fresh.update(servo_tables(cncsim, tmp))
        for name, jobs in FILES.items():
            path = os.path.join(ROOT, name)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            for job in jobs:
                i, j = block(text, job)
                if text[i:j] != fresh[job]:
                    stale.append(f"{name}: {job}")
                    print(f"{name}: table {job} differs from the run:\n--- {name}\n{text[i:j]}--- run\n{fresh[job]}")
                    text = text[:i] + fresh[job] + text[j:]
            if not check:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
    if check:
        if stale:
            sys.exit("stale results (" + ", ".join(stale) + "): run scripts/update_results.py " + sys.argv[1])
        print("the results tables match the runs")


if __name__ == "__main__":
    main()
