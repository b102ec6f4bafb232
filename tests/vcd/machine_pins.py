#!/usr/bin/env python3
"""Every architecture's VCD has the same machine pins, declared first and in the same order (docs/vcd.md: per
DRV8825 its STEP, DIR and nENBL, the laser head's input), then its own link pins, and last the carriage position
per axis (real-valued): a trace of one architecture can be analysed with the options of another. spi-fpga's SPI wires
toggle bit by bit, so they are traced only when asked for (`spi.trace_wires = true` or named in `trace.signals`):
asked for here. The ideal controller has no link: the machine's pins alone.

Usage: machine_pins.py CNCSIM SCENARIO WORKDIR ARCHITECTURE...
"""
import os
import subprocess
import sys

from vcd_tools import fail

MACHINE_PINS = ["step_x", "dir_x", "n_enbl_x", "step_y", "dir_y", "n_enbl_y", "laser"]
CARRIAGE = ["carriage_x_mm", "carriage_y_mm"]
LINK_PINS = {"fpga-uart": {"uart_rx", "uart_tx"}, "atmega": {"uart_rx", "uart_tx"},
             "spi-fpga": {"sclk", "mosi", "miso", "ss"}, "ideal": set()}


def declared(vcd):
    """The names of the $var declarations of the VCD's header, in order."""
    names = []
    with open(vcd) as f:
        for line in f:
            if line.startswith("$enddefinitions"):
                return names
            words = line.split()
            if words[:1] == ["$var"]:
                names.append(words[4])
    fail("%s: no $enddefinitions" % vcd)


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    cncsim, scenario, workdir = sys.argv[1:4]
    os.makedirs(workdir, exist_ok=True)
    for arch in sys.argv[4:]:
        vcd = os.path.join(workdir, arch + ".vcd")
        cmd = [cncsim, "run", scenario, "--set", "scenario.architecture=" + arch, "--vcd", vcd, "--progress", "off"]
        if arch == "spi-fpga":
            cmd += ["--set", "spi.trace_wires=true"]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            fail("%s: exit %d\n%s" % (" ".join(cmd), run.returncode, run.stderr))
        names = declared(vcd)
        if names[:len(MACHINE_PINS)] != MACHINE_PINS or names[-len(CARRIAGE):] != CARRIAGE:
            fail("%s: the VCD declares %s, expected the machine pins %s first and the carriage %s last" %
                 (arch, names, MACHINE_PINS, CARRIAGE))
        missing = LINK_PINS[arch] - set(names)
        if missing:
            fail("%s: no link pin %s in %s" % (arch, sorted(missing), names))
        print("%s: %s" % (arch, " ".join(names)))


if __name__ == "__main__":
    main()
