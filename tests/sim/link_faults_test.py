#!/usr/bin/env python3
"""Bit errors on the fpga-uart link, with and without the packet check: usage CNCSIM SOURCE_DIR WORKDIR.

The 1,000-cut raster of scenarios/improvements at a bit error rate of 1e-4 on both UART wires:
- the seed's packets: some run wrong and nothing notices; each such packet's steps error is the difference of the
  fields it ran and the fields sent; the steps the tally leaves at the job's end are where the carriage ends, as the
  metrics measure it from the STEP edges (ideal mechanics, 160 steps/mm): two readings that share no code;
- the same seed twice gives the same report, byte for byte;
- with protocol.crc = "crc16": no packet runs wrong or is lost, the tool ends on the programmed point, packets were
  sent again; without faults the check costs exactly its two bytes a packet on the wire (11 -> 13 a motion packet,
  9 -> 11 the init), and the job time is reported;
- a host stall makes the job longer by the time it held the script up.
"""
import filecmp
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import args_and_workdir, check, run_report  # noqa: E402

STEPS_PER_MM = 160.0  # the scenarios' machine: 1.8 deg, 1/32, GT2 20T


def main():
    cncsim, source, work = args_and_workdir()
    scenarios = os.path.join(source, "scenarios", "improvements")
    seed_sc = os.path.join(scenarios, "link_ber_seed.toml")
    crc_sc = os.path.join(scenarios, "link_ber_crc.toml")

    seed, _ = run_report(cncsim, seed_sc, work, "seed")
    faults = seed["fpga-uart"]["faults"]
    packets = faults["packets"]
    check(packets["silently_executed_wrong"] > 0, "the seed's packets: no silent corruption at BER 1e-4")
    check(packets["silently_executed_wrong"] == len(faults["silent"]), "one record per silent corruption")
    for c in faults["silent"]:
        want = [c["executed"]["steps"][k] - c["sent"]["steps"][k] for k in range(2)]
        check(c["error_steps"] == want, "segment %d: error %s, fields give %s" % (c["segment"], c["error_steps"], want))
        check(c["executed"] != c["sent"], "segment %d listed but ran as sent" % c["segment"])
    off = faults["job_end_error_steps"]
    tally_um = 1000.0 * math.hypot(off[0], off[1]) / STEPS_PER_MM
    measured_um = seed["metrics"]["path"]["job_end_um"]
    check(tally_um > 0.0, "the corruptions left no steps at the job's end")
    check(abs(tally_um - measured_um) < 0.01,
          "job end: %.3f um from the packets, %.3f um measured by the metrics" % (tally_um, measured_um))
    print("seed protocol: %d run wrong, %d lost, end %.3f um (metrics %.3f um)"
          % (packets["silently_executed_wrong"], packets["lost"], tally_um, measured_um))

    run_report(cncsim, seed_sc, work, "seed_again")
    check(filecmp.cmp(os.path.join(work, "seed.json"), os.path.join(work, "seed_again.json"), shallow=False),
          "the same seed gave another report")

    crc, _ = run_report(cncsim, crc_sc, work, "crc")
    cf = crc["fpga-uart"]["faults"]
    check(cf["packets"]["silently_executed_wrong"] == 0, "with the CRC a packet ran wrong")
    check(cf["packets"]["lost"] == 0 and cf["packets"]["extra"] == 0, "with the CRC a packet was lost or ran twice")
    check(cf["packets"]["executed_as_sent"] == cf["packets"]["sent"], "with the CRC not every packet ran")
    check(crc["metrics"]["path"]["job_end_um"] == 0.0, "with the CRC the tool ends off the programmed point")
    check(cf["retransmitted"] > 0 and cf["detected"]["crc_errors"] > 0, "with the CRC nothing was detected or resent")

    clean, _ = run_report(cncsim, seed_sc, work, "clean", sets=["faults.uart_ber=0"])
    clean_crc, _ = run_report(cncsim, crc_sc, work, "clean_crc", sets=["faults.uart_ber=0"])
    n = clean["fpga-uart"]["sender"]["packets_sent"]
    check(clean["fpga-uart"]["link"]["bytes_to_fpga"] == 9 + 11 * n, "the seed's frames are not 9 + 11 per packet")
    check(clean_crc["fpga-uart"]["link"]["bytes_to_fpga"] == 11 + 13 * n, "the checked frames are not 11 + 13")
    t_seed = clean["metrics"]["job"]["job_time_s"]
    t_crc = clean_crc["metrics"]["job"]["job_time_s"]
    t_faults = crc["metrics"]["job"]["job_time_s"]
    check(t_crc >= t_seed, "two more bytes a packet made the job shorter")
    print("job time: seed %.3f s, with the CRC %.3f s (+%.2f %%), with the CRC at BER 1e-4 %.3f s (%d sent again)"
          % (t_seed, t_crc, 100.0 * (t_crc / t_seed - 1.0), t_faults, cf["retransmitted"]))
    # A host stall of 2 s at 5 s: the script is held up from the first thing it had to do in the stall (read an ACK)
    # to its end, and the job is that much longer, within one USB frame (the writes after it find another phase of
    # the 1 ms frames).
    stall, _ = run_report(cncsim, seed_sc, work, "stall",
                          sets=["faults.uart_ber=0", "faults.host_stall_at_s=5", "faults.host_stall_s=2"])
    held = stall["fpga-uart"]["faults"]["host_stall"]["host_held_up_s"]
    longer = stall["metrics"]["job"]["job_time_s"] - t_seed
    check(1.9 < held <= 2.0, "a 2 s stall held the host up %.4f s" % held)
    check(abs(longer - held) <= 0.001, "the stall held the host up %.4f s, the job took %.4f s longer" % (held, longer))
    check(stall["fpga-uart"]["faults"]["packets"]["executed_as_sent"] == n, "a stall lost a packet")
    print("host stall: held up %.4f s, job %.4f s longer" % (held, longer))
    print("PASS")


if __name__ == "__main__":
    main()
