#!/usr/bin/env python3
"""Faults on the Arduino board's UART wires (atmega and grbl): usage CNCSIM SOURCE_DIR WORKDIR GRBL_PROTOCOL_ELF.

What each receiver framed is matched against what the other end sent (board_faults.hpp); the faulty wires count,
on their own, the frames they hit. The checks hold the two apart:
- a wire that hits nothing (BER 1e-12) leaves every byte as sent, both ways, on grbl's streamed job too;
- frames lost whole (no bit error) are exactly the bytes the receiver never framed, and none arrives wrong; the
  seed 003 protocol notices a lost byte only as a missing confirm, and stops;
- bit errors: seed 003's protocol has no check, so a changed byte can run (the PC gets its confirm and goes on)
  and the tool ends off the programmed point by more than a step, as the metrics measure it from the STEP edges;
  a changed confirm stops the PC program (protocol mismatch); the same seed gives the same report, byte for byte;
- a host stall: seed 003's PC program writes a byte per confirm, so the job takes exactly as much longer as the
  stall held the program up (within a 1 ms USB frame); grbl's sender has the square's few lines in grbl's buffer
  before the stall, so the job still ends on the programmed point with every step (the stall costs it no motion).
"""
import filecmp
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import check  # noqa: E402

STEP_UM = 1000.0 / 160.0  # the scenarios' machine: 160 steps/mm


def run(cncsim, scenario, work, tag, sets):
    """(exit code, report, stdout) of a run that may fail; the report is written either way."""
    report = os.path.join(work, tag + ".json")
    cmd = [cncsim, "run", scenario, "--progress", "off", "--report", report]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode in (0, 1), "%s: exit %d: %s" % (tag, r.returncode, r.stderr))
    with open(report) as f:
        return r.returncode, json.load(f), r.stdout


def directions(faults):
    return [("to the MCU", faults["to_mcu"]), ("from the MCU", faults["from_mcu"])]


def main():
    cncsim, source, work, grbl_elf = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    square = os.path.join(source, "scenarios", "atmega", "square_20mm.toml")
    grbl_square = os.path.join(source, "tests", "data", "grbl", "square_20mm.toml")

    for arch, scenario, sets in (("atmega", square, []), ("grbl", grbl_square, ["avr.firmware=" + grbl_elf])):
        rc, rep, _ = run(cncsim, scenario, work, arch + "_clean", sets + ["faults.uart_ber=1e-12"])
        check(rc == 0, "%s: a wire that hits nothing failed the run" % arch)
        for name, d in directions(rep[arch]["faults"]):
            check(d["frames_hit"] == 0, "%s %s: a frame hit at BER 1e-12" % (arch, name))
            check(d["frames"] > 0 and d["bytes_as_sent"] == d["frames"],
                  "%s %s: %d of %d bytes as sent on a wire that hit nothing" % (arch, name, d["bytes_as_sent"],
                                                                               d["frames"]))

    rc, rep, out = run(cncsim, square, work, "lost", ["faults.uart_frame_loss_rate=0.05", "faults.seed=3"])
    f = rep["atmega"]["faults"]
    check(f["to_mcu"]["frames_lost"] + f["from_mcu"]["frames_lost"] > 0, "no frame lost at 5 %")
    for name, d in directions(f):
        check(d["bytes_lost"] == d["frames_lost"],
              "%s: %d bytes never framed, the wire lost %d" % (name, d["bytes_lost"], d["frames_lost"]))
        check(d["bytes_wrong"] == 0 and d["bytes_extra"] == 0, "%s: a byte changed with frames lost whole" % name)
    check(rc == 1 and "no confirm byte 0x06" in out, "a lost byte was not noticed as a missing confirm: " + out)

    rc, rep, out = run(cncsim, square, work, "silent", ["faults.uart_ber=3e-3", "faults.seed=6"])
    f = rep["atmega"]["faults"]
    check(rc == 0, "BER 3e-3 seed 6: the run did not end: " + out)
    check(f["to_mcu"]["bytes_wrong"] > 0, "no byte arrived changed")
    check(f["transfers"]["ran_without_a_check_noticing"] > 0, "no changed transfer ran")
    end_um = rep["metrics"]["path"]["job_end_um"]
    check(end_um > STEP_UM, "the changed transfers left the tool %.3f um off, less than a step" % end_um)
    print("seed 003 protocol at BER 3e-3: %d transfers run changed, the tool ends %.1f um off"
          % (f["transfers"]["ran_without_a_check_noticing"], end_um))
    run(cncsim, square, work, "silent_again", ["faults.uart_ber=3e-3", "faults.seed=6"])
    check(filecmp.cmp(os.path.join(work, "silent.json"), os.path.join(work, "silent_again.json"), shallow=False),
          "the same seed gave another report")

    rc, rep, out = run(cncsim, square, work, "mismatch", ["faults.uart_ber=1e-2", "faults.seed=1"])
    check(rep["atmega"]["faults"]["from_mcu"]["bytes_wrong"] > 0, "BER 1e-2 seed 1: no confirm changed")
    check(rc == 1 and "protocol mismatch" in out, "a changed confirm did not stop the PC program: " + out)
    clean = run(cncsim, square, work, "stall_clean", [])[1]
    rc, rep, out = run(cncsim, square, work, "stall", ["faults.host_stall_at_s=0.5", "faults.host_stall_s=1.5"])
    held = rep["atmega"]["faults"]["host_stall"]["host_held_up_s"]
    longer = rep["metrics"]["job"]["job_time_s"] - clean["metrics"]["job"]["job_time_s"]
    check(rc == 0 and held > 0.0, "the stall held the PC program up %.6f s: %s" % (held, out))
    check(abs(longer - held) <= 1e-3, "the job took %.6f s longer for a stall that held the program %.6f s"
          % (longer, held))
    sets = ["avr.firmware=" + grbl_elf, "faults.host_stall_at_s=1", "faults.host_stall_s=1.5"]
    rc, rep, out = run(cncsim, grbl_square, work, "grbl_stall", sets)
    check(rc == 0 and rep["grbl"]["faults"]["host_stall"]["host_held_up_s"] > 0.0, "grbl: the stall " + out)
    steps = [a["driver_timing"]["rate"]["checked"] + 1 for a in rep["metrics"]["axes"]]
    check(steps == [9600, 9600] and rep["metrics"]["path"]["job_end_um"] < STEP_UM,
          "grbl with a stall: %s steps, ends %.3f um off" % (steps, rep["metrics"]["path"]["job_end_um"]))
    print("PASS")


if __name__ == "__main__":
    main()
