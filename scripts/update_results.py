#!/usr/bin/env python3
"""The comparison results of the README and docs/results.md, regenerated from the simulator in one command:

    scripts/update_results.py build/sim/cncsim          # rewrite the tables and docs/results/*.png
    scripts/update_results.py build/sim/cncsim --check  # exit 1 if a table differs from a fresh run

Each table sits between `<!-- results:NAME:begin -->` and `<!-- results:NAME:end -->` (README.md: the circle;
docs/results.md: every job) and is what `cncsim compare scenarios/compare/NAME.toml --arch ARCHS --format markdown`
prints; the path overlay plot of each job is copied from its `--out` folder to docs/results/NAME_path.png.
"""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
JOBS = ["circle_r10", "six_segment"]
# The tables of each file, by job.
FILES = {"README.md": ["circle_r10"], os.path.join("docs", "results.md"): JOBS}
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
