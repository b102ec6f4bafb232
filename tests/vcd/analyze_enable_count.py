#!/usr/bin/env python3
"""`cncsim analyze --enable` counts the STEP pulses the driver acts on in a run's VCD, as the run counts them.

The atmega square (scenarios/atmega/square_20mm.toml: 160 steps/mm) moves X 10 mm (G0 to 10,10), 20 + 20 mm (the
square's two X sides) and 10 mm (G0 back to 0,0): 60 mm, 9,600 steps. Seed 003's firmware stops an axis by its
nENBL while the timer keeps toggling STEP, so the raw STEP pin carries more pulses than that; a DRV8825 acts on a
rising STEP edge only while nENBL is low (active low, DRV8825 datasheet, "nENBL"), with the level it had before an
edge at the same instant. This file's own reader of the VCD (not cncsim's) counts those edges, and the count must be
9,600, the run's own X count, and what analyze counts with --enable ENABLE. The carriage positions are real
variables written between the pin edges: the dynamic carriage's at every step, so both carriages are run.

Usage: analyze_enable_count.py CNCSIM SCENARIO WORKDIR ENABLE [--set KEY=VALUE ...]
"""
import os
import re
import sys

from vcd_tools import analyze, expect_equal, fail, run_cncsim

EXPECTED_X_STEPS = 160 * (10 + 20 + 20 + 10)  # steps/mm x the job's X travel, mm


def enabled_rising_edges(path, step, enable):
    """Rising edges of `step` while `enable` is low, from the VCD text."""
    with open(path) as f:
        text = f.read()
    head, _, body = text.partition("$enddefinitions")
    ids = {name: ident for ident, name in re.findall(r"\$var\s+\w+\s+\d+\s+(\S+)\s+(\S+)\s+\$end", head)}
    for name in (step, enable):
        if name not in ids:
            fail("%s: no variable %s" % (path, name))
    step_id, enable_id = ids[step], ids[enable]
    levels = {step_id: None, enable_id: None}
    enable_before = None  # the enable's level before the current instant's changes
    count = 0
    tokens = iter(body.split())
    for tok in tokens:
        if tok.startswith("#"):
            enable_before = levels[enable_id]
        elif tok[0] in "rRbB":
            next(tokens)  # a real or vector value: its identifier follows
        elif tok[0] in "01xXzZ":
            ident, level = tok[1:], tok[0] == "1"
            if ident == step_id and level and levels[step_id] is False and enable_before is False:
                count += 1
            if ident in levels:
                levels[ident] = level
                if ident == enable_id and enable_before is None:
                    enable_before = level  # the $dumpvars value
    return count


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    cncsim, scenario, workdir, enable = sys.argv[1:5]
    extra = sys.argv[5:]
    vcd, report = run_cncsim(cncsim, workdir, "run", scenario, *extra)
    counted = enabled_rising_edges(vcd, "step_x", "n_enbl_x")
    expect_equal("X steps read from the VCD while n_enbl_x is low", counted, EXPECTED_X_STEPS)
    run_x = report["metrics"]["axes"][0]
    expect_equal("the run's first axis", run_x["axis"], "x")
    expect_equal("the run's X steps", run_x["rising_edges"], EXPECTED_X_STEPS)
    analyzed = analyze(cncsim, vcd, os.path.join(workdir, "analyze.json"),
                       "--step", "step_x", "--dir", "dir_x", "--enable", enable)
    expect_equal("analyze --enable %s: X steps" % enable, analyzed["axes"][0]["rising_edges"], EXPECTED_X_STEPS)
    print("%s %s: %d X steps while n_enbl_x is low: the VCD, the run and analyze --enable %s agree"
          % (os.path.basename(scenario), " ".join(extra), counted, enable))


if __name__ == "__main__":
    main()
