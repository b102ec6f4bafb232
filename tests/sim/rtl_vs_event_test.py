#!/usr/bin/env python3
"""The FPGA's Verilog in the loop against its event-driven model: usage CNCSIM SCENARIO [--set KEY=VALUE]...
[--rtl-set KEY=VALUE]... [--only PATH]... [--expect-difference].

Runs the scenario twice, fpga.model = "event" and "rtl" (the --set keys on both runs, e.g. the architecture of a
compare scenario or spi.trace_wires = true, which the RTL of spi-fpga forces; the --rtl-set keys on the second run
only), each with the
detailed JSON report and a VCD, and compares: the same exit status, the same report (every figure, every packet
record), and the same value changes in the VCD at the same times (STEP, DIR, nENBL, laser, the link's lines, busy,
the FPGA's strobes, the carriage positions). Within one time the order of the changes is free: the two models
write a clock edge's registers in different delta cycles. --expect-difference turns the check round: the runs
must differ (a deliberately wrong design shows that the comparison can fail), and the first difference is printed.
--only compares those parts of the report alone (a path such as metrics or fpga-uart/dead_time), and the VCD
without the FPGA's inner strobes (a user's design need not have them).
"""
import json
import os
import subprocess
import sys
import tempfile


def run(cncsim, scenario, folder, tag, sets):
    report = os.path.join(folder, tag + ".json")
    vcd = os.path.join(folder, tag + ".vcd")
    cmd = [cncsim, "run", scenario, "--progress", "off", "--report", report, "--vcd", vcd,
           "--set", "trace.detail=true"]
    for s in sets:
        cmd += ["--set", s]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode not in (0, 1):
        sys.exit("%s: %s exited %d:\n%s" % (tag, " ".join(cmd), done.returncode, done.stderr))
    with open(report) as f:
        return done.returncode, json.load(f), vcd_changes(vcd)


def vcd_changes(path):
    """(signal names by id, {time: sorted [(name, value)]}) of a VCD file."""
    names, changes, t = {}, {}, 0
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "$var":
                names[words[3]] = words[4]
            elif words[0].startswith("#"):
                t = int(words[0][1:])
            elif words[0][0] in "01xz" and len(words) == 1:
                changes.setdefault(t, []).append((names[words[0][1:]], words[0][0]))
            elif words[0][0] in "rb" and len(words) == 2:
                changes.setdefault(t, []).append((names[words[1]], words[0][1:]))
    return {t: sorted(c) for t, c in changes.items()}


def report_differences(a, b, path=""):
    if type(a) is not type(b):
        return ["%s: %r / %r" % (path, a, b)]
    if isinstance(a, dict):
        out = []
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append("%s/%s: only in the %s run" % (path, k, "event" if k in a else "rtl"))
            else:
                out += report_differences(a[k], b[k], path + "/" + k)
        return out
    if isinstance(a, list):
        if len(a) != len(b):
            return ["%s: %d items / %d" % (path, len(a), len(b))]
        out = []
        for i, (x, y) in enumerate(zip(a, b)):
            out += report_differences(x, y, "%s[%d]" % (path, i))
        return out
    return [] if a == b else ["%s: %r / %r" % (path, a, b)]


def part(report, path):
    for key in path.split("/"):
        report = report[key]
    return report


INNER_STROBES = {"pkt_valid", "cfg_valid", "rx_valid", "ack"}


def without_strobes(changes):
    kept = {t: [c for c in cs if c[0] not in INNER_STROBES] for t, cs in changes.items()}
    return {t: cs for t, cs in kept.items() if cs}


def vcd_differences(a, b):
    out = []
    for t in sorted(set(a) | set(b)):
        if a.get(t) != b.get(t):
            out.append("at %d: event %s / rtl %s" % (t, a.get(t, []), b.get(t, [])))
    return out


def main():
    args = sys.argv[1:]
    expect_difference = "--expect-difference" in args
    args = [a for a in args if a != "--expect-difference"]
    cncsim, scenario = args[0], args[1]
    both_sets = [args[i + 1] for i in range(2, len(args) - 1) if args[i] == "--set"]
    rtl_sets = both_sets + ["fpga.model=rtl"] + [args[i + 1] for i in range(2, len(args) - 1) if args[i] == "--rtl-set"]
    only = [args[i + 1] for i in range(2, len(args) - 1) if args[i] == "--only"]
    with tempfile.TemporaryDirectory() as folder:
        code_e, report_e, vcd_e = run(cncsim, scenario, folder, "event", both_sets)
        code_r, report_r, vcd_r = run(cncsim, scenario, folder, "rtl", rtl_sets)
    if only:
        report_e, report_r = ({p: part(r, p) for p in only} for r in (report_e, report_r))
        vcd_e, vcd_r = without_strobes(vcd_e), without_strobes(vcd_r)
    differences = report_differences(report_e, report_r) + vcd_differences(vcd_e, vcd_r)
    if code_e != code_r:
        differences.insert(0, "exit status: event %d / rtl %d" % (code_e, code_r))
    edges = sum(len(c) for c in vcd_e.values())
    if expect_difference:
        if not differences:
            sys.exit("FAIL: the runs agree on all %d value changes, though the design differs" % edges)
        print("PASS: the runs differ (%d differences), first: %s" % (len(differences), differences[0]))
        return
    if differences:
        print("\n".join(differences[:20]))
        sys.exit("FAIL: %d differences between the event-driven and the RTL run of %s" % (len(differences), scenario))
    packets = len(report_e.get("fpga-uart", {}).get("fpga", {}).get("packets", [])) if not only else 0
    frames = report_e.get("spi-fpga", {}).get("fpga", {}).get("frames", 0) if not only else 0
    print("PASS: %s: the same report and the same %d value changes in %d instants (%d packets, %d frames), exit %d" %
          (os.path.basename(scenario), edges, len(vcd_e), packets, frames, code_e))


if __name__ == "__main__":
    main()
