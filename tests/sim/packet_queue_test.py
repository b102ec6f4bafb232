#!/usr/bin/env python3
"""The packet queue on fpga-uart (fpga.queue_depth): usage CNCSIM SOURCE_DIR WORKDIR.

- The study of scenarios/improvements (a queue of 4) on the 10,000-cut raster, where the host's fixed start (its
  0.35 s settle and init gap) weighs 0.25 %: the dead time a gap between two moves falls
  below the time an 11-byte seed packet takes on the wire (110 bits at the line's rate, computed here from the
  report's line baud), and the job time is within 1 % of the motion time; the seed's stop-and-wait on the same job
  leaves more than that transfer time in every gap.
- The 1,000-cut raster with a queue of 4 and bytes lost on both wires: the lost bytes are detected and the packets
  sent again, and every move runs exactly once: each axis's STEP pulses equal the steps the G-code programs (counted
  here from the file at 160 steps/mm), as without faults, and the tool ends on the programmed point.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import args_and_workdir, check, run_report  # noqa: E402

STEPS_PER_MM = 160  # the scenarios' machine: 1.8 deg, 1/32, GT2 20T
SEED_PACKET_BITS = 11 * 10  # seed 000's 11-byte motion packet, 8N1


def programmed_steps(job):
    """Each axis's STEP pulses the job's absolute G0/G1 moves program (every end point on the 1/160 mm grid)."""
    at = {"X": 0, "Y": 0}
    total = {"X": 0, "Y": 0}
    with open(job) as f:
        for line in f:
            code = line.split("(")[0]
            if not re.match(r"\s*G[01]\b", code):
                continue
            for axis, value in re.findall(r"([XY])(-?[0-9.]+)", code):
                to = round(float(value) * STEPS_PER_MM)
                total[axis] += abs(to - at[axis])
                at[axis] = to
    return total


def main():
    cncsim, source, work = args_and_workdir()
    scenarios = os.path.join(source, "scenarios", "improvements")

    study = os.path.join(scenarios, "queue_raster.toml")
    long_job = "scenario.job=../jobs/raster_10000_cuts.nc"
    queued, _ = run_report(cncsim, study, work, "queue4", sets=[long_job])
    job = queued["metrics"]["job"]
    transfer_ms = 1000.0 * SEED_PACKET_BITS / queued["fpga-uart"]["link"]["line_baud"]
    check(queued["fpga-uart"]["queue"]["depth"] == 4, "the study's scenario is not the queue of 4")
    check(job["dead_gaps"] >= 10000, "the raster has %d gaps" % job["dead_gaps"])
    check(job["dead_mean_ms"] < transfer_ms,
          "queue of 4: %.3f ms a gap, an 11-byte packet takes %.3f ms" % (job["dead_mean_ms"], transfer_ms))
    over = job["job_time_s"] / job["motion_time_s"] - 1.0
    check(over < 0.01, "queue of 4: job %.3f s, motion %.3f s" % (job["job_time_s"], job["motion_time_s"]))
    seed, _ = run_report(cncsim, study, work, "seed", sets=[long_job, "fpga.queue_depth=0", 'protocol.crc="none"'])
    sj = seed["metrics"]["job"]
    check(sj["dead_mean_ms"] > transfer_ms, "stop-and-wait: %.3f ms a gap" % sj["dead_mean_ms"])
    print("raster: stop-and-wait %.3f s (%.3f ms a gap), queue of 4 %.3f s (%.3f ms a gap, +%.2f %% over the motion "
          "%.3f s); an 11-byte packet takes %.3f ms"
          % (sj["job_time_s"], sj["dead_mean_ms"], job["job_time_s"], job["dead_mean_ms"], 100.0 * over,
             job["motion_time_s"], transfer_ms))

    lost_sc = os.path.join(scenarios, "queue_lost_bytes.toml")
    want = programmed_steps(os.path.join(source, "scenarios", "jobs", "raster_1000_cuts.nc"))
    clean, _ = run_report(cncsim, lost_sc, work, "clean", sets=["faults.uart_frame_loss_rate=0"])
    lost, _ = run_report(cncsim, lost_sc, work, "lost")
    faults = lost["fpga-uart"]["faults"]
    check(faults["to_fpga"]["frames_lost"] > 0, "no byte to the FPGA was lost")
    check(lost["fpga-uart"]["queue"]["host_sent_again"] > 0, "the lost bytes made no packet go again")
    for run, name in ((clean, "without faults"), (lost, "with lost bytes")):
        for k, axis in enumerate("XY"):
            got = run["metrics"]["axes"][k]["rising_edges"]
            check(got == want[axis], "%s: %d STEP pulses on %s, the G-code programs %d" % (name, got, axis, want[axis]))
        check(run["metrics"]["path"]["job_end_um"] == 0.0, "%s: the tool ends off the programmed point" % name)
    packets = faults["packets"]
    check(packets["executed_as_sent"] == packets["sent"] and packets["lost"] == 0 and packets["extra"] == 0
          and packets["silently_executed_wrong"] == 0, "with lost bytes: %s" % packets)
    print("lost bytes: %d to the FPGA and %d from it lost, %d packets sent again, every move once (X %d, Y %d STEP "
          "pulses); job %.3f s against %.3f s without faults"
          % (faults["to_fpga"]["frames_lost"], faults["from_fpga"]["frames_lost"],
             lost["fpga-uart"]["queue"]["host_sent_again"], want["X"], want["Y"], lost["metrics"]["job"]["job_time_s"],
             clean["metrics"]["job"]["job_time_s"]))
    print("PASS")


if __name__ == "__main__":
    main()
