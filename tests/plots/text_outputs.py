#!/usr/bin/env python3
"""Every text file that `cncsim compare SCENARIO --out DIR` and `cncsim run SCENARIO --plots DIR` write is clean
text, and what the plots and the page say of counts agrees with numbers read elsewhere:

- no control byte (below 0x20, other than tab, line feed and carriage return) and valid UTF-8 in any file written
  but the PNGs: the scripts, data files, tables, reports, SVGs, VCDs and the page;
- the dead-time plot's title of each run gives its number of gaps, which equals both the report's gaps between
  and inside moves (metrics/job/dead_gaps + dead_inside_gaps) and the rows of the run's dead_time.dat, and its x range ends one past the last gap;
- the page shows the job's first 80 lines and says how many more there are (`long_job`: a job of more lines,
  written here).

usage: text_outputs.py CNCSIM SOURCE_DIR WORK_DIR (SCENARIO_NAME | long_job)
  SCENARIO_NAME is one of scenarios/compare/*.toml, without .toml.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tomllib
import xml.etree.ElementTree as ET

ARCHS = ["ideal", "fpga-uart", "atmega", "spi-fpga"]
JOB_LINES_SHOWN = 80  # the page's head of a long job (compare_outputs.cpp)
# Bytes below 0x20 but tab (0x09), line feed (0x0a) and carriage return (0x0d).
CONTROL = re.compile(rb"[\x00-\x08\x0b\x0c\x0e-\x1f]")
BINARY = (".png",)
SVG_NS = "{http://www.w3.org/2000/svg}"


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(cmd, cwd=None):
    r = subprocess.run(cmd, capture_output=True, cwd=cwd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr.decode(errors='replace')}")
    return r.stdout


def check_text(name, data):
    bad = CONTROL.search(data)
    if bad is not None:
        i, b = bad.start(), data[bad.start()]
        context = data[max(0, i - 40):i + 20].decode("utf-8", errors="replace")
        fail(f"{name}: control byte 0x{b:02x} at offset {i}: {context!r}")
    try:
        data.decode("utf-8")
    except UnicodeDecodeError as e:
        fail(f"{name}: not UTF-8: {e}")


def check_files(out):
    """Every file under `out` but the PNGs is clean text; returns the number checked by extension."""
    by_ext = {}
    for root, _, files in os.walk(out):
        for f in files:
            if f.endswith(BINARY):
                continue
            path = os.path.join(root, f)
            with open(path, "rb") as fh:
                check_text(path, fh.read())
            ext = os.path.splitext(f)[1]
            by_ext[ext] = by_ext.get(ext, 0) + 1
    return by_ext


def data_rows(path):
    """Rows of a gnuplot data file: lines that are neither empty nor `#` comments."""
    with open(path, encoding="utf-8") as f:
        return [line.split() for line in f if line.strip() and not line.startswith("#")]


def svg_texts(path):
    root = ET.parse(path).getroot()
    return {"".join(t.itertext()).strip() for t in root.iter(SVG_NS + "text")}


def plot_names(out):
    with open(os.path.join(out, "plots.json"), encoding="utf-8") as f:
        return {p["name"] for p in json.load(f)}


def check_dead_time(out, reports):
    """reports: {architecture: its JSON report}, the runs plotted in `out`."""
    gaps = {}
    for arch, report in reports.items():
        job = report["metrics"]["job"]
        gaps[arch] = job["dead_gaps"] + (job["dead_inside_gaps"] or 0)
        rows = data_rows(os.path.join(out, "data", arch, "dead_time.dat"))
        if len(rows) != gaps[arch]:
            fail(f"{arch}: dead_time.dat has {len(rows)} gaps, the report's between and inside moves {gaps[arch]}")
    if "dead_time" not in plot_names(out):
        if any(gaps.values()):
            fail(f"{out}: no dead_time plot, with gaps {gaps}")
        return gaps
    with open(os.path.join(out, "data", "dead_time.gp"), encoding="utf-8") as f:
        script = f.read()
    # A panel per run: its title, then its settings up to the next panel's title.
    panels = {m.group(1): (m.group(2), m.group(3)) for m in
              re.finditer(r"^set title '([^':\n]+): ([^'\n]*) gaps'\n(.*?)(?=^set title |\Z)", script, re.M | re.S)}
    if set(panels) != set(reports):
        fail(f"dead_time.gp titles runs {sorted(panels)}, the runs are {sorted(reports)}")
    texts = svg_texts(os.path.join(out, "dead_time.svg"))
    for arch, n in gaps.items():
        title, panel = panels[arch]
        if title != str(n):
            fail(f"dead_time.gp: title {arch + ': ' + title + ' gaps'!r}, the report counts {n} gaps")
        if f"{arch}: {n} gaps" not in texts:
            fail(f"dead_time.svg has no text '{arch}: {n} gaps'")
        if n > 0 and f"set xrange [0:{n + 1}]\n" not in panel:
            fail(f"dead_time.gp: {arch}'s panel has no 'set xrange [0:{n + 1}]'")
    return gaps


def job_lines(path):
    with open(path, "rb") as f:
        parts = f.read().split(b"\n")
    return len(parts) - (1 if parts[-1] == b"" else 0)


def check_page(out, job):
    with open(os.path.join(out, "index.html"), encoding="utf-8") as f:
        page = f.read()
    n = job_lines(job)
    more = re.findall(r"\.\.\. \((\S+) more lines\)", page)
    if n > JOB_LINES_SHOWN and more != [str(n - JOB_LINES_SHOWN)]:
        fail(f"index.html says {more} more lines; the job has {n} lines, {JOB_LINES_SHOWN} shown")
    if n <= JOB_LINES_SHOWN and more:
        fail(f"index.html says {more} more lines of a job of {n} lines")
    return n


def long_job(work, source):
    """A scenario of the compare machine with a job of 100 moves: more lines than the page shows."""
    with open(os.path.join(work, "long.nc"), "w") as f:
        f.write("(a zigzag of 100 moves, 0.5 mm across and 0.25 mm up each)\nG21 G90\nG0 X1 Y1\nM3\n")
        for k in range(1, 101):
            f.write(f"G1 X{1 + 0.5 * (k % 2):.1f} Y{1 + 0.25 * k:.2f} F1200\n")
        f.write("M5\nM30\n")
    with open(os.path.join(source, "scenarios", "compare", "diagonal_45.toml"), encoding="utf-8") as f:
        text = f.read()
    scenario = os.path.join(work, "long.toml")
    with open(scenario, "w") as f:
        f.write(re.sub(r'^job = ".*"', 'job = "long.nc"', text, count=1, flags=re.M))
    return scenario


def reports_in(out, archs, name):
    reports = {}
    for arch in archs:
        with open(os.path.join(out, name(arch)), encoding="utf-8") as f:
            reports[arch] = json.load(f)
    return reports


def main():
    cncsim, source, work, name = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if name == "long_job":
        scenario, archs = long_job(work, source), ["ideal", "fpga-uart"]
    else:
        scenario, archs = os.path.join(source, "scenarios", "compare", name + ".toml"), ARCHS
    with open(scenario, "rb") as f:
        setup = tomllib.load(f)
    job = os.path.join(os.path.dirname(scenario), setup["scenario"]["job"])

    compare = os.path.join(work, "compare")
    table = run([cncsim, "compare", scenario, "--arch", ",".join(archs), "--out", compare])
    check_text("compare's table (stdout)", table)
    checked = check_files(compare)
    gaps = check_dead_time(compare, reports_in(compare, archs, lambda a: a + ".json"))
    lines = check_page(compare, job)
    print(f"compare {name}: dead-time gaps {gaps}; job of {lines} lines")

    if name != "long_job":
        plots = os.path.join(work, "run")
        arch = setup["scenario"]["architecture"]
        run([cncsim, "run", scenario, "--plots", plots, "--report", os.path.join(work, "run.json"),
             "--progress", "off"])
        check_text("run.json", open(os.path.join(work, "run.json"), "rb").read())
        for ext, n in check_files(plots).items():
            checked[ext] = checked.get(ext, 0) + n
        gaps = check_dead_time(plots, {arch: json.load(open(os.path.join(work, "run.json"), encoding="utf-8"))})
        print(f"run --plots {name} ({arch}): dead-time gaps {gaps}")

    for ext in (".gp", ".dat", ".json", ".svg", ".html", ".md", ".csv"):
        if not checked.get(ext):
            fail(f"no {ext} file written: nothing of that kind was checked")
    print("ok: text files checked, by extension: " + ", ".join(f"{e or '(none)'} {n}" for e, n in
                                                                sorted(checked.items())))
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
