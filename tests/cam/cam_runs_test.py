#!/usr/bin/env python3
"""Each ordering's G-code runs on each architecture, and a DXF job is the G-code `cncsim cam` writes (docs/cam.md):
usage CNCSIM SOURCE_DIR WORKDIR ARCH[,ARCH...].

For every ordering of tests/data/cam/small_part.dxf: `cncsim cam --order O --out O.nc`; `cncsim run O.nc --arch A`
runs on every ARCH with as many programmed moves as the cam counted commands (a G0 per route and a G1/G2/G3 per line
or arc); on the first ARCH, `cncsim run small_part.dxf --set cam.order=O` writes the same G-code byte for byte
(cam.gcode) and gives the same report figures as the run of O.nc; `cncsim cam --compare-orders --arch A` shows each
ordering's job time on the first ARCH as those runs give it.
"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import check, run_report  # noqa: E402

ORDERS = ["selection", "seed000", "seed003", "optimized"]


def main():
    cncsim, source, work, archs = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    drawing = os.path.join(source, "tests", "data", "cam", "small_part.dxf")
    first = archs.split(",")[0]
    job_times = {}
    for order in ORDERS:
        gcode = os.path.join(work, order + ".nc")
        out = subprocess.run([cncsim, "cam", drawing, "--order", order, "--out", gcode], check=True,
                             capture_output=True, text=True).stdout
        routes = int(re.search(r"routes \(rapids\)\s+(\d+)", out).group(1))
        moves = int(re.search(r"cutting moves\s+(\d+)", out).group(1))
        for k, arch in enumerate(archs.split(",")):
            tag = "%s_%s" % (order, arch)
            report, _ = run_report(cncsim, gcode, work, tag, extra=["--arch", arch])
            check(report["gcode"]["moves"] == routes + moves,
                  "%s: %d programmed moves, the cam wrote %d rapids and %d cuts"
                  % (tag, report["gcode"]["moves"], routes, moves))
            print("%-10s %-10s job time %.4f s, %d moves" % (order, arch, report["metrics"]["job"]["job_time_s"],
                                                               report["gcode"]["moves"]))
            if k > 0:
                continue
            job_times[order] = report["metrics"]["job"]["job_time_s"]
            written = os.path.join(work, tag + "_dxf_job.nc")
            from_dxf, _ = run_report(cncsim, drawing, work, tag + "_dxf",
                                     sets=["cam.order=" + order, "cam.gcode=" + written], extra=["--arch", arch])
            with open(gcode) as a, open(written) as b:
                check(a.read() == b.read(), "%s: the DXF job's G-code differs from cncsim cam's" % tag)
            check(from_dxf["scenario"]["drawing"] == drawing, "%s: the report names no drawing" % tag)
            for section in ("gcode", "metrics"):
                check(from_dxf[section] == report[section], "%s: the DXF job's %s differ from the G-code's"
                      % (tag, section))
    table = subprocess.run([cncsim, "cam", drawing, "--compare-orders", "--arch", first], check=True,
                           capture_output=True, text=True).stdout
    print(table)
    for order in ORDERS:
        row = re.search(r"^%s\s+(\d+)\s+(\d+)\s+(\d+)\s+\S+\s+\S+\s+(\S+)$" % order, table, re.M)
        check(row is not None, "--compare-orders shows no row for %s" % order)
        check(abs(float(row.group(4)) - job_times[order]) < 5e-5,
              "%s: --compare-orders shows %s s on %s, its run %.4f s" % (order, row.group(4), first, job_times[order]))
    print("PASS")


if __name__ == "__main__":
    main()
