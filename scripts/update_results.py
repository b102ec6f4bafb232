#!/usr/bin/env python3
"""The README's comparison results, regenerated from the simulator in one command:

    scripts/update_results.py build/sim/cncsim          # rewrite the README tables and docs/results/*.png
    scripts/update_results.py build/sim/cncsim --check  # exit 1 if the README's tables differ from a fresh run

Each table sits between `<!-- results:NAME:begin -->` and `<!-- results:NAME:end -->` in README.md and is what
`cncsim compare scenarios/compare/NAME.toml --format markdown` prints; the path overlay plot of each job is copied
from its `--out` folder to docs/results/NAME_path.png.
"""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
JOBS = ["circle_r10", "six_segment"]
ARCHS = "fpga-uart,atmega,spi-fpga"


def table(cncsim, job, out=None):
    cmd = [cncsim, "compare", os.path.join("scenarios", "compare", job + ".toml"), "--arch", ARCHS,
           "--format", "markdown"]
    if out:
        cmd += ["--out", out]
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {r.returncode}")
    return r.stdout


def block(readme, job):
    begin = f"<!-- results:{job}:begin -->\n"
    end = f"<!-- results:{job}:end -->"
    i = readme.index(begin) + len(begin)
    return i, readme.index(end, i)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cncsim = os.path.abspath(sys.argv[1])
    check = "--check" in sys.argv[2:]
    path = os.path.join(ROOT, "README.md")
    with open(path, encoding="utf-8") as f:
        readme = f.read()
    stale = []
    with tempfile.TemporaryDirectory(prefix="cncsim-results-") as tmp:
        for job in JOBS:
            out = None if check else os.path.join(tmp, job)
            fresh = table(cncsim, job, out)
            i, j = block(readme, job)
            if readme[i:j] != fresh:
                stale.append(job)
                print(f"README table {job} differs from the run:\n--- README\n{readme[i:j]}--- run\n{fresh}")
                readme = readme[:i] + fresh + readme[j:]
            if out:
                os.makedirs(os.path.join(ROOT, "docs", "results"), exist_ok=True)
                shutil.copy(os.path.join(out, "path.png"), os.path.join(ROOT, "docs", "results", job + "_path.png"))
    if check:
        if stale:
            sys.exit("stale README results: run scripts/update_results.py " + sys.argv[1])
        print("README results match the runs")
        return
    with open(path, "w", encoding="utf-8") as f:
        f.write(readme)


if __name__ == "__main__":
    main()
