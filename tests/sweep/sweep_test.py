#!/usr/bin/env python3
"""`cncsim sweep` end to end: usage sweep_test.py MODE CNCSIM SOURCE_DIR WORKDIR.

- servo_tables: sweeps/spi_fpga_servo_loop.toml gives, for each of its nine points, the figures of a `cncsim run` of
  the square made here with the same keys (the expansion written out by hand, not the sweep's), and the servo-period
  and latency tables of docs/results.md and the spi-fpga README are those figures to 0.1 um.
- jobs: tests/data/sweeps/square_feeds.toml (3 architectures x 4 feeds x 5 seeds) gives the same results.csv,
  results.json and summary.md with --jobs 1 and --jobs 2; every point's report has the seed and feed the file gives
  it, and summary.md's mean, min, max and 95 % interval are those computed here from results.csv (Student's t from a
  table).
- resume: tests/data/sweeps/square_seeds.toml stopped by SIGINT after some points (exit 130, no results), then run
  again: the points done are not run again (their records and reports untouched, the rerun runs only the others),
  and the results equal an uninterrupted run's byte for byte.
- feed_search: sweeps/lost_step_feed.toml's [search] on fpga-uart finds the highest feed without a lost step that
  docs/mechanics.md states (F2640, F2700 losing steps), within the search's tolerance; a `cncsim run` made here at
  the feed found loses no step, one at the smallest failing feed loses some.
- bad_input: an unknown key, an empty value list, a range with step 0, a value out of its key's range and a metric
  pointer the report does not have each exit 2 naming the sweep file's line and the key, and write no results.
"""
import csv
import glob
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import check, check_bad_input, run_report  # noqa: E402

# t(0.975, n - 1) of a Student's t table, for the seed counts the tests use.
T975 = {2: 12.706, 3: 4.303, 4: 3.182, 5: 2.776}


def sweep(cncsim, sweep_file, out, *extra):
    return subprocess.run([cncsim, "sweep", sweep_file, "--out", out, *extra], capture_output=True, text=True)


def rows(out):
    with open(os.path.join(out, "results.csv"), newline="") as f:
        return list(csv.DictReader(f))


def read(path):
    with open(path, "rb") as f:
        return f.read()


def servo_tables(cncsim, source, work):
    out = os.path.join(work, "sweep")
    r = sweep(cncsim, os.path.join(source, "sweeps", "spi_fpga_servo_loop.toml"), out)
    check(r.returncode == 0, "the sweep failed: " + r.stderr)
    scenario = os.path.join(source, "scenarios", "spi-fpga", "square_20mm.toml")
    common = ["machine.rapid_feed_mm_per_min=12000", 'mechanics.model="ideal"']
    runs = [("servo_period", "host.servo_period_us", v, []) for v in (250, 500, 1000, 2000)]
    runs += [("latency", "host.latency_max_us", v, ['host.latency_distribution="uniform"']) for v in (0, 20, 50, 100, 200)]
    got = rows(out)
    check(len(got) == len(runs), "%d points, not %d" % (len(got), len(runs)))
    figures = {}
    for (study, key, value, sets), row in zip(runs, got):
        check(row["study"] == study and float(row[key]) == value, "point %s is not %s = %s" % (row["point"], key, value))
        report, _ = run_report(cncsim, scenario, work, "%s_%s" % (study, value), common + sets + ["%s=%s" % (key, value)])
        path = report["metrics"]["path"]
        for metric in ("following_max_um", "following_rms_um"):
            check(float(row["/metrics/path/" + metric]) == path[metric],
                  "%s = %s: %s %s, a run gives %r" % (key, value, metric, row["/metrics/path/" + metric], path[metric]))
        figures.setdefault(study, []).append("%.1f / %.1f" % (path["following_max_um"], path["following_rms_um"]))
    for doc in ("docs/results.md", "sim/architectures/spi_fpga/README.md"):
        with open(os.path.join(source, doc), encoding="utf-8") as f:
            text = f.read()
        for study, head in (("servo_period", "| servo period"), ("latency", "| latency bound")):
            m = re.search(re.escape(head) + r"[^\n]*\n[^\n]*\n\| following max / RMS \[um\] \|([^\n]*)\|\n", text)
            check(m is not None, "%s: no %s table" % (doc, study))
            shown = [c.strip() for c in m.group(1).split("|")]
            check(shown == figures[study], "%s, %s table: %s, the sweep gives %s" % (doc, study, shown, figures[study]))
    print("servo period:", figures["servo_period"], "latency:", figures["latency"])


