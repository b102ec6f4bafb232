#!/usr/bin/env python3
"""Whole runs with the dynamic mechanics.

  lost_steps_f4800 CNCSIM ROOT: the six-segment shape at F4800 (scenarios/mechanics/six_segment_f4800.toml).
    80 mm/s is 1.55 x the X axis's pull-in rate (51.7 mm/s, `cncsim motor-curve`); fpga-uart jumps straight
    to it and must lose steps, which its report counts and its summary prints; spi-fpga reaches the same speed
    on its 1000 mm/s^2 ramp and must lose none.
    The table of docs/mechanics.md ("What the dynamic carriage changes") must be what the runs print: the losses at F4800 per
    architecture, none at the stated highest feed, some at the next feed the search tried.
  circle_contour CNCSIM ROOT: the fpga-uart circle: the contour error with dynamic mechanics exceeds the ideal one
    (and its plots draw the load angle and the lost steps over time), and the summary says where it comes from.
"""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import run_report  # noqa: E402


def run(cncsim, scenario, sets, tmp, tag, extra=()):
    # The table of docs/mechanics.md was searched on exact clocks: a boundary feed can move with a unit's offset.
    return run_report(cncsim, scenario, tmp, tag, ["clock.ideal=true", *sets], extra)


def lost(report, arch):
    m = report[arch]["mechanics"]
    return m["x"]["lost_full_steps"], m["y"]["lost_full_steps"]


def six_segment(cncsim, root, tmp, arch, feed):
    with open(os.path.join(root, "scenarios", "jobs", "six_segment_f4800.nc")) as f:
        text = f.read().replace("F4800", "F%d" % feed)
    job = os.path.join(tmp, "six_segment_%s_f%d.nc" % (arch, feed))
    with open(job, "w") as f:
        f.write(text)
    scenario = os.path.join(root, "scenarios", "mechanics", "six_segment_f4800.toml")
    return run(cncsim, scenario, ["scenario.architecture=" + arch, "scenario.job=" + job,
                                  "machine.rapid_feed_mm_per_min=%d" % feed], tmp, "%s_f%d" % (arch, feed))


def lost_steps_f4800(cncsim, root, tmp):
    with open(os.path.join(root, "docs", "mechanics.md")) as f:
        readme = f.read()
    rows = re.findall(r"^\| (fpga-uart|atmega|spi-fpga) \| (\d+) / (\d+) \| F(\d+)(?: \(F(\d+) loses steps\))? \|",
                      readme, re.M)
    assert len(rows) == 3, "docs/mechanics.md: expected the three rows of the lost-steps table, found %r" % rows
    for arch, x, y, good, bad in rows:
        report, out = six_segment(cncsim, root, tmp, arch, 4800)
        assert lost(report, arch) == (int(x), int(y)), "%s at F4800: report %r, docs/mechanics.md %s / %s" % (
            arch, lost(report, arch), x, y)
        assert re.search(r"x: lost %s full steps" % x, out), "%s: the summary does not print the losses" % arch
        if arch == "spi-fpga":
            assert (int(x), int(y)) == (0, 0), "the spi-fpga ramp must lose no step"
            assert int(good) == 4800
            continue
        if arch == "fpga-uart":
            assert int(x) > 0, "fpga-uart jumps to 80 mm/s, above the pull-in rate, and must lose steps"
        report, _ = six_segment(cncsim, root, tmp, arch, int(good))
        assert lost(report, arch) == (0, 0), "%s at F%s (docs/mechanics.md: no losses): %r" % (arch, good, lost(report, arch))
        report, _ = six_segment(cncsim, root, tmp, arch, int(bad))
        assert sum(lost(report, arch)) > 0, "%s at F%s (docs/mechanics.md: loses steps): none lost" % (arch, bad)


def circle_contour(cncsim, root, tmp):
    scenario = os.path.join(root, "scenarios", "fpga-uart", "circle_r10.toml")
    ideal, _ = run(cncsim, scenario, ["mechanics.model=ideal"], tmp, "circle_ideal")
    plots = os.path.join(tmp, "plots")
    dynamic, out = run(cncsim, scenario, ["mechanics.model=dynamic"], tmp, "circle_dynamic", ["--plots", plots])
    ci = ideal["metrics"]["path"]["contour_max_um"]
    cd = dynamic["metrics"]["path"]["contour_max_um"]
    assert cd > ci, "contour max dynamic %g um is not above ideal %g um" % (cd, ci)
    assert "include their lag and ringing" in out, "the summary does not say where the error comes from"
    # The dynamic run's plots include the load angle and the lost steps over time.
    for name, title in (("series_load_angle", "load angle over time"), ("series_lost_full_steps", "lost full steps")):
        svg = os.path.join(plots, name + ".svg")
        assert os.path.exists(svg) and os.path.exists(os.path.join(plots, name + ".png")), "no plot " + name
        with open(svg) as f:
            assert title in f.read(), "%s has no title '%s'" % (svg, title)
    print("circle contour max: ideal %.3f um, dynamic %.3f um" % (ci, cd))


def main():
    mode, cncsim, root = sys.argv[1:4]
    with tempfile.TemporaryDirectory(prefix="dynamic_runs_%s_" % mode) as tmp:
        {"lost_steps_f4800": lost_steps_f4800, "circle_contour": circle_contour}[mode](cncsim, root, tmp)


if __name__ == "__main__":
    main()
