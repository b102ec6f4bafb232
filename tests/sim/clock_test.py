#!/usr/bin/env python3
"""The controllers' clocks as parts with a tolerance and jitter (docs/metrics.md, "Clocks").

  rate_shift CNCSIM ROOT: the atmega square (scenarios/atmega/square_20mm.toml) on its default clock and on an
    ideal one: every STEP period is a count of the resonator's cycles, so the worst rate error on the default clock
    is the ideal clock's times (1 + offset), the offset taken from the report's clock object (this test does the
    arithmetic, not the code under test). The offset lies within the resonator's +-0.5 % (Murata CERALOCK
    catalogue), and the UART still carries the job.
  fpga_tie CNCSIM ROOT: the fpga-uart square on its default clock: the STEP edges come from a counter on a clock
    with white phase jitter of sigma rms, cut at 4 sigma, and written at 1 ps: every TIE is within 4 sigma plus the
    fit's own error, and the TIE rms of a run is sigma within 40 %. With clock.ideal the TIE is exactly 0 and the
    summary says why in one line.
  same_seed CNCSIM ROOT: two runs of the fpga-uart square with the same seed write the same report, summary and VCD
    byte for byte; another seed draws another oscillator (another offset). The VCD's timescale is 1 ps (auto), so
    the jittered edges are written where they fell.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import run_report  # noqa: E402


def run(cncsim, scenario, tmp, tag, sets=(), vcd=False):
    return run_report(cncsim, scenario, tmp, tag, sets, ["--vcd", os.path.join(tmp, tag + ".vcd")] if vcd else [])


def check(ok, what):
    if not ok:
        print("FAIL: " + what)
        sys.exit(1)
    print("ok: " + what)


def rate_shift(cncsim, root, tmp):
    square = os.path.join(root, "scenarios/atmega/square_20mm.toml")
    real, _ = run(cncsim, square, tmp, "real")
    ideal, _ = run(cncsim, square, tmp, "ideal", ["clock.ideal=true"])
    clock = real["clock"]
    offset = clock["offset_ppm"] * 1e-6
    check(real["ok"] and ideal["ok"], "both runs carry the job")
    check(abs(clock["offset_ppm"]) <= 5000.0 and clock["tolerance_ppm"] == 5000.0,
          "offset %.3f ppm within the resonator's +-5000 ppm" % clock["offset_ppm"])
    check(clock["hz"] == round(16e6 * (1 + offset)), "the report's frequency is 16 MHz x (1 + offset)")
    check(ideal["clock"]["offset_ppm"] == 0 and ideal["clock"]["exact"], "clock.ideal: no offset")
    e_ideal = ideal["metrics"]["pulse"]["rate_error_worst_pct"] / 100.0
    e_real = real["metrics"]["pulse"]["rate_error_worst_pct"] / 100.0
    expected = (1.0 + e_ideal) * (1.0 + offset) - 1.0
    # The jitter (10 ps rms) moves a run's first and last edge: over a run of milliseconds, below 1e-8.
    check(abs(e_real - expected) < 1e-7,
          "rate error %.6f %% = ideal %.6f %% shifted by %.3f ppm (expected %.6f %%)"
          % (e_real * 100, e_ideal * 100, clock["offset_ppm"], expected * 100))
    check(abs(e_real - e_ideal) > 0.5 * abs(offset) * (1 + e_ideal), "the shift is there to see")


def fpga_tie(cncsim, root, tmp):
    square = os.path.join(root, "scenarios/fpga-uart/square_20mm.toml")
    real, _ = run(cncsim, square, tmp, "real")
    sigma_ps = real["clock"]["jitter_rms_ps"]
    check(sigma_ps == 3.0, "the DE1-SoC oscillator's default jitter is 3 ps rms")
    pulse = real["metrics"]["pulse"]
    tie_max_ps = pulse["tie_max_ns"] * 1000.0
    tie_rms_ps = pulse["tie_rms_max_ns"] * 1000.0
    # Cut at 4 sigma, rounded to 1 ps; the fitted grid of a run of >= 800 edges is off by well under a sigma.
    check(0 < tie_max_ps <= 4 * sigma_ps + 0.5 + sigma_ps, "TIE max %.1f ps within the jitter bound" % tie_max_ps)
    check(0.6 * sigma_ps <= tie_rms_ps <= 1.4 * sigma_ps, "TIE rms %.2f ps is the clock's %.1f ps" % (tie_rms_ps, sigma_ps))
    _, real_summary = run(cncsim, square, tmp, "real_again")
    check("0 by construction" not in real_summary, "no such line on the real clock")
    ideal, summary = run(cncsim, square, tmp, "ideal", ["clock.ideal=true"])
    check(ideal["metrics"]["pulse"]["tie_max_ns"] == 0, "clock.ideal: TIE 0")
    check("TIE and period jitter are 0 by construction" in summary, "the summary says why the TIE is 0")


def same_seed(cncsim, root, tmp):
    square = os.path.join(root, "scenarios/fpga-uart/square_20mm.toml")
    a, out_a = run(cncsim, square, tmp, "a", vcd=True)
    b, out_b = run(cncsim, square, tmp, "b", vcd=True)
    check(out_a.replace("a.json", "") == out_b.replace("b.json", ""), "the same summary")
    check(a == b, "the same report")
    with open(os.path.join(tmp, "a.vcd"), "rb") as fa, open(os.path.join(tmp, "b.vcd"), "rb") as fb:
        va, vb = fa.read(), fb.read()
    check(va == vb, "the same VCD, byte for byte")
    check(b"$timescale 1 ps $end" in va, "the VCD resolves the jittered edges (1 ps)")
    c, _ = run(cncsim, square, tmp, "c", ["scenario.seed=2"])
    check(c["clock"]["offset_ppm"] != a["clock"]["offset_ppm"], "another seed, another unit")


def main():
    mode, cncsim, root = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as tmp:
        {"rate_shift": rate_shift, "fpga_tie": fpga_tie, "same_seed": same_seed}[mode](cncsim, root, tmp)


if __name__ == "__main__":
    main()
