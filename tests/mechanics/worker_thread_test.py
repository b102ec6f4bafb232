#!/usr/bin/env python3
"""The dynamic mechanics on their worker thread give the same runs as on the simulation's thread.

mechanics.worker_thread = true (the default) integrates the axes beside the simulation (mech::MechanicsWorker);
false keeps them on the simulation's thread, as a run with --vcd does. The worker makes the same calls in the same
order, so every run below must give the same exit code and the same JSON report byte for byte, and the same
printed summary: the three architectures, --detail, the whole logs (--samples), lost steps, a link fault, a job cut
off by its time limit, and a limit that falls while the carriage still rings after the job.
Usage: worker_thread_test.py CNCSIM SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

RUNS = [
    ("fpga-uart/square_20mm.toml", []),
    ("fpga-uart/six_segment.toml", ["--detail"]),
    ("fpga-uart/circle_r10.toml", ["--samples", "{tmp}/samples_{tag}.csv"]),
    ("fpga-uart/long_move_timeout.toml", []),
    ("fpga-uart/six_segment.toml", ["--set", "scenario.max_sim_s=3"]),
    ("mechanics/six_segment_f4800.toml", []),
    ("atmega/square_20mm.toml", []),
    ("atmega/diagonal_45.toml", ["--detail"]),
    ("spi-fpga/square_20mm.toml", []),
    ("spi-fpga/circle_r10.toml", []),
    ("spi-fpga/six_segment.toml", ["--detail"]),
    ("spi-fpga/square_at_next_pulse.toml", []),
]


def run(cncsim, source, tmp, scenario, extra, worker, tag):
    report = os.path.join(tmp, "%s_%s.json" % (tag, worker))
    args = [a.format(tmp=tmp, tag="%s_%s" % (tag, worker)) for a in extra]
    cmd = [cncsim, "run", os.path.join(source, "scenarios", scenario), "--progress", "off", "--report", report,
           "--set", "mechanics.model=dynamic", "--set", "mechanics.worker_thread=" + worker] + args
    p = subprocess.run(cmd, capture_output=True, text=True)
    with open(report, "rb") if os.path.exists(report) else open(os.devnull, "rb") as f:
        return p.returncode, f.read(), p.stdout


def compare(cncsim, source, tmp, scenario, extra, tag):
    sync = run(cncsim, source, tmp, scenario, extra, "false", tag)
    worker = run(cncsim, source, tmp, scenario, extra, "true", tag)
    what = "%s %s" % (scenario, " ".join(extra))
    assert sync[0] == worker[0], "%s: exit %d on the worker, %d without" % (what, worker[0], sync[0])
    assert sync[1], "%s: no report" % what
    assert sync[1] == worker[1], "%s: the reports differ" % what
    assert sync[2] == worker[2], "%s: the summaries differ" % what
    for name in ("samples_%s_false.csv" % tag, "samples_%s_true.csv" % tag):
        if os.path.exists(os.path.join(tmp, name)):
            with open(os.path.join(tmp, "samples_%s_false.csv" % tag), "rb") as a, \
                    open(os.path.join(tmp, "samples_%s_true.csv" % tag), "rb") as b:
                assert a.read() == b.read(), "%s: the samples differ" % what
    return json.loads(sync[1])


def main():
    cncsim, source = sys.argv[1:3]
    with tempfile.TemporaryDirectory() as tmp:
        for i, (scenario, extra) in enumerate(RUNS):
            compare(cncsim, source, tmp, scenario, extra, "r%d" % i)
            print("same: %s %s" % (scenario, " ".join(extra)))
        # A limit 1 ms after the job's end: the carriage still rings, so the periodic samples (the worker's, or the
        # kernel's events) run into it.
        report = compare(cncsim, source, tmp, "fpga-uart/square_20mm.toml", [], "end")
        end_s = report["metrics"]["job"]["job_time_s"]
        compare(cncsim, source, tmp, "fpga-uart/square_20mm.toml", ["--set", "scenario.max_sim_s=%.6f" % (end_s + 1e-3)],
                "ringing")
        print("same: a limit 1 ms after the job's end (%.6f s)" % (end_s + 1e-3))


if __name__ == "__main__":
    main()
