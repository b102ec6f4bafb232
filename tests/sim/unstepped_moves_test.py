#!/usr/bin/env python3
"""Moves shorter than one microstep are recorded (docs/metrics.md "Move"): usage CNCSIM ARCH WORKDIR.

A job with four such moves (the first move, one between two moves, one after a dwell, the last move) among two
that step: the report has one record per programmed move (as many as gcode.moves), on the job's lines in order,
the short ones with zero steps commanded (and emitted, where the host sends nothing for them). Where the host sends nothing for them (fpga-uart, atmega),
the run is the run of the same job without them: the same STEP edges, job time and dead time, the dwell kept.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import run_report  # noqa: E402

SHORT_MM = 0.001
JOB = [  # (G-code, steps): whether the line's move steps
    ("G21 G90 F600", None),
    ("G1 X%.3f" % SHORT_MM, False),
    ("G1 X10", True),
    ("G1 X%.3f" % (10 + SHORT_MM), False),
    ("G4 P0.5", None),
    ("G1 X%.3f" % (10 + 2 * SHORT_MM), False),
    ("G1 Y5", True),
    ("G1 Y%.3f" % (5 + SHORT_MM), False),
    ("M2", None),
]
HOSTS_SEND_NOTHING = {"fpga-uart", "atmega"}


def write_job(folder, name, with_short):
    lines = [code for code, steps in JOB if with_short or steps is not False]
    path = os.path.join(folder, name + ".nc")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    scenario = os.path.join(folder, name + ".toml")
    with open(scenario, "w") as f:
        f.write('[scenario]\njob = "%s"\n' % path)
    return scenario


def main():
    cncsim, arch, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    failures = []
    sets = ["scenario.architecture=" + arch]
    report, _ = run_report(cncsim, write_job(work, "short", True), work, "short", sets)
    microstep_mm = 1.0 / max(report["scenario"]["steps_per_mm"])
    if SHORT_MM >= microstep_mm / 2:
        failures.append("the short moves (%g mm) round to a step of %g mm" % (SHORT_MM, microstep_mm))

    want_lines = [n + 1 for n, (_, steps) in enumerate(JOB) if steps is not None]
    moves = report["metrics"]["moves"]
    if report["gcode"]["moves"] != len(want_lines):
        failures.append("gcode.moves %d, the job has %d" % (report["gcode"]["moves"], len(want_lines)))
    if moves["line"] != want_lines:
        failures.append("move records on lines %s, the job's moves are on %s" % (moves["line"], want_lines))
    else:
        for k, n in enumerate(want_lines):
            if JOB[n - 1][1]:
                continue
            # A planner's FPGA steps behind its servo thread: a step of the move before may fall in a short move's
            # window there; a host that sends nothing for it gives it an instant, where no step falls.
            fields = ("steps_commanded", "steps_emitted") if arch in HOSTS_SEND_NOTHING else ("steps_commanded",)
            for field in fields:
                steps = {axis: per_move[k] for axis, per_move in moves[field].items()}
                if any(steps.values()):
                    failures.append("line %d: %s %s, expected none" % (n, field, steps))

    if arch in HOSTS_SEND_NOTHING:
        base, _ = run_report(cncsim, write_job(work, "base", False), work, "base", sets)
        for key in ("job_time_s", "dead_total_ms", "dead_gaps"):
            got, want = report["metrics"]["job"][key], base["metrics"]["job"][key]
            if got != want:
                failures.append("metrics.job.%s %r, without the short moves %r" % (key, got, want))
        got = [a["rising_edges"] for a in report["metrics"]["axes"]]
        want = [a["rising_edges"] for a in base["metrics"]["axes"]]
        if got != want:
            failures.append("rising edges %s, without the short moves %s" % (got, want))
        if report["metrics"]["job"]["job_time_s"] < 0.5:
            failures.append("job time %g s: the 0.5 s dwell is lost" % report["metrics"]["job"]["job_time_s"])

    for f in failures:
        print("FAIL:", f)
    print("%s: %d move records on lines %s" % (arch, len(moves["line"]), moves["line"]))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