def jobs(cncsim, source, work):
    sweep_file = os.path.join(source, "tests", "data", "sweeps", "square_feeds.toml")
    outs = {}
    for n in ("1", "2"):
        outs[n] = os.path.join(work, "jobs" + n)
        shutil.rmtree(outs[n], ignore_errors=True)
        r = sweep(cncsim, sweep_file, outs[n], "--jobs", n)
        check(r.returncode == 0, "--jobs %s: exit %d: %s" % (n, r.returncode, r.stderr))
    for name in ("results.csv", "results.json", "summary.md"):
        check(read(os.path.join(outs["1"], name)) == read(os.path.join(outs["2"], name)),
              name + " differs between --jobs 1 and --jobs 2")
    got = rows(outs["1"])
    check(len(got) == 3 * 4 * 5, "%d points" % len(got))
    for row in got:
        with open(os.path.join(outs["1"], "points", row["point"] + ".json")) as f:
            scenario = json.load(f)["scenario"]
        check(row["status"] == "ok", "point %s: %s" % (row["point"], row["message"]))
        check(scenario["seed"] == int(row["seed"]) and scenario["architecture"] == row["architecture"],
              "point %s ran seed %s on %s" % (row["point"], scenario["seed"], scenario["architecture"]))
    # The feed reached the job: the ideal controller's square takes 80 mm at each feed plus a fixed rest.
    ideal = {float(r["scenario.feed_mm_per_min"]): float(r["/metrics/job/job_time_s"]) for r in got
             if r["architecture"] == "ideal"}
    check(ideal[1200] - ideal[2400] > 0.9 * 80.0 * (60 / 1200 - 60 / 2400), "the feed does not reach the job: %s" % ideal)
    seeds_differ = {r["/metrics/path/following_max_um"] for r in got if r["architecture"] == "fpga-uart"
                    and r["scenario.feed_mm_per_min"] == "2400"}
    check(len(seeds_differ) > 1, "fpga-uart's five seeds give one following error")
    with open(os.path.join(outs["1"], "summary.md")) as f:
        summary = f.read()
    metric = "/metrics/path/following_max_um"
    section = summary[summary.index("### " + metric):]
    for arch in ("ideal", "fpga-uart", "spi-fpga"):
        for feed in ("1200", "1600", "2000", "2400"):
            v = [float(r[metric]) for r in got if r["architecture"] == arch and r["scenario.feed_mm_per_min"] == feed]
            mean = sum(v) / len(v)
            sd = math.sqrt(sum((x - mean) ** 2 for x in v) / (len(v) - 1))
            half = T975[len(v)] * sd / math.sqrt(len(v))
            want = "| %s | %s | 5 | %.6g | %.6g | %.6g | %.6g .. %.6g |" % (arch, feed, mean, min(v), max(v),
                                                                           mean - half, mean + half)
            check(want in section, "summary.md has no line %s" % want)
    print("60 points, the same with --jobs 1 and 2; summary.md's statistics as computed here")


def resume(cncsim, source, work):
    sweep_file = os.path.join(source, "tests", "data", "sweeps", "square_seeds.toml")
    whole = os.path.join(work, "whole")
    parts = os.path.join(work, "parts")
    for d in (whole, parts):
        shutil.rmtree(d, ignore_errors=True)
    r = sweep(cncsim, sweep_file, whole)
    check(r.returncode == 0, "the uninterrupted sweep failed: " + r.stderr)
    total = len(rows(whole))
    child = subprocess.Popen([cncsim, "sweep", sweep_file, "--out", parts, "--jobs", "2"], stderr=subprocess.PIPE,
                             text=True)
    deadline = time.time() + 120
    while len(glob.glob(os.path.join(parts, "points", "*.done.json"))) < 4 and time.time() < deadline:
        time.sleep(0.02)
    child.send_signal(signal.SIGINT)
    _, err = child.communicate(timeout=120)
    check(child.returncode == 130, "interrupted: exit %s, not 130: %s" % (child.returncode, err))
    check(not os.path.exists(os.path.join(parts, "results.csv")), "an interrupted sweep wrote results.csv")
    done = sorted(glob.glob(os.path.join(parts, "points", "*.done.json")))
    check(4 <= len(done) < total, "%d of %d points done before the interrupt" % (len(done), total))
    before = {p: (os.stat(p).st_mtime_ns, read(p)) for p in done + [d[:-len(".done.json")] + ".json" for d in done]}
    r = sweep(cncsim, sweep_file, parts)
    check(r.returncode == 0, "the resumed sweep failed: " + r.stderr)
    said = "%d of %d points done by an earlier run, %d to run" % (len(done), total, total - len(done))
    check(said in r.stderr, "the rerun does not say '%s': %s" % (said, r.stderr))
    for p, (mtime, text) in before.items():
        check(os.stat(p).st_mtime_ns == mtime and read(p) == text, p + " was written again: its point ran twice")
    for name in ("results.csv", "results.json", "summary.md"):
        check(read(os.path.join(whole, name)) == read(os.path.join(parts, name)),
              name + ": the resumed sweep's differs from the uninterrupted one's")
    print("interrupted after %d of %d points; resumed, the same results" % (len(done), total))


