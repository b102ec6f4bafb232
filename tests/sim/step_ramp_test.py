#!/usr/bin/env python3
"""The FPGA's trapezoidal ramp on fpga-uart (fpga.ramp): usage CNCSIM SOURCE_DIR WORKDIR.

The study of scenarios/improvements (the six-segment shape at 80 mm/s, F4800, rapids too, with the dynamic mechanics
of seed 000's machine, its X carriage 3.8 kg):
- the seed's step_gen, stepping every move at full rate from its first step, loses full steps on X;
- with the ramp no axis loses a step, no STEP comes faster than the DRV8825's 250 kHz, and the tool ends on the
  programmed point;
- the ramp's cost is what constant acceleration predicts, computed here from the job file: each move's dominant axis
  (the packet's feed is the dominant axis' feed, seed 000 §3.4.5) goes from 5 mm/s to its speed v and back at
  1000 mm/s^2, which adds (v - 5)^2 / (1000 v) to the move; the motion time grows by that sum, within a step at the
  start speed per move.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import (args_and_workdir, check, check_ramp_cost, check_ramped_run,  # noqa: E402
                           dominant_speeds_mm_per_s, lost_full_steps, run_report)

FEED_MM_PER_S = 80.0      # the job's F4800 and the scenario's rapid feed
ACCEL_MM_PER_S2 = 1000.0  # machine.<axis>.max_accel_mm_per_s2's default
START_MM_PER_S = 5.0      # fpga.ramp_start_mm_per_s's default
STEPS_PER_MM = 160        # the default machine: 1.8 deg, 1/32, GT2 20T
FULL_STEPS_PER_MM = 5     # its 200 full steps per 40 mm turn


def predicted_cost_s(job):
    """Sum over the job's G0/G1 moves of the two ramps' extra time on the dominant axis."""
    speeds = dominant_speeds_mm_per_s(job, FEED_MM_PER_S)
    return sum((v - START_MM_PER_S) ** 2 / (ACCEL_MM_PER_S2 * v) for v in speeds), len(speeds)


def main():
    cncsim, source, work = args_and_workdir()
    study = os.path.join(source, "scenarios", "improvements", "ramp_80mm_s.toml")
    ramp, _ = run_report(cncsim, study, work, "ramp")
    seed, _ = run_report(cncsim, study, work, "seed", sets=['fpga.ramp="none"'])

    seed_x, _ = lost_full_steps(seed)
    check(seed_x > 0, "the seed's step_gen lost no step on X at 80 mm/s")
    end_um = check_ramped_run(ramp, "ramp", FULL_STEPS_PER_MM)

    cost, moves = predicted_cost_s(os.path.join(source, "scenarios", "jobs", "six_segment_f4800.nc"))
    measured = check_ramp_cost(ramp, seed, cost, moves, 1.0 / (START_MM_PER_S * STEPS_PER_MM),
                               "ramps (constant acceleration)")
    print("80 mm/s six-segment: the seed loses %d full steps on X, the ramp none; the ramps cost %.3f s of motion "
          "(predicted %.3f s for %d moves), job %.3f s against %.3f s; tool %.2f um off the end point"
          % (seed_x, measured, cost, moves, ramp["metrics"]["job"]["job_time_s"], seed["metrics"]["job"]["job_time_s"],
             end_um))


if __name__ == "__main__":
    main()
