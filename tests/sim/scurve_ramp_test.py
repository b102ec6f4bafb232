#!/usr/bin/env python3
"""The FPGA's S-curve ramp on fpga-uart (fpga.ramp = "s-curve"): usage CNCSIM SOURCE_DIR WORKDIR.

The study of scenarios/improvements/ramp_scurve_80mm_s.toml (the six-segment shape at 80 mm/s, F4800, rapids too,
with the dynamic mechanics of seed 000's machine, its X carriage 3.8 kg):
- with the S-curve no axis loses a step (the seed's step_gen loses full steps on X), every step commanded is
  stepped, no STEP comes faster than the DRV8825's 250 kHz, and the tool ends on the programmed point;
- the S-curve's cost is what a jerk-limited ramp predicts, computed here from the job file: each move's dominant
  axis goes from 5 mm/s to its speed v and back at 1000 mm/s^2 and 50,000 mm/s^3, each ramp taking
  T = dv / a + a / j (T = 2 sqrt(dv / j) when dv < a^2 / j) at the mean speed (5 + v) / 2, which adds T dv / v to
  the move; the motion time grows by that sum over the seed's, within a step at the start speed per move;
- its job time is reported against the trapezoid's and the seed's;
- a jerk the FPGA's register cannot hold (too large: its jerk phases would be shorter than the register can
  express; too small: the register would hold 0) and the S-curve on the RTL are exit 2 naming the key.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import (args_and_workdir, check, check_bad_input, check_ramp_cost,  # noqa: E402
                           check_ramped_run, dominant_speeds_mm_per_s, lost_full_steps, run_report)

FEED_MM_PER_S = 80.0      # the job's F4800 and the scenario's rapid feed
ACCEL_MM_PER_S2 = 1000.0  # machine.<axis>.max_accel_mm_per_s2's default
JERK_MM_PER_S3 = 50000.0  # machine.<axis>.max_jerk_mm_per_s3's default
START_MM_PER_S = 5.0      # fpga.ramp_start_mm_per_s's default
STEPS_PER_MM = 160        # the default machine: 1.8 deg, 1/32, GT2 20T
FULL_STEPS_PER_MM = 5     # its 200 full steps per 40 mm turn


def ramp_time_s(dv):
    a, j = ACCEL_MM_PER_S2, JERK_MM_PER_S3
    return dv / a + a / j if dv >= a * a / j else 2 * math.sqrt(dv / j)


def predicted_cost_s(job):
    """Sum over the job's G0/G1 moves of the two S-curve ramps' extra time on the dominant axis."""
    speeds = dominant_speeds_mm_per_s(job, FEED_MM_PER_S)
    return sum(ramp_time_s(v - START_MM_PER_S) * (v - START_MM_PER_S) / v for v in speeds), len(speeds)


def main():
    cncsim, source, work = args_and_workdir()
    study = os.path.join(source, "scenarios", "improvements", "ramp_scurve_80mm_s.toml")
    scurve, _ = run_report(cncsim, study, work, "s-curve")
    trapezoid, _ = run_report(cncsim, study, work, "trapezoidal", sets=['fpga.ramp="trapezoidal"'])
    seed, _ = run_report(cncsim, study, work, "seed", sets=['fpga.ramp="none"'])

    seed_x, _ = lost_full_steps(seed)
    check(seed_x > 0, "the seed's step_gen lost no step on X at 80 mm/s")
    end_um = check_ramped_run(scurve, "S-curve", FULL_STEPS_PER_MM)

    cost, moves = predicted_cost_s(os.path.join(source, "scenarios", "jobs", "six_segment_f4800.nc"))
    measured = check_ramp_cost(scurve, seed, cost, moves, 1.0 / (START_MM_PER_S * STEPS_PER_MM),
                               "S-curves (jerk-limited)")

    for name, sets, key in (("jerk too large", ["machine.x.max_jerk_mm_per_s3=1e7", "machine.y.max_jerk_mm_per_s3=1e7"],
                             "machine.x.max_jerk_mm_per_s3"),
                            ("jerk too small", ["machine.y.max_jerk_mm_per_s3=1e-5"], "machine.y.max_jerk_mm_per_s3"),
                            ("on the RTL", ['fpga.model="rtl"'], "fpga.ramp")):
        unwritten = os.path.join(work, "bad.json")
        cmd = [cncsim, "run", study, "--progress", "off", "--report", unwritten]
        for s in sets:
            cmd += ["--set", s]
        check_bad_input("s-curve, " + name, subprocess.run(cmd, capture_output=True, text=True), [key], unwritten)

    job = {name: r["metrics"]["job"]["job_time_s"] for name, r in
           (("s-curve", scurve), ("trapezoidal", trapezoid), ("seed", seed))}
    print("80 mm/s six-segment: the seed loses %d full steps on X, the S-curve none; the S-curves cost %.3f s of "
          "motion (predicted %.3f s for %d moves); job %.3f s (trapezoidal %.3f s, seed %.3f s); tool %.2f um off "
          "the end point" % (seed_x, measured, cost, moves, job["s-curve"], job["trapezoidal"], job["seed"], end_um))


if __name__ == "__main__":
    main()
