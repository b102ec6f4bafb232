"""Runs `cncsim run` with a JSON report, and the checks, for the Python tests that read a run's figures."""
import json
import math
import os
import re
import subprocess
import sys


def run_report(cncsim, scenario, tmp, tag, sets=(), extra=()):
    """(report as a dict, summary text) of `cncsim run SCENARIO --set S... EXTRA...`; the report goes to TMP/TAG.json.
    A run that fails raises CalledProcessError with its message."""
    report = os.path.join(tmp, tag + ".json")
    cmd = [cncsim, "run", scenario, "--progress", "off", "--report", report]
    for s in sets:
        cmd += ["--set", s]
    out = subprocess.run(cmd + list(extra), check=True, capture_output=True, text=True).stdout
    with open(report) as f:
        return json.load(f), out


def check(cond, what):
    """Ends the test with FAIL: WHAT unless COND."""
    if not cond:
        print("FAIL:", what)
        sys.exit(1)


def args_and_workdir():
    """(cncsim, source dir, work dir) of a test called as TEST CNCSIM SOURCE_DIR WORKDIR; the work dir made."""
    cncsim, source, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    return cncsim, source, work


def check_bad_input(name, r, said, unwritten):
    """The command (a finished subprocess.run with text output) exited 2, its stderr says each of SAID, and the file
    UNWRITTEN does not exist; prints the message."""
    check(r.returncode == 2, "%s: exit %d, not 2: %s" % (name, r.returncode, r.stderr))
    for what in said:
        check(what in r.stderr, "%s: the message does not say '%s': %s" % (name, what, r.stderr))
    check(not os.path.exists(unwritten), "%s: %s written" % (name, unwritten))
    print(name + ":", r.stderr.strip().splitlines()[-1])


def dominant_speeds_mm_per_s(job, feed_mm_per_s):
    """The dominant axis' speed of each G0/G1 move of JOB (X/Y words, absolute) run at FEED_MM_PER_S along the path:
    the packet's feed is the dominant axis' feed (seed 000 §3.4.5)."""
    at = {"X": 0.0, "Y": 0.0}
    speeds = []
    with open(job) as f:
        for line in f:
            code = line.split("(")[0]
            if not re.match(r"\s*G[01]\b", code):
                continue
            to = dict(at)
            for axis, value in re.findall(r"([XY])(-?[0-9.]+)", code):
                to[axis] = float(value)
            dx, dy = abs(to["X"] - at["X"]), abs(to["Y"] - at["Y"])
            at = to
            if dx == 0 and dy == 0:
                continue
            speeds.append(feed_mm_per_s * max(dx, dy) / math.hypot(dx, dy))
    return speeds


def lost_full_steps(report):
    """(X, Y) full steps an fpga-uart run's dynamic mechanics lost."""
    mech = report["fpga-uart"]["mechanics"]
    return mech["x"]["lost_full_steps"], mech["y"]["lost_full_steps"]


def check_ramped_run(report, what, full_steps_per_mm):
    """An fpga-uart run with an FPGA ramp (WHAT names it): no full step lost, no STEP period under the DRV8825's
    4 us, each cruise at the packet's rate within 0.1 % (measured against the ramp's own commanded motion), every step
    commanded stepped, and the tool within half a full step of the programmed end."""
    check(lost_full_steps(report) == (0, 0), "with the %s X and Y lost %d and %d full steps"
          % ((what,) + lost_full_steps(report)))
    for axis in report["metrics"]["axes"]:
        rate = axis["driver_timing"]["rate"]
        check(rate["violations"] == 0, "%s: %d STEP periods under the DRV8825's 4 us" % (axis["axis"],
                                                                                            rate["violations"]))
        check(abs(axis["rate_error_worst_pct"]) < 0.1,
              "%s: rate error %.4f %% in the cruise" % (axis["axis"], axis["rate_error_worst_pct"]))
    executed = report["metrics"]["moves"]
    for axis in ("x", "y"):
        check(executed["steps_emitted"][axis] == executed["steps_commanded"][axis],
              "with the %s %s stepped %s for %s commanded" % (what, axis, executed["steps_emitted"][axis],
                                                             executed["steps_commanded"][axis]))
    end_um = report["metrics"]["path"]["job_end_um"]
    check(end_um < 1000.0 / full_steps_per_mm / 2, "with the %s the tool ends %.1f um off the programmed point"
          % (what, end_um))
    return end_um


def check_ramp_cost(ramped, seed, predicted_s, moves, start_step_s, what):
    """The motion time the ramped run RAMPED adds over SEED's is PREDICTED_S (computed by the test for MOVES moves),
    within a step at the start speed (START_STEP_S) per move; returns the measured cost."""
    measured = ramped["metrics"]["job"]["motion_time_s"] - seed["metrics"]["job"]["motion_time_s"]
    check(abs(measured - predicted_s) < moves * start_step_s,
          "the %s cost %.4f s of motion, %.4f s predicted" % (what, measured, predicted_s))
    return measured