def feed_search(cncsim, source, work):
    with open(os.path.join(source, "sweeps", "lost_step_feed.toml")) as f:
        text = f.read()
    scenario = os.path.join(source, "scenarios", "mechanics", "six_segment_f4800.toml")
    text = text.replace('"../scenarios/mechanics/six_segment_f4800.toml"', '"%s"' % scenario)
    text = re.sub(r"architectures = \[[^]]*\]", 'architectures = ["fpga-uart"]', text)
    check('architectures = ["fpga-uart"]' in text and scenario in text, "the sweep file is not as the test expects")
    sweep_file = os.path.join(work, "lost_step_feed.toml")
    with open(sweep_file, "w") as f:
        f.write(text)
    out = os.path.join(work, "out")
    shutil.rmtree(out, ignore_errors=True)
    r = sweep(cncsim, sweep_file, out)
    check(r.returncode == 0, "the search failed: " + r.stderr)
    with open(os.path.join(out, "search.json")) as f:
        found = json.load(f)
    tolerance = found["tolerance"]
    result = found["architectures"][0]
    with open(os.path.join(source, "docs", "mechanics.md"), encoding="utf-8") as f:
        m = re.search(r"\| fpga-uart \| [^|]* \| F(\d+) \(F(\d+) loses steps\) \|", f.read())
    check(m is not None, "docs/mechanics.md states no highest feed for fpga-uart")
    stated, stated_bad = float(m.group(1)), float(m.group(2))
    check(abs(result["largest"] - stated) <= tolerance and result["smallest_failing"] - result["largest"] <= tolerance,
          "the search found F%s (F%s fails), the docs state F%g" % (result["largest"], result["smallest_failing"], stated))
    for feed, lossless in ((result["largest"], True), (result["smallest_failing"], False)):
        report, _ = run_report(cncsim, scenario, work, "f%g" % feed,
                               ["scenario.architecture=fpga-uart", "clock.ideal=true", "scenario.feed_mm_per_min=%g" % feed,
                                "machine.rapid_feed_mm_per_min=%g" % feed])
        lost = [report["fpga-uart"]["mechanics"][a]["lost_full_steps"] for a in ("x", "y")]
        check((sum(lost) == 0) == lossless, "F%g loses %s full steps" % (feed, lost))
    print("fpga-uart: F%g without lost steps, F%g loses some (docs: F%g, F%g)" % (result["largest"],
                                                                              result["smallest_failing"], stated,
                                                                              stated_bad))


def bad_input(cncsim, source, work):
    scenario = os.path.join(source, "scenarios", "fpga-uart", "square_20mm.toml")
    head = 'scenario = "%s"\nmetrics = ["/metrics/job/job_time_s"]\n' % scenario
    cases = {
        "unknown_key": ('vary = [{ key = "host.servo_period", values = [1] }]\n', 3, "host.servo_period",
                        "not a scenario key"),
        "empty_list": ('vary = [{ key = "fpga.queue_depth", values = [] }]\n', 3, "vary[0].values", "empty list"),
        "step_zero": ('vary = [{ key = "fpga.queue_depth", from = 0, to = 4, step = 0 }]\n', 3, "vary[0].step",
                      "step 0"),
        "out_of_range": ('vary = [{ key = "host.operator_pause_s", values = [5, -1] }]\n', 3,
                         "host.operator_pause_s = -1", "--set host.operator_pause_s"),
        "unknown_metric": ('vary = [{ key = "fpga.queue_depth", values = [0] }]\n', 2, "metrics",
                           '"/metrics/job/no_such_time_s" is not in the report of fpga-uart'),
    }
    for name, (vary, line, key, what) in cases.items():
        text = head + vary
        if name == "unknown_metric":
            text = text.replace("job_time_s", "no_such_time_s")
        path = os.path.join(work, name + ".toml")
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(work, name)
        check_bad_input(name, sweep(cncsim, path, out), ["%s:%d: %s" % (path, line, key), what],
                        os.path.join(out, "results.csv"))


def main():
    mode, cncsim, source, work = sys.argv[1:5]
    source = os.path.abspath(source)
    os.makedirs(work, exist_ok=True)
    {"servo_tables": servo_tables, "jobs": jobs, "resume": resume, "feed_search": feed_search,
     "bad_input": bad_input}[mode](cncsim, source, work)


if __name__ == "__main__":
    main()
