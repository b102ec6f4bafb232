#!/usr/bin/env python3
"""The carriage position in the VCD: carriage_x_mm / carriage_y_mm are 64-bit real variables in the
syntax gtkwave reads (IEEE 1364 §18.2: "$var real 64 <id> <name> $end", values "r<number> <id>", written %.16g),
read here by this file's own parser, not cncsim's.

Ideal mechanics on the fpga-uart square (scenarios/fpga-uart/square_20mm.toml, seed 000's machine: 1.8 deg,
1/32 microsteps, GT2 20-tooth pulley = 40 mm per revolution / 6400 microsteps = 160 steps/mm, the job starting
at the machine origin 0,0): after every STEP_X rising edge, and so at the last one, the VCD's carriage_x_mm is the
signed count of STEP_X edges so far (DIR_X giving the sign) / 160 mm. The sign convention is taken from the job:
its first move goes to +X (G0 X10), and it reaches X30 (its square's far side) and ends at X0.
A window (trace.from_s/to_s) with trace.signals naming carriage_x_mm holds only the signals named (by name or as
BLOCK.NAME), starts with the
position the full trace has at trace.from_s, and sigrok-cli reads it (its VCD input skips real variables).
Dynamic mechanics: the trace ends within a full step (32 microsteps = 0.2 mm) of the commanded X0.

Usage: carriage_position.py CNCSIM SCENARIO WORKDIR
"""
import math
import os
import re
import subprocess
import sys

from vcd_tools import DOWNSAMPLE_TO_10MHZ, fail, sigrok_cli

STEPS_PER_MM = 160.0  # see above
WINDOW_FROM_S, WINDOW_TO_S = 1.0, 2.0
TIMESCALE_PS = 100  # trace.timescale default, 100 ps


def parse_vcd(path):
    """(vars {name: (kind, id)}, changes [(tick, id, value)], with $dumpvars at the first tick)."""
    with open(path) as f:
        text = f.read()
    head, _, body = text.partition("$enddefinitions $end")
    variables = {}
    for kind, size, ident, name in re.findall(r"\$var\s+(\w+)\s+(\d+)\s+(\S+)\s+(\S+)\s+\$end", head):
        if kind == "real" and size != "64":
            fail("%s: real variable %s is %s bits, not 64" % (path, name, size))
        variables[name] = (kind, ident)
    changes = []
    tick = None
    for line in body.split("\n"):
        line = line.strip()
        if not line or line in ("$dumpvars", "$end"):
            continue
        if line.startswith("#"):
            tick = int(line[1:])
        elif line[0] in "rR":
            number, ident = line[1:].split()
            value = float(number)
            if "%.16g" % value != number:
                fail("%s: real value %r is not written %%.16g" % (path, line))
            changes.append((tick, ident, value))
        elif line[0] in "01xz":
            changes.append((tick, line[1:], line[0] == "1"))
        else:
            fail("%s: unexpected line %r" % (path, line))
    return variables, changes


def run(cncsim, scenario, vcd, *sets):
    cmd = [cncsim, "run", scenario, "--vcd", vcd, "--progress", "off", "--set", "clock.ideal=true"]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: exit %d\n%s" % (" ".join(cmd), r.returncode, r.stderr))
    return parse_vcd(vcd)


def x_after_each_step(variables, changes):
    """Per STEP_X rising edge: (tick, signed edge count, last carriage_x_mm written before the next edge)."""
    step, dir_, pos = (variables[n][1] for n in ("step_x", "dir_x", "carriage_x_mm"))
    dir_level, count, x, edges = False, 0, None, []
    for tick, ident, value in changes:
        if ident == dir_:
            dir_level = value
        elif ident == step and value:
            if edges:
                edges[-1][2] = x
            count += 1 if dir_level else -1
            edges.append([tick, count, None])
        elif ident == pos:
            x = value
    if not edges:
        fail("no STEP_X edge in the trace")
    edges[-1][2] = x
    return edges


def check_ideal(edges):
    sign = 1 if edges[0][1] > 0 else -1  # the first move is to +X
    for tick, count, x in edges:
        expected = sign * count / STEPS_PER_MM
        if x is None or not math.isclose(x, expected, abs_tol=1e-9):
            fail("after the STEP_X edge at tick %d (%d steps): carriage_x_mm %s, expected %.9f" %
                 (tick, sign * count, x, expected))
    far = max(x for _, _, x in edges)
    if not math.isclose(far, 30.0, abs_tol=1e-9) or not math.isclose(edges[-1][2], 0.0, abs_tol=1e-9):
        fail("carriage_x_mm reaches %s and ends at %s, the job's X30 and X0" % (far, edges[-1][2]))
    print("ideal: %d STEP_X edges, carriage_x_mm = steps / 160 after each; last %s mm" % (len(edges), edges[-1][2]))


def value_at(changes, ident, tick):
    value = None
    for t, i, v in changes:
        if t > tick:
            break
        if i == ident:
            value = v
    return value


def check_window(cncsim, scenario, workdir, full_vars, full_changes):
    vcd = os.path.join(workdir, "window.vcd")
    variables, changes = run(cncsim, scenario, vcd, "mechanics.model=ideal",
                             'trace.signals=["driver_x.step_x", "dir_x", "carriage.carriage_x_mm"]',
                             "trace.from_s=%g" % WINDOW_FROM_S, "trace.to_s=%g" % WINDOW_TO_S)
    if sorted(variables) != ["carriage_x_mm", "dir_x", "step_x"]:
        fail("window: the VCD holds %s, not the signals named" % sorted(variables))
    start_tick = int(WINDOW_FROM_S * 1e12) // TIMESCALE_PS
    first = changes[0][0]
    if first != start_tick:
        fail("window: starts at tick %s, expected %d" % (first, start_tick))
    got = value_at(changes, variables["carriage_x_mm"][1], start_tick)
    # The full trace's value just before the window (a change at the window's first tick is in both).
    expected = value_at(full_changes, full_vars["carriage_x_mm"][1], start_tick)
    if got != expected:
        fail("window: carriage_x_mm %s at %g s, the full trace has %s" % (got, WINDOW_FROM_S, expected))
    sigrok_cli("-i", vcd, "-I", "vcd:downsample=%d" % DOWNSAMPLE_TO_10MHZ, "-P", "timing:data=step_x")
    print("window %g..%g s: carriage_x_mm starts at %s mm as in the full trace; sigrok-cli reads it" %
          (WINDOW_FROM_S, WINDOW_TO_S, got))


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    cncsim, scenario, workdir = sys.argv[1:]
    os.makedirs(workdir, exist_ok=True)
    variables, changes = run(cncsim, scenario, os.path.join(workdir, "ideal.vcd"), "mechanics.model=ideal")
    for name in ("carriage_x_mm", "carriage_y_mm"):
        if variables.get(name, ("",))[0] != "real":
            fail("ideal: no real variable %s in %s" % (name, sorted(variables)))
    check_ideal(x_after_each_step(variables, changes))
    check_window(cncsim, scenario, workdir, variables, changes)

    variables, changes = run(cncsim, scenario, os.path.join(workdir, "dynamic.vcd"), "mechanics.model=dynamic")
    last = value_at(changes, variables["carriage_x_mm"][1], changes[-1][0] if changes else 0)
    if last is None or abs(last) >= 32 / STEPS_PER_MM:
        fail("dynamic: carriage_x_mm ends at %s mm, more than a full step from the commanded X0" % last)
    print("dynamic: carriage_x_mm ends at %s mm" % last)


if __name__ == "__main__":
    main()
