#!/usr/bin/env python3
"""STEP pulses lost on the DRV8825s' inputs (faults.step_loss_rate): usage CNCSIM SOURCE_DIR WORKDIR.

The 20 mm square with ideal mechanics, 1 % of the pulses lost, on fpga-uart and spi-fpga: on each axis the pulses lost
are within five standard deviations of 1 % of the rising edges on the pin (the metrics count those from the pins, the
drivers count their losses); the tool's end, measured by the metrics from the carriage, is exactly where the net lost
pulses put it (160 steps/mm); the same seed gives the same losses, another seed others; without the fault the report
has no step_faults section and the tool ends on the point.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import args_and_workdir, check, run_report  # noqa: E402

RATE = 0.01


def main():
    cncsim, source, work = args_and_workdir()
    square = os.path.join(source, "scenarios", "fpga-uart", "square_20mm.toml")
    for arch in ("fpga-uart", "spi-fpga"):
        sets = ["scenario.architecture=" + arch, "mechanics.model=ideal"]
        r, _ = run_report(cncsim, square, work, arch, sets=sets + ["faults.step_loss_rate=%g" % RATE])
        f = r[arch]["step_faults"]
        for k, axis in enumerate(r["metrics"]["axes"]):
            n = axis["rising_edges"]
            sd = math.sqrt(n * RATE * (1 - RATE))
            check(abs(f["lost"][k] - n * RATE) <= 5 * sd,
                  "%s %s: %d of %d pulses lost at a rate of %g" % (arch, axis["axis"], f["lost"][k], n, RATE))
        off_um = 1000.0 * math.hypot(f["lost_net_steps"][0], f["lost_net_steps"][1]) / 160.0
        end_um = r["metrics"]["path"]["job_end_um"]
        check(off_um > 0.0, "%s: the losses cancelled out; pick a rate or job where they do not" % arch)
        check(abs(end_um - off_um) < 0.01, "%s: the tool ends %.3f um off, the lost pulses make %.3f um"
              % (arch, end_um, off_um))
        again, _ = run_report(cncsim, square, work, arch + "_again", sets=sets + ["faults.step_loss_rate=%g" % RATE])
        check(again[arch]["step_faults"] == f, "%s: the same seed lost other pulses" % arch)
        other, _ = run_report(cncsim, square, work, arch + "_seed2",
                              sets=sets + ["faults.step_loss_rate=%g" % RATE, "faults.seed=2"])
        check(other[arch]["step_faults"]["lost"] != f["lost"], "%s: another seed lost the same pulses" % arch)
        clean, _ = run_report(cncsim, square, work, arch + "_clean", sets=sets)
        check("step_faults" not in clean[arch] and clean["metrics"]["path"]["job_end_um"] == 0.0,
              "%s: without the fault a pulse was lost" % arch)
        print("%s: lost %s (net %s): tool %.3f um off, measured %.3f um" % (arch, f["lost"], f["lost_net_steps"], off_um,
                                                                           end_um))
    print("PASS")


if __name__ == "__main__":
    main()
