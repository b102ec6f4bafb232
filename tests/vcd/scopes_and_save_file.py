#!/usr/bin/env python3
"""Each architecture's VCD has one scope per hardware block under the top scope `cncsim`, and its gtkwave save file
(FILE.vcd -> FILE.gtkw) names only signals the VCD has, every one of them, grouped by block, the carriage's
positions as analog traces.

The blocks expected are the hardware's (docs/architectures.md), written here, not read from the code:
- every XY architecture drives two DRV8825 (driver_x, driver_y: STEP, DIR, nENBL), the laser head and the carriage
  (its real-valued position per axis);
- fpga-uart: the CP2102 <-> FPGA UART lines (link) and the FPGA's own nets (busy and the strobes);
- atmega: the CP2102 <-> ATmega328P UART lines (link); the MCU's pins are the drivers' and the laser's;
- spi-fpga: the SPI wires between the host and the FPGA (link; asked for here: they are traced on request);
- ideal: no link, no controller chip: the machine alone;
- lathe-sync: the ATmega16's pins, grouped by the part at their other end: the L298, the two encoders (the motor's
  disc; the spindle's disc and index), the limit switch, the keypad and the LCD.
For the XY architectures the save file's marker is the first STEP rising edge in the VCD, within the half tick
an unclocked edge is rounded by (the job's first move starts there), and its view starts before it; gtkwave counts time in the timescale's unit, ps at 100 ps.

Usage: scopes_and_save_file.py CNCSIM XY_SCENARIO LATHE_SCENARIO WORKDIR ARCHITECTURE...
"""
import os
import subprocess
import sys

from vcd_tools import fail

DRIVERS = [("driver_x", ["step_x", "dir_x", "n_enbl_x"]), ("driver_y", ["step_y", "dir_y", "n_enbl_y"]),
           ("laser", ["laser"])]
CARRIAGE = [("carriage", ["carriage_x_mm", "carriage_y_mm"])]
EXPECTED = {
    "fpga-uart": DRIVERS + [("link", ["uart_rx", "uart_tx"]),
                            ("fpga", ["busy", "pkt_valid", "cfg_valid", "rx_valid", "ack"])] + CARRIAGE,
    "atmega": DRIVERS + [("link", ["uart_rx", "uart_tx"])] + CARRIAGE,
    "spi-fpga": DRIVERS + [("link", ["sclk", "mosi", "miso", "ss"])] + CARRIAGE,
    "ideal": DRIVERS + CARRIAGE,
    "lathe-sync": [("l298", ["oc1a_ena_pd5", "dir1_in1_pd0", "dir2_in2_pd1"]),
                   ("motor_encoder", ["int0_motor_pd2"]),
                   ("spindle_encoder", ["int1_spindle_pd3", "index_pd6"]),
                   ("limit_switch", ["limit_pd7"]),
                   ("keypad", ["col1_pb7", "col2_pb6", "col3_pb5", "col4_pb4",
                               "row1_pb3", "row2_pb2", "row3_pb1", "row4_pb0"]),
                   ("lcd", ["lcd_rs_pa4", "lcd_rw_pa5", "lcd_e_pa6", "lcd_d4_pa0", "lcd_d5_pa1", "lcd_d6_pa2",
                            "lcd_d7_pa3"])],
}
# gtkwave 3.3's trace flags (src/analyzer.h TraceEntFlagBits).
GRP_BEGIN, GRP_END = 1 << 23, 1 << 24
ANALOG_STEP, ANALOG_INTERPOLATED = 1 << 15, 1 << 16


def read_vcd(path):
    """(blocks [(scope, [names])] under the top scope, {dotted path: (kind, id)}, first rising time per id)."""
    scopes, blocks, variables, rises = [], [], {}, {}
    with open(path) as f:
        header, in_dumpvars = True, False
        tick = 0
        for line in f:
            words = line.split()
            if not words:
                continue
            if header:
                if words[0] == "$scope":
                    scopes.append(words[2])
                    if len(scopes) == 2:
                        blocks.append((words[2], []))
                elif words[0] == "$upscope":
                    scopes.pop()
                elif words[0] == "$var":
                    if len(scopes) != 2:
                        fail("%s: $var %s is not in a block's scope (%s)" % (path, words[4], ".".join(scopes)))
                    blocks[-1][1].append(words[4])
                    variables[".".join(scopes + [words[4]])] = (words[1], words[3])
                elif words[0] == "$enddefinitions":
                    header = False
                continue
            if words[0] == "$dumpvars":
                in_dumpvars = True
            elif words[0] == "$end":
                in_dumpvars = False
            elif words[0].startswith("#"):
                tick = int(words[0][1:])
            elif words[0][0] == "1" and not in_dumpvars and words[0][1:] not in rises:
                rises[words[0][1:]] = tick
    if scopes or not blocks:
        fail("%s: the scopes are not closed, or there are none" % path)
    return blocks, variables, rises


