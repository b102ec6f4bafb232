#!/usr/bin/env python3
"""USB latency spikes on the CP2102 link (faults.usb_spike_*): usage CNCSIM SOURCE_DIR WORKDIR.

Both hosts here wait for an answer before they write again (seed 003's PC program a confirm per byte, seed 000's
script an ACK per packet), so each spike that delays data holds the job up by its length, give or take the 1 ms USB
frame the next write waits for: the job time the metrics measure from the STEP edges grows by the delays the CP2102
counts, within a frame per delayed frame. The same seed gives the same report, byte for byte.
"""
import filecmp
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import args_and_workdir, check, run_report  # noqa: E402

USB_FRAME_MS = 1.0  # USB 2.0 full speed


def main():
    cncsim, source, work = args_and_workdir()
    for arch, rate, seeds in (("atmega", 0.05, (1, 3)), ("fpga-uart", 0.3, (1, 2))):
        scenario = os.path.join(source, "scenarios", arch, "square_20mm.toml")
        clean, _ = run_report(cncsim, scenario, work, arch + "_clean")
        check("usb_spikes" not in clean[arch], "%s: spikes reported without faults" % arch)
        for seed in seeds:
            sets = ["faults.usb_spike_rate=%g" % rate, "faults.usb_spike_mean_ms=5", "faults.seed=%d" % seed]
            rep, _ = run_report(cncsim, scenario, work, "%s_%d" % (arch, seed), sets)
            u = rep[arch]["usb_spikes"]
            frames = u["to_chip"]["frames_delayed"] + u["to_host"]["frames_delayed"]
            delay_ms = u["to_chip"]["delay_ms"] + u["to_host"]["delay_ms"]
            longer_ms = 1e3 * (rep["metrics"]["job"]["job_time_s"] - clean["metrics"]["job"]["job_time_s"])
            check(frames > 0, "%s seed %d: no spike delayed data" % (arch, seed))
            check(abs(longer_ms - delay_ms) <= USB_FRAME_MS * (frames + 1),
                  "%s seed %d: the job took %.3f ms longer for %.3f ms of spikes in %d frames"
                  % (arch, seed, longer_ms, delay_ms, frames))
            print("%s seed %d: %d frames delayed %.3f ms, the job %.3f ms longer" % (arch, seed, frames, delay_ms,
                                                                                 longer_ms))
        run_report(cncsim, scenario, work, "%s_%d_again" % (arch, seeds[0]), sets[:2] + ["faults.seed=%d" % seeds[0]])
        check(filecmp.cmp(os.path.join(work, "%s_%d.json" % (arch, seeds[0])),
                          os.path.join(work, "%s_%d_again.json" % (arch, seeds[0])), shallow=False),
              "%s: the same seed gave another report" % arch)
    print("PASS")


if __name__ == "__main__":
    main()
