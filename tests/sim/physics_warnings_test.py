#!/usr/bin/env python3
"""Warnings for what the physics did, in the run's summary, its JSON report and the compare page.

  feed_held CNCSIM ROOT: the 20 mm square (scenarios/fpga-uart/square_20mm.toml) at F20000 on a machine whose axes
    go 150 mm/s: the four sides (lines 5-8) are held to 60 x 150 = F9000, one warning for the four lines,
    held by X and by Y.
  load_angle CNCSIM ROOT: the six-segment shape at F4800 (scenarios/mechanics/six_segment_f4800.toml): fpga-uart
    jumps to 80 mm/s, past the X axis's pull-in rate, and loses steps, so its X rotor went past pull-out (a slip
    takes the rotor past 180 electrical degrees, so past 90); every axis whose peak load angle is 81 (90 less
    10 %) or more has the warning of its kind, at the axis and the time of the peak, and no other axis has one.
"""
import html
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import run_report  # noqa: E402

PULL_OUT_DEG = 90.0  # a hybrid stepper's torque peaks at 90 electrical degrees of load angle


def compare_page(cncsim, scenario, sets, tmp, arch):
    out = os.path.join(tmp, "compare_" + arch)
    cmd = [cncsim, "compare", scenario, "--arch", arch, "--out", out]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    with open(os.path.join(out, "index.html")) as f:
        return f.read()


def warnings_of(report, kind):
    return [w for w in report["warnings"] if w["kind"] == kind]


def feed_held(cncsim, root, tmp):
    v_max_mm_per_s = 150.0
    asked = 20000.0
    held = min(asked, 60.0 * v_max_mm_per_s)  # every side runs along one axis
    with open(os.path.join(root, "scenarios", "jobs", "square_20mm.nc")) as f:
        text = f.read()
    job = os.path.join(tmp, "square_f20000.nc")
    with open(job, "w") as f:
        f.write("\n".join(l.replace("F800", "F%d" % asked) if l.startswith("G1") else l
                          for l in text.splitlines()) + "\n")
    lines = [i + 1 for i, l in enumerate(text.splitlines()) if l.startswith("G1")]
    assert lines == list(range(lines[0], lines[0] + 4)), lines
    scenario = os.path.join(root, "scenarios", "fpga-uart", "square_20mm.toml")
    sets = ["scenario.job=" + job, "machine.x.max_velocity_mm_per_s=%g" % v_max_mm_per_s,
            "machine.y.max_velocity_mm_per_s=%g" % v_max_mm_per_s]
    report, out = run_report(cncsim, scenario, tmp, "square_f20000", sets)
    where = "%s:%d-%d" % (job, lines[0], lines[-1])
    figures = ("feed %.1f mm/min held to %.1f mm/min by machine.x.max_velocity_mm_per_s = %g and "
               "machine.y.max_velocity_mm_per_s = %g" % (asked, held, v_max_mm_per_s, v_max_mm_per_s))
    w = warnings_of(report, "feed_held")
    assert len(w) == 1 and w[0]["count"] == 1 and w[0]["first"] == [where], w
    assert w[0]["message"].startswith(figures), w[0]["message"]
    assert "warning: %s: %s" % (where, figures) in out, out
    page = compare_page(cncsim, scenario, sets, tmp, "fpga-uart")
    assert html.escape(where) + ": " + html.escape(figures) in page, "the compare page has no feed_held warning"
    # Within the limits, no warning.
    report, _ = run_report(cncsim, scenario, tmp, "square_f800", sets[1:])
    assert not warnings_of(report, "feed_held"), report["warnings"]
    print("square at F%d: %s: %s" % (asked, where, figures))


def load_angle(cncsim, root, tmp):
    scenario = os.path.join(root, "scenarios", "mechanics", "six_segment_f4800.toml")
    for arch in ("fpga-uart", "spi-fpga"):
        report, out = run_report(cncsim, scenario, tmp, arch, ["scenario.architecture=" + arch])
        near = warnings_of(report, "load_angle_near_pull_out")
        past = warnings_of(report, "load_angle_past_pull_out")
        expected_near, expected_past = [], []
        for axis in ("x", "y"):
            m = report[arch]["mechanics"][axis]
            peak, t_s = m["peak_load_angle_electrical_deg"], m["peak_load_angle_t_s"]
            place = "%s at %.6f s" % (axis.upper(), t_s)
            if peak > PULL_OUT_DEG:
                expected_past.append(place)
            elif peak >= 0.9 * PULL_OUT_DEG:
                expected_near.append(place)
            else:
                continue
            summary = [l for l in out.splitlines() if l.startswith("warning:") and "load_angle" in l or
                       l.startswith("warning: %s: peak load angle %.1f electrical deg" % (place, peak))]
            assert any(place in l for l in summary), "%s: no summary warning at %s\n%s" % (arch, place, out)
            if arch == "fpga-uart" and axis == "x":
                assert m["lost_full_steps"] > 0 and peak > PULL_OUT_DEG, (arch, axis, m)
        assert [p for w in near for p in w["first"]] == expected_near, (arch, near, expected_near)
        assert [p for w in past for p in w["first"]] == expected_past, (arch, past, expected_past)
        if arch == "fpga-uart":
            page = compare_page(cncsim, scenario, [], tmp, arch)
            assert html.escape(expected_past[0]) in page, "the compare page has no load angle warning"
        print("%s: near pull-out %r, past %r" % (arch, expected_near, expected_past))


def main():
    mode, cncsim, root = sys.argv[1:4]
    with tempfile.TemporaryDirectory(prefix="physics_warnings_%s_" % mode) as tmp:
        {"feed_held": feed_held, "load_angle": load_angle}[mode](cncsim, root, tmp)


if __name__ == "__main__":
    main()
