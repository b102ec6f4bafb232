#!/usr/bin/env python3
"""Synthesis of our seed 000 RTL (models/fpga/rtl) for the low-cost FPGAs seed 000 §7.2 names: usage RTL_DIR WORKDIR.

For each variant of step_gen's arithmetic (DIVIDER 0: the seed's single-clock division and product; 1: one bit per
clock during DIR_WAIT), Yosys synthesises `top` for the Lattice iCE40UP5K (synth_ice40) and the Gowin GW1N-9
(synth_gowin) and nextpnr-ice40 places and routes the iCE40 build on the UP5K (SG48 package) with a 50 MHz
constraint. Fails when a synthesis fails or infers a latch; prints the cells, the iCE40 logic cells used of 5,280
and the maximum clock nextpnr finds, and whether it meets 50 MHz (a placement that does not fit is reported, not
failed: the seed's single-clock arithmetic is not expected to fit).
"""
import json
import os
import re
import subprocess
import sys

SOURCES = ["top.v", "uart_rx.v", "uart_tx.v", "packet_decoder.v", "step_gen.v", "period_divider.v", "laser_ctrl.v"]
UP5K_LOGIC_CELLS = 5280  # iCE40 UltraPlus family data sheet, table 1-1: iCE40UP5K


def yosys(rtl_dir, work, divider, synth, out_json):
    log = os.path.join(work, "yosys_%s_divider%d.log" % (synth, divider))
    script = "read_verilog %s; chparam -set DIVIDER %d top; %s -top top -json %s; stat" % (
        " ".join(os.path.join(rtl_dir, s) for s in SOURCES), divider, synth, out_json)
    run = subprocess.run(["yosys", "-p", script], capture_output=True, text=True)
    with open(log, "w") as f:
        f.write(run.stdout + run.stderr)
    if run.returncode != 0:
        return None, "yosys %s failed (%s)" % (synth, log)
    text = run.stdout
    stat = text[text.rfind("Number of cells:"):]
    cells = {m.group(1): int(m.group(2)) for m in re.finditer(r"^\s+(\S+)\s+(\d+)$", stat, re.M)}
    # proc_dlatch says "Latch inferred for signal" for each; a latch left in the netlist is a *LATCH* cell.
    if "Latch inferred for signal" in text or any("LATCH" in cell.upper() for cell in cells):
        return None, "%s: a latch was inferred (%s)" % (synth, log)
    return cells, None


def nextpnr(work, divider, in_json):
    report = os.path.join(work, "nextpnr_divider%d.json" % divider)
    log = os.path.join(work, "nextpnr_divider%d.log" % divider)
    run = subprocess.run(["nextpnr-ice40", "--up5k", "--package", "sg48", "--json", in_json, "--freq", "50",
                          "--report", report], capture_output=True, text=True)
    with open(log, "w") as f:
        f.write(run.stdout + run.stderr)
    if not os.path.exists(report):
        fits = re.search(r"ERROR: (.*)", run.stderr)
        return "does not place: %s" % (fits.group(1) if fits else "see " + log)
    with open(report) as f:
        r = json.load(f)
    lc = r["utilization"]["ICESTORM_LC"]
    fmax = min(c["achieved"] for c in r["fmax"].values())
    return "%d of %d logic cells (%.0f %%), max clock %.1f MHz: %s 50 MHz" % (
        lc["used"], lc["available"], 100.0 * lc["used"] / lc["available"], fmax,
        "meets" if fmax >= 50.0 else "misses")


def main():
    rtl_dir, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    failures = []
    for divider in (1, 0):
        for synth, luts in (("synth_ice40", "SB_LUT4"), ("synth_gowin", "LUT4")):
            out_json = os.path.join(work, "top_%s_divider%d.json" % (synth, divider))
            cells, error = yosys(rtl_dir, work, divider, synth, out_json)
            if error:
                failures.append(error)
                continue
            lut_count = sum(n for k, n in cells.items() if k.startswith(luts[:-1]) and "LUT" in k)
            ffs = sum(n for k, n in cells.items() if "DFF" in k)
            print("DIVIDER %d, %s: %d LUTs, %d flip-flops, %d cells" % (divider, synth, lut_count, ffs,
                                                                         sum(cells.values())))
            if synth == "synth_ice40":
                if divider == 0 and lut_count > UP5K_LOGIC_CELLS:
                    print("  iCE40UP5K: %d LUTs of %d: does not fit" % (lut_count, UP5K_LOGIC_CELLS))
                else:
                    print("  iCE40UP5K, nextpnr: " + nextpnr(work, divider, out_json))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
