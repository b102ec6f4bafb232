#!/usr/bin/env python3
"""The lathe's plots (docs/plots.md "lathe-sync"), checked against the run's own report.

Reads the plots and the report of scenarios/lathe-sync/m6_thread.toml run with --plots and --report (the ctest
fixture scenario/lathe.m6_outputs), then:
  1. plots.json lists exactly the lathe's two plots, with their titles and axis labels; each SVG is well-formed
     with those texts and each PNG decodes and is not blank (compare_outputs.py's checks).
  2. phase_error.dat holds a block per later pass; over the rows after the settle revolutions its largest |value|
     is the report's phase_error_max_um (to the data file's 9 digits), at the report's pass, revolution and sign,
     and over every row the report's phase_error_max_whole_pass_um; the largest |mean| over each block's last
     revolution (40 spindle pulses) is phase_error_end_um. The plot marks the max with the report's figures, and
     the settling revolutions are named in the key.
  3. following_error.dat holds a block per pass; the firmware column's max is the pass's
     following_error_max_pulses, and the carriage column lies within one motor pulse of it at every spindle
     pulse: the INT0 count follows the carriage within one pulse (docs/architectures.md "lathe-sync"), so the
     two curves of a pass part by at most that.

Usage: lathe_plots.py M6_OUTPUTS  (m6.json and m6_plots/ of that run)
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from compare_outputs import check_png, check_svg, svg_texts  # noqa: E402

SPINDLE_SLOTS = 40  # seed 002 §2.5.3 SP_PPR
DIGITS = 1e-6  # the data files carry 9 significant digits: below 1e-6 um on figures under 1000 um
REVOLUTION = "spindle revolutions since the pass start index [rev]"
EXPECTED = {
    "phase_error_passes": ("Phase error of each pass against pass 1", REVOLUTION,
                           "phase error [um] (+: ahead of pass 1)"),
    "following_error_passes": ("Following error of each pass: the firmware count and the carriage", REVOLUTION,
                               "following error [motor pulses]"),
}


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def blocks(path):
    """The data rows of a gnuplot file, a list per block (blocks are two blank lines apart)."""
    out, blank = [[]], 0
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            if not line.strip():
                blank += 1
                continue
            if blank >= 2 and out[-1]:
                out.append([])
            blank = 0
            out[-1].append([float(v) for v in line.split()])
    return out


def close(a, b):
    return abs(a - b) <= DIGITS * max(1.0, abs(b))


def check_phase(data, report, out):
    thread = report["thread"]
    passes = len(report["passes"])
    phase = blocks(os.path.join(data, "phase_error.dat"))
    if len(phase) != passes - 1:
        fail(f"phase_error.dat has {len(phase)} blocks for {passes} passes")
    settle = thread["settle_revolutions"]
    settled = [(abs(um), k + 2, rev, um) for k, rows in enumerate(phase) for rev, um in rows if rev >= settle]
    top = max(settled)
    if not close(top[0], thread["phase_error_max_um"]):
        fail(f"plotted max after {settle} revolutions {top[0]} um, report {thread['phase_error_max_um']} um")
    where = (top[1], top[2], top[3])
    want = (thread["phase_error_max_pass"], thread["phase_error_max_revolution"], thread["phase_error_max_signed_um"])
    if where[0] != want[0] or not close(where[1], want[1]) or not close(where[2], want[2]):
        fail(f"plotted max at pass, revolution, value {where}, report {want}")
    whole = max(abs(um) for rows in phase for _, um in rows)
    if not close(whole, thread["phase_error_max_whole_pass_um"]):
        fail(f"plotted max over whole passes {whole} um, report {thread['phase_error_max_whole_pass_um']} um")
    end = max(abs(sum(um for _, um in rows[-SPINDLE_SLOTS:]) / len(rows[-SPINDLE_SLOTS:])) for rows in phase)
    if not close(end, thread["phase_error_end_um"]):
        fail(f"plotted end {end} um, report {thread['phase_error_end_um']} um")
    for rows in phase:
        for rev, _ in rows:
            if not close(rev * SPINDLE_SLOTS, round(rev * SPINDLE_SLOTS)):
                fail(f"revolution {rev} is not a spindle pulse (1/{SPINDLE_SLOTS} rev)")
    texts = svg_texts(os.path.join(out, "phase_error_passes.svg"))
    mark = "max %+.2f um: pass %d at revolution %.3f" % (want[2], want[0], want[1])
    settling = f"first {settle} revolutions: settling, left out of the max"
    for text in (mark, settling):
        if text not in texts:
            fail(f"phase_error_passes.svg has no text {text!r}")
    return top


def check_following(data, report):
    following = blocks(os.path.join(data, "following_error.dat"))
    if len(following) != len(report["passes"]):
        fail(f"following_error.dat has {len(following)} blocks for {len(report['passes'])} passes")
    worst = 0.0
    for i, (rows, p) in enumerate(zip(following, report["passes"])):
        firmware = max(r[1] for r in rows)
        if not close(firmware, p["following_error_max_pulses"]):
            fail(f"pass {i + 1}: plotted firmware max {firmware}, report {p['following_error_max_pulses']} pulses")
        apart = max(abs(r[1] - r[2]) for r in rows)
        if apart > 1.0 + DIGITS:
            fail(f"pass {i + 1}: firmware count and carriage {apart} motor pulses apart (at most 1)")
        worst = max(worst, apart)
    return worst


def main():
    outputs = sys.argv[1]
    out = os.path.join(outputs, "m6_plots")
    with open(os.path.join(outputs, "m6.json")) as f:
        report = json.load(f)["lathe-sync"]
    with open(os.path.join(out, "plots.json")) as f:
        plots = json.load(f)
    names = [p["name"] for p in plots]
    if sorted(names) != sorted(EXPECTED):
        fail(f"plots.json lists {names}, expected {sorted(EXPECTED)}")
    for p in plots:
        if (p["title"], p["xlabel"], p["ylabel"]) != EXPECTED[p["name"]]:
            fail(f"{p['name']}: title and labels {(p['title'], p['xlabel'], p['ylabel'])}")
        check_svg(os.path.join(out, p["name"] + ".svg"), p)
        check_png(os.path.join(out, p["name"] + ".png"))
    data = os.path.join(out, "data", "lathe-sync")
    top = check_phase(data, report, out)
    apart = check_following(data, report)
    print(f"ok: phase error max {top[3]:+.3f} um (pass {top[1]}, revolution {top[2]:.3f}) as reported; "
          f"firmware count and carriage at most {apart:.3f} motor pulses apart")


if __name__ == "__main__":
    main()