def read_gtkw(path):
    """([(flags, trace name)], {key: value}, zoom line values); groups as ("group", name) entries."""
    traces, keys, zoom, flags = [], {}, None, 0
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("["):
                key, _, value = line.partition("] ")
                keys[key + "]"] = value
            elif line.startswith("*"):
                zoom = [float(v) for v in line[1:].split()]
            elif line.startswith("@"):
                flags = int(line[1:], 16)
            elif line.startswith("-"):
                if flags & (GRP_BEGIN | GRP_END):
                    traces.append(("begin" if flags & GRP_BEGIN else "end", line[1:]))
            elif line:
                traces.append((flags, line))
    return traces, keys, zoom


def check(arch, vcd, gtkw):
    blocks, variables, rises = read_vcd(vcd)
    if blocks != EXPECTED[arch]:
        fail("%s: the VCD's blocks are\n  %s\nexpected\n  %s" % (arch, blocks, EXPECTED[arch]))
    traces, keys, zoom = read_gtkw(gtkw)
    if keys.get("[dumpfile]") != '"%s"' % os.path.abspath(vcd):
        fail("%s: [dumpfile] %s, not the VCD %s" % (arch, keys.get("[dumpfile]"), os.path.abspath(vcd)))
    group, shown, groups = None, [], []
    for flags, name in traces:
        if flags == "begin":
            group = name
            groups.append(name)
        elif flags == "end":
            group = None
        else:
            if name not in variables:
                fail("%s: the save file names %s, which the VCD does not have" % (arch, name))
            if group is None or name.split(".")[1] != group:
                fail("%s: %s is not in its block's group (in %s)" % (arch, name, group))
            analog = flags & (ANALOG_STEP | ANALOG_INTERPOLATED)
            if bool(analog) != (variables[name][0] == "real"):
                fail("%s: %s (%s) has flags %x" % (arch, name, variables[name][0], flags))
            shown.append(name)
    if sorted(shown) != sorted(variables):
        fail("%s: the save file shows %s, the VCD has %s" % (arch, sorted(shown), sorted(variables)))
    if groups != [b for b, _ in blocks]:
        fail("%s: groups %s, blocks %s" % (arch, groups, [b for b, _ in blocks]))
    if arch != "lathe-sync":
        step_ids = [variables["cncsim.%s.%s" % (d, s)][1] for d, s in (("driver_x", "step_x"), ("driver_y", "step_y"))]
        first_rise_ps = min(rises[i] for i in step_ids if i in rises) * 100  # 100 ps ticks
        # The ideal controller's edges fall at any ps and the VCD has them at the nearest 100 ps tick.
        if zoom is None or abs(zoom[1] - first_rise_ps) > 50:
            fail("%s: marker %s, the first STEP rise is at %d ps" % (arch, zoom and zoom[1], first_rise_ps))
        if not int(keys["[timestart]"]) < first_rise_ps:
            fail("%s: the view starts at %s ps, not before the first STEP rise" % (arch, keys["[timestart]"]))
    print("%s: %s; the save file shows all %d signals" %
          (arch, " ".join("%s(%d)" % (b, len(n)) for b, n in blocks), len(shown)))


def main():
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    cncsim, xy_scenario, lathe_scenario, workdir = sys.argv[1:5]
    os.makedirs(workdir, exist_ok=True)
    for arch in sys.argv[5:]:
        vcd = os.path.join(workdir, arch + ".vcd")
        gtkw = os.path.join(workdir, arch + ".gtkw")
        for stale in (vcd, gtkw):
            if os.path.exists(stale):
                os.remove(stale)
        if arch == "lathe-sync":
            cmd = [cncsim, "run", lathe_scenario, "--set", "lathe.passes=1", "--set", "lathe.length_mm=1",
                   "--set", "clock.ideal=true"]
        else:
            cmd = [cncsim, "run", xy_scenario, "--set", "scenario.architecture=" + arch, "--set", "clock.ideal=true"]
        cmd += ["--vcd", vcd, "--progress", "off"]
        if arch == "spi-fpga":
            cmd += ["--set", "spi.trace_wires=true"]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            fail("%s: exit %d\n%s" % (" ".join(cmd), run.returncode, run.stderr))
        if not os.path.exists(gtkw):
            fail("%s: no save file %s beside the VCD" % (arch, gtkw))
        check(arch, vcd, gtkw)


if __name__ == "__main__":
    main()
