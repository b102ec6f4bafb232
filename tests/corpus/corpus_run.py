#!/usr/bin/env python3
"""One corpus job through `cncsim run` on one architecture, checked from outside the interpreter.

lenient: exit 0, a report marked ok and of bounded size, the programmed moves' end points, kinds and arc centres
equal to those this script's second reader (tests/data/gcode-corpus/check_corpus.py, Machine) finds, to 1e-9 mm,
one record per XY move; and the report's "ignored by this machine" list equal, word by word and line
by line, to what this script finds by its own reading of the file (the words docs/gcode.md lists as
ignored: T D H O M6 M7-M9 M100-M199 G40-G42 G43 G49 G80 G97 G18 G19, '%' lines and '/' block-delete lines).
strict: exit 2 when the file has any such word, with every one of them named in the message; exit 0 otherwise.

Usage: corpus_run.py CNCSIM JOB ARCH lenient|strict WORKDIR
"""
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "gcode-corpus"))
from check_corpus import Machine  # noqa: E402

WORD = re.compile(r"([A-Z])([-+]?(?:\d+\.?\d*|\.\d+))")
IGNORED_G = {"G40", "G41", "G42", "G41.1", "G42.1", "G43", "G43.1", "G43.2", "G49", "G80", "G97", "G18", "G19"}
IGNORED_M = {"M6", "M7", "M8", "M9"} | {"M%d" % n for n in range(100, 200)}


def code(letter, number):
    value = float(number)
    text = "%g" % value
    return letter + text


def expected_ignored(path):
    """word -> sorted list of line numbers, up to the program end (M2/M30 or the second '%')."""
    found = {}
    marks = 0
    with open(path, encoding="utf-8") as f:
        for n, raw in enumerate(f.read().splitlines(), start=1):
            body = raw.strip()
            if body == "%":
                found.setdefault("%", []).append(n)
                marks += 1
                if marks == 2:
                    break
                continue
            if body.startswith("/"):
                found.setdefault("/", []).append(n)
                continue
            text = re.sub(r"\([^)]*\)", "", raw.split(";")[0]).upper().replace(" ", "").replace("\t", "")
            words = WORD.findall(text)
            ended = False
            for letter, number in words:
                w = code(letter, number) if letter in "GM" else letter + number
                if (letter == "G" and w in IGNORED_G) or (letter == "M" and w in IGNORED_M) or letter in "TDHO":
                    lines = found.setdefault(w, [])
                    if not lines or lines[-1] != n:
                        lines.append(n)
                if letter == "M" and w in ("M2", "M30"):
                    ended = True
            if ended:
                break
    return found


def programmed_end_failures(job, report):
    """The report's programmed moves against the moves check_corpus.py's Machine reads from the file."""
    machine = Machine(1200.0, False)
    with open(job, encoding="utf-8") as f:
        for n, line in enumerate(f.read().splitlines(), start=1):
            machine.block(line, n)
    # cncsim's XY moves: an arc, or a line whose XY part is longer than 1e-9 mm (a Z-only move is a host wait).
    want = [e for e in machine.ends
            if e[3] is not None or math.hypot(e[2]["X"] - e[1]["X"], e[2]["Y"] - e[1]["Y"]) > 1e-9]
    moves = report["metrics"]["moves"]
    failures = []
    if len(moves["index"]) != report["gcode"]["moves"]:
        failures.append("%d move records for gcode.moves %d" % (len(moves["index"]), report["gcode"]["moves"]))
    if len(moves["index"]) != len(want):
        failures.append("%d move records, the file has %d XY moves" % (len(moves["index"]), len(want)))
        return failures
    for k, (kind, _, end, centre, line) in enumerate(want):
        got = (moves["kind"][k], moves["end_x_mm"][k], moves["end_y_mm"][k], moves["end_z_mm"][k])
        bad = got[0] != kind or any(abs(a - b) > 1e-9 for a, b in zip(got[1:], (end["X"], end["Y"], end["Z"])))
        if centre is not None:
            bad = bad or any(abs(a - b) > 1e-9 for a, b in zip((moves["center_x_mm"][k], moves["center_y_mm"][k]),
                                                               centre))
        elif moves["center_x_mm"][k] is not None:
            bad = True
        if bad or moves["line"][k] != line:
            failures.append("move %d (line %d): report %s, centre %s; file %s %s, centre %s" %
                            (k + 1, line, got, (moves["center_x_mm"][k], moves["center_y_mm"][k]), kind, end, centre))
            break
    return failures


def main():
    cncsim, job, arch, policy, workdir = sys.argv[1:6]
    os.makedirs(workdir, exist_ok=True)
    scenario = os.path.join(workdir, "scenario.toml")
    report = os.path.join(workdir, "report.json")
    if os.path.exists(report):
        os.remove(report)
    with open(scenario, "w") as f:
        # The corpus jobs' long rapids exceed send_steps.py's 10 s ACK timeout (the 40k job's last G0 takes
        # 10.6 s at 1200 mm/min): a user raises the key, as the timeout message says.
        f.write('[scenario]\njob = "%s"\narchitecture = "%s"\ngcode_policy = "%s"\n[host]\nack_timeout_s = 60\n'
                % (os.path.abspath(job), arch, policy))
    run = subprocess.run([cncsim, "run", scenario, "--report", report], capture_output=True, text=True)
    expected = expected_ignored(job)
    failures = []
    if policy == "lenient":
        if run.returncode != 0:
            failures.append("exit %d, expected 0" % run.returncode)
        else:
            with open(report) as f:
                r = json.load(f)
            if not r["ok"]:
                failures.append("report not ok")
            got = {w["word"]: w["lines"] for w in r["gcode"]["ignored_by_this_machine"]}
            if got != expected:
                failures.append("ignored words differ:\n  report: %s\n  file:   %s" % (got, expected))
            for w in r["gcode"]["ignored_by_this_machine"]:
                if w["count"] != len(w["lines"]):
                    failures.append("count of %s is %d for %d lines" % (w["word"], w["count"], len(w["lines"])))
            if r["gcode"]["moves"] == 0:
                failures.append("no XY move was run")
            # The default report grows with the job by its per-move columns only: under 1 MB and 160 bytes a move.
            bound = 1024 * 1024 + 160 * r["gcode"]["moves"]
            if os.path.getsize(report) >= bound:
                failures.append("default report is %d bytes, not under %d" % (os.path.getsize(report), bound))
            failures += programmed_end_failures(job, r)
    else:
        want = 2 if expected else 0
        if run.returncode != want:
            failures.append("exit %d, expected %d" % (run.returncode, want))
        for word, lines in expected.items():
            if "'%s'" % word not in run.stderr:
                failures.append("strict message does not name '%s' (lines %s)" % (word, lines))
            elif "%s:%d:" % (job, lines[0]) not in run.stderr:
                failures.append("strict message does not give %s's first line %d" % (word, lines[0]))
    if failures:
        print("stdout:\n" + run.stdout[-3000:] + "\nstderr:\n" + run.stderr[-3000:])
        print("\n".join(failures))
        return 1
    print("1 passed, 0 failed: %s on %s (%s), %d ignored words" % (os.path.basename(job), arch, policy, len(expected)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
