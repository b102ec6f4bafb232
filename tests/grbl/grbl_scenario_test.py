#!/usr/bin/env python3
"""The grbl architecture with our grbl-protocol test firmware, through `cncsim run`.

Usage: grbl_scenario_test.py MODE CNCSIM SOURCE_DIR FIRMWARE_ELF FIRMWARE_HEX
  square    the 20 mm square: 9600 STEP pulses on each axis that the drivers take (10 + 20 + 20 + 10 mm at 160
            steps/mm, counted here from the report's edges), every line answered, the job ends on a status report
            that says Idle at machine 0,0, no error.
  error     a line the firmware does not support (M8, coolant) in a lenient run: reported as a warning at its G-code
            line with grbl's error:20, and the job goes on to its end.
  setting   a setting the firmware refuses ($999=1): exit 2, the message names the setting and where it was set.
  hex       the firmware's Intel HEX image (avr-objcopy's) runs as its ELF does: the same report but for the file name.
"""
import json
import os
import subprocess
import sys
import tempfile


def run(cncsim, source, scenario, firmware, extra):
    report = tempfile.NamedTemporaryFile(suffix=".json", delete=False).name
    os.remove(report)
    args = [cncsim, "run", scenario, "--set", "avr.firmware=" + firmware, "--report", report,
            "--progress", "off"] + extra
    p = subprocess.run(args, cwd=source, capture_output=True, text=True)
    data = None
    if os.path.exists(report):
        with open(report) as f:
            data = json.load(f)
        os.remove(report)
    return p, data


def check(cond, what):
    if not cond:
        print("FAIL:", what)
        sys.exit(1)
    print("ok:", what)


def main():
    mode, cncsim, source, firmware, hex_image = sys.argv[1:6]
    scenario = "tests/data/grbl/square_20mm.toml"
    if mode == "square":
        p, r = run(cncsim, source, scenario, firmware, [])
        check(p.returncode == 0, "exit 0 (stderr: %s)" % p.stderr.strip())
        for a in r["metrics"]["axes"]:
            check(a["rising_edges"] == 9600, "%s: %d STEP pulses taken, 9600 expected" % (a["axis"], a["rising_edges"]))
        sender = r["grbl"]["sender"]
        check(sender["lines_sent"] == 10 and sender["lines_answered"] == 10,
              "10 lines sent and answered (%d, %d)" % (sender["lines_sent"], sender["lines_answered"]))
        check(sender["last_status"].startswith("<Idle|MPos:0.000,0.000,"), "ends Idle at 0,0: " + sender["last_status"])
        check(sender["errors"] == [], "no error")
    elif mode == "error":
        job = os.path.join(tempfile.mkdtemp(), "with_m8.nc")
        with open(job, "w") as f:
            f.write("G21 G90\nG1 X2 Y1 F600\nM8\nG1 X0 Y0\n")
        p, r = run(cncsim, source, scenario, firmware, ["--set", "scenario.job=" + job])
        check(p.returncode == 0, "exit 0 (stderr: %s)" % p.stderr.strip())
        errors = r["grbl"]["sender"]["errors"]
        check(errors == [{"where": job + ":3", "line": "M8", "answer": "error:20"}], "M8 answered error:20: %s" % errors)
        warnings = [w for w in r["warnings"] if w["kind"] == "grbl_error"]
        check(len(warnings) == 1 and warnings[0]["first"] == [job + ":3"], "a warning at its line: %s" % warnings)
        check(r["grbl"]["sender"]["last_status"].startswith("<Idle|MPos:0.000,0.000,"),
              "the job went on to its end")
    elif mode == "setting":
        p, r = run(cncsim, source, scenario, firmware, ["--set", 'grbl.settings=["$999=1"]'])
        check(p.returncode == 2, "exit 2, got %d" % p.returncode)
        check("$999=1" in p.stderr and "--set grbl.settings" in p.stderr and "error:3" in p.stderr,
              "the message names the setting: " + p.stderr.strip())
        check(r is None, "no report")
    elif mode == "hex":
        p_elf, r_elf = run(cncsim, source, scenario, firmware, [])
        p_hex, r_hex = run(cncsim, source, scenario, hex_image, [])
        check(p_elf.returncode == 0 and p_hex.returncode == 0, "both run")
        check(r_hex["grbl"]["firmware"] == hex_image, "the report names the HEX file")
        r_hex["grbl"]["firmware"] = r_elf["grbl"]["firmware"]
        check(r_hex == r_elf, "the HEX run's report equals the ELF run's")
    else:
        sys.exit("unknown mode " + mode)


if __name__ == "__main__":
    main()
