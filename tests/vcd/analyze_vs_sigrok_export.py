#!/usr/bin/env python3
"""`cncsim analyze` reads sigrok-cli's own VCD export (its "META samplerate" line, $date, $version and $comment
header, changes on the timestamp's line) and agrees with analyze of the original capture within one sample.

The run's VCD (100 ps) is resampled by sigrok-cli at 10 MHz (one sample = 100 ns) and written back with -O vcd,
keeping every channel. Per axis, both give the same STEP rising and falling edges, DIR
changes and pulse runs (edges of each); each run's mean period, the worst jitter and TIE and every DRV8825 timing
minimum differ by at most one sample.

Usage: analyze_vs_sigrok_export.py CNCSIM SCENARIO WORKDIR ANALYZE_OPTIONS...
"""
import os
import sys

from vcd_tools import DOWNSAMPLE_TO_10MHZ, analyze, expect_equal, fail, run_cncsim, sigrok_cli

SAMPLE_NS = 100.0  # 10 MHz


def within_one_sample(what, exported, original):
    if exported is None and original is None:
        return
    if exported is None or original is None or abs(exported - original) > SAMPLE_NS:
        fail("%s: export %s, original %s (more than one sample, %.0f ns, apart)" % (what, exported, original,
                                                                                   SAMPLE_NS))


def compare_axis(original, exported):
    name = original["axis"]
    for field in ("rising_edges", "falling_edges", "dir_changes", "runs_count"):
        expect_equal("%s %s" % (name, field), exported[field], original[field])
    for k, (o, e) in enumerate(zip(original["runs"], exported["runs"])):
        expect_equal("%s run %d edges" % (name, k), e["edges"], o["edges"])
        within_one_sample("%s run %d mean period [ns]" % (name, k), e["period_mean_ns"], o["period_mean_ns"])
    for field in ("jitter_pp_max_ns", "tie_max_ns"):
        within_one_sample("%s %s" % (name, field), exported[field], original[field])
    for rule, check in original["driver_timing"].items():
        if isinstance(check, dict):
            within_one_sample("%s %s minimum [ns]" % (name, rule), exported["driver_timing"][rule]["min_ns"],
                              check["min_ns"])


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    cncsim, scenario, workdir = sys.argv[1:4]
    options = sys.argv[4:]
    vcd, _ = run_cncsim(cncsim, workdir, "run", scenario)
    export = os.path.join(workdir, "sigrok_export.vcd")
    # Every channel: sigrok-cli 0.7.2's -C exports channels that are not adjacent in the file under the wrong
    # names (step_y's edges as dir_y when n_enbl_x lies between them).
    sigrok_cli("-i", vcd, "-I", "vcd:downsample=%d" % DOWNSAMPLE_TO_10MHZ, "-O", "vcd", "-o", export)
    with open(export) as f:
        if not f.readline().startswith("META samplerate: "):
            fail("%s does not start with sigrok-cli's META samplerate line: a different sigrok-cli?" % export)
    original = analyze(cncsim, vcd, os.path.join(workdir, "original.json"), *options)
    exported = analyze(cncsim, export, os.path.join(workdir, "export.json"), *options)
    for o, e in zip(original["axes"], exported["axes"]):
        compare_axis(o, e)
        print("%s: %d STEP edges in %d runs; worst jitter p-p %.1f ns in the export (a sample is %.0f ns)"
              % (o["axis"], o["rising_edges"], o["runs_count"], e["jitter_pp_max_ns"], SAMPLE_NS))
    print("analyze of sigrok-cli's export agrees with the original within one sample")


if __name__ == "__main__":
    main()
