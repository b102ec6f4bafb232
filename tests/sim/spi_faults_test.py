#!/usr/bin/env python3
"""Bit errors on the SPI wires of spi-fpga (faults.spi_ber): usage CNCSIM SOURCE_DIR WORKDIR.

- a BER that hits nothing (1e-12) leaves every figure of the run as it is without faults;
- the frames the FPGA's own command check refused (its slave's count of frames not accepted) are exactly the frames
  whose command byte the draws changed (the master's count, from the bits it inverted): two counts that share no
  code;
- the frames run with changed rate words leave the tool off the programmed point at the job's end by more than a
  step, as the metrics measure it from the STEP edges; the same seed gives the same report, byte for byte.
"""
import filecmp
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import args_and_workdir, check, run_report  # noqa: E402

STEP_UM = 1000.0 / 160.0  # the scenarios' machine: 160 steps/mm


def main():
    cncsim, source, work = args_and_workdir()
    square = os.path.join(source, "scenarios", "spi-fpga", "square_20mm.toml")
    clean, _ = run_report(cncsim, square, work, "clean")
    quiet, _ = run_report(cncsim, square, work, "quiet", ["faults.spi_ber=1e-12"])
    check(quiet["spi-fpga"]["faults"]["to_fpga"]["frames_hit"] == 0, "a frame hit at BER 1e-12")
    check(quiet["metrics"] == clean["metrics"], "a BER that hits nothing changed the metrics")

    sets = ["faults.spi_ber=1e-4", "faults.seed=2"]
    rep, _ = run_report(cncsim, square, work, "ber", sets)
    f = rep["spi-fpga"]["faults"]["to_fpga"]
    check(f["frames_hit"] > 0 and f["command_byte_hit"] > 0, "BER 1e-4 seed 2: no frame or command byte hit")
    check(f["refused_by_the_command_check"] == f["command_byte_hit"],
          "the FPGA refused %d frames, %d had their command byte changed" % (f["refused_by_the_command_check"],
                                                                           f["command_byte_hit"]))
    check(f["ran_changed"] > 0, "no frame ran changed")
    end_um = rep["metrics"]["path"]["job_end_um"]
    check(end_um > STEP_UM, "%d frames ran changed and the tool ends %.3f um off" % (f["ran_changed"], end_um))
    print("BER 1e-4: %d of %d frames hit, %d refused, %d run changed, the tool ends %.1f um off"
          % (f["frames_hit"], f["frames"], f["refused_by_the_command_check"], f["ran_changed"], end_um))
    run_report(cncsim, square, work, "ber_again", sets)
    check(filecmp.cmp(os.path.join(work, "ber.json"), os.path.join(work, "ber_again.json"), shallow=False),
          "the same seed gave another report")
    print("PASS")


if __name__ == "__main__":
    main()
