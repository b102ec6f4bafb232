#!/usr/bin/env python3
"""Synthesis of our FPGA RTL (models/fpga/rtl) for low-cost FPGAs: usage DESIGN RTL_DIR WORKDIR, DESIGN one of
fpga_uart (seed 000's `top`) or spi_fpga (seed 004's `spi_fpga_top`).

For each variant of the design (seed 000: step_gen's arithmetic, DIVIDER 1: one bit per clock during DIR_WAIT, 0: the
seed's single-clock division and product; seed 004: its defaults), Yosys synthesises the top for the Lattice
iCE40UP5K (synth_ice40) and the Gowin GW1N-9 (synth_gowin), the parts seed 000 §7.2 names, and nextpnr-ice40 places
and routes the iCE40 build on the UP5K (SG48 package) with a 50 MHz constraint. Fails when a synthesis fails or
infers a latch; prints the LUTs, flip-flops, block RAMs (and the Gowin's distributed RAMs when used) and cells, the
iCE40 logic cells used of 5,280 and the maximum clock nextpnr finds, and whether it meets 50 MHz (a placement that
does not fit is reported, not failed: seed 000's single-clock arithmetic is not expected to fit).
"""
import json
import os
import re
import subprocess
import sys

# Per design: its top module, its files, and its variants as (label, file tag, top parameters).
DESIGNS = {
    "fpga_uart": ("top",
                  ["top.v", "uart_rx.v", "uart_tx.v", "packet_decoder.v", "step_gen.v", "period_divider.v",
                   "step_ramp.v", "laser_ctrl.v", "packet_queue.v"],
                  [("DIVIDER 1", "divider1", {"DIVIDER": 1}), ("DIVIDER 0", "divider0", {"DIVIDER": 0})]),
    "spi_fpga": ("spi_fpga_top",
                 ["spi_fpga_top.v", "spi_slave.v", "spi_cmd_fifo.v", "spi_pulse_gen.v", "spi_step_counter.v",
                  "spi_laser_latch.v"],
                 [("spi_fpga_top", "defaults", {})]),
}
# Per family: the Yosys pass, the prefix of its LUT cells, its block RAM cells (the iCE40's 4 kbit EBR; the Gowin
# BSRAM as Yosys 0.23 names it, and the B-suffixed names later Yosys versions use) and its distributed RAM cells (the
# GW1N's shadow SRAM, 16 words in the logic, GW1N series data sheet; the iCE40 has none), which hold a memory's bits
# in place of flip-flops.
FAMILIES = [
    ("synth_ice40", "SB_LUT", {"SB_RAM40_4K", "SB_RAM40_4KNR", "SB_RAM40_4KNW", "SB_RAM40_4KNRNW"}, set()),
    ("synth_gowin", "LUT", {"SP", "SPX9", "SDP", "SDPX9", "DP", "DPX9", "SDPB", "SDPX9B", "DPB", "DPX9B"},
     {"RAM16S1", "RAM16S2", "RAM16S4", "RAM16SDP1", "RAM16SDP2", "RAM16SDP4"}),
]
UP5K_LOGIC_CELLS = 5280  # iCE40 UltraPlus family data sheet, table 1-1: iCE40UP5K


def yosys(rtl_dir, top, sources, params, synth, out_json, log):
    chparam = "".join("chparam -set %s %d %s; " % (name, value, top) for name, value in params.items())
    script = "read_verilog %s; %s%s -top %s -json %s; stat" % (
        " ".join(os.path.join(rtl_dir, s) for s in sources), chparam, synth, top, out_json)
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


def nextpnr(in_json, report, log):
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


def count(cells, kind):
    return sum(n for cell, n in cells.items() if kind(cell))


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in DESIGNS:
        sys.exit("usage: synth_report.py {%s} RTL_DIR WORKDIR" % ",".join(DESIGNS))
    design, rtl_dir, work = sys.argv[1:4]
    top, sources, variants = DESIGNS[design]
    os.makedirs(work, exist_ok=True)
    failures = []
    for label, tag, params in variants:
        for synth, lut_prefix, brams, lutrams in FAMILIES:
            name = os.path.join(work, "%s_%s_%s" % (design, tag, synth))
            cells, error = yosys(rtl_dir, top, sources, params, synth, name + ".json", name + "_yosys.log")
            if error:
                failures.append(error)
                continue
            luts = count(cells, lambda k: k.startswith(lut_prefix))
            ffs = count(cells, lambda k: "DFF" in k)
            rams = count(cells, lambda k: k in brams)
            ram16s = count(cells, lambda k: k in lutrams)
            print("%s, %s: %d LUTs, %d flip-flops, %d block RAMs, %s%d cells" % (
                label, synth, luts, ffs, rams, "%d distributed RAMs, " % ram16s if ram16s else "",
                sum(cells.values())))
            if synth != "synth_ice40":
                continue
            # A logic cell holds one LUT4 (iCE40 UltraPlus family data sheet, PLB): more LUTs than logic cells
            # cannot place, and nextpnr would spend minutes finding that out.
            if luts > UP5K_LOGIC_CELLS:
                print("  iCE40UP5K: %d LUTs of %d: does not fit" % (luts, UP5K_LOGIC_CELLS))
            else:
                print("  iCE40UP5K, nextpnr: " + nextpnr(name + ".json", name + "_nextpnr.json",
                                                         name + "_nextpnr.log"))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
