#!/usr/bin/env python3
"""`cncsim analyze` of a run's own VCD gives the run's pulse figures: the VCD holds the edges the run measured, and
analyze splits pulse runs where the period changes, which for these jobs is where the run's moves change.

pulses: per axis the STEP edges, the pulse runs (edges, mean period, jitter, TIE of each), the axis's worst jitter
and TIE, and every DRV8825 timing rule (checked edges, minimum, violations) equal the run's report.
commanded: the same, with analyze given the run's report (--commanded): its runs split where the command changed
(spi-fpga: the rate words of the servo periods, with their commanded rates, so the rate errors agree too; the
others: the moves).
edges: the STEP edges, the net steps and the driver rules only.
Extra arguments go to analyze (the atmega run counts STEP edges only while nENBL is low: --enable n_enbl_x:active-low).

Usage: analyze_vs_run.py CNCSIM SCENARIO WORKDIR pulses|commanded|edges ANALYZE_OPTIONS...
"""
import math
import os
import sys

from vcd_tools import analyze, expect_equal, fail, run_cncsim

RUN_FIELDS = ("edges", "t_first_ps", "t_last_ps", "period_mean_ns", "jitter_pp_ns", "jitter_std_ns",
              "tie_max_ns", "tie_rms_ns")
AXIS_PULSE_FIELDS = ("runs_count", "jitter_pp_max_ns", "jitter_std_max_ns", "tie_max_ns", "tie_rms_max_ns")


def same(a, b):
    if isinstance(a, float) or isinstance(b, float):
        return a is not None and b is not None and math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-9)
    return a == b


def expect_same(what, got, expected):
    if not same(got, expected):
        fail("%s: analyze %s, run %s" % (what, got, expected))


def compare_axis(mode, run_axis, analyzed, run_fields):
    name = run_axis["axis"]
    for field in ("rising_edges", "falling_edges"):
        expect_same("%s %s" % (name, field), analyzed[field], run_axis[field])
    for rule, check in run_axis["driver_timing"].items():
        if isinstance(check, dict):
            for field in ("checked", "min_ns", "violations"):
                expect_same("%s %s %s" % (name, rule, field), analyzed["driver_timing"][rule][field], check[field])
    if mode == "edges":
        expect_same("%s net steps" % name, analyzed["net_steps"], run_axis["net_steps"])
        return
    for field in AXIS_PULSE_FIELDS:
        expect_same("%s %s" % (name, field), analyzed[field], run_axis[field])
    for k, (got, expected) in enumerate(zip(analyzed["runs"], run_axis["runs"])):
        for field in run_fields:
            expect_same("%s run %d %s" % (name, k, field), got[field], expected[field])


def main():
    if len(sys.argv) < 5 or sys.argv[4] not in ("pulses", "commanded", "edges"):
        sys.exit(__doc__)
    cncsim, scenario, workdir, mode = sys.argv[1:5]
    options = sys.argv[5:]
    vcd, report = run_cncsim(cncsim, workdir, "run", scenario)
    run_fields = RUN_FIELDS
    if mode == "commanded":
        options += ["--commanded", os.path.join(workdir, "run.json")]
        if "commanded_rates" in report:
            run_fields += ("rate_commanded_steps_per_s", "rate_error_pct")
    analyzed = analyze(cncsim, vcd, os.path.join(workdir, "analyze.json"), *options)
    run_axes = report["metrics"]["axes"]
    expect_equal("axes", len(analyzed["axes"]), len(run_axes))
    for run_axis, analyzed_axis in zip(run_axes, analyzed["axes"]):
        compare_axis(mode, run_axis, analyzed_axis, run_fields)
        print("%s (%s): %d STEP edges, %s" % (run_axis["axis"], analyzed_axis["axis"], run_axis["rising_edges"],
                                              "%d pulse runs" % run_axis["runs_count"] if mode != "edges"
                                              else "net %d steps" % run_axis["net_steps"]))
    print("analyze of the run's VCD agrees with the run (%s)" % mode)


if __name__ == "__main__":
    main()
