#!/usr/bin/env python3
"""The bytes on a UART link, as sigrok-cli's `uart` decoder reads them from cncsim's VCD, equal the bytes the host
model sent and the controller answered, recomputed here from the job and the seeds' documented packet layouts.

fpga-uart STEPS_SCENARIO: uart_rx (host -> FPGA) carries seed 000's init packet FF 01 1E 1A 30 01 1E 1A 30
(NUMERATOR 18 750 000 for both axes: §4.9, tests/host/seed000_golden_test.cpp), then one 11-byte motion
packet per row of the scenario's steps file, packed as send_steps.py does (struct ">BiiH": motion, StepsX, StepsY,
FeedRate; §4.9); uart_tx (FPGA -> host) one ACK 0xAA per completed packet.
atmega SCENARIO (scenarios/atmega/speed_10_45.toml, "G1 X20.000 F10.45" in mm/s, then M30): uart_rx carries the
seed 003 G01 command 01 80 0C 03 FF D2 (ID 0x01; X count 3200 = 20 mm x 160 steps/mm, low byte first; OCR0A 3 for
10.45 mm/s, eqs. 5.1-5.2; OCR2A 255, Y idle; PORTB 0xD2 = '1' '1' DIR_Y 0 EN_Y 1 STEP_Y 0 EN_X 0 HEADER 1 DIR_X 0)
and M30 0x3B (Table 5.1, tests/atmega/cad2g_plan_test.cpp); uart_tx one confirm 0x06 before every byte the MCU
reads (protocol.h).
Both directions are also counted against the run's report. Baud rates are the report's (the CP2102's line rate
for uart_rx, the controller's own for uart_tx).

Usage: uart_bytes.py CNCSIM fpga-uart|atmega SCENARIO WORKDIR
"""
import csv
import os
import struct
import sys
import tomllib

from vcd_tools import DOWNSAMPLE_TO_10MHZ, decode, expect_equal, run_cncsim

SEED000_INIT = bytes.fromhex("FF 01 1E 1A 30 01 1E 1A 30")
SEED000_ACK = 0xAA
PC_BYTES_SPEED_10_45 = bytes.fromhex("01 80 0C 03 FF D2 3B")
LASER_ENGRAVER_CONFIRM = 0x06
FPGA_CLOCK_HZ = 50_000_000  # seed 000 CLOCK_50: the FPGA's uart_tx bit is 434 of its clocks


def job_of(scenario):
    """The scenario's job file (scenario.job, relative to the scenario)."""
    with open(scenario, "rb") as f:
        return os.path.join(os.path.dirname(scenario), tomllib.load(f)["scenario"]["job"])


def seed000_packets(steps_file):
    packets = []
    with open(steps_file) as f:
        for row in csv.DictReader(f):
            packets.append(struct.pack(">BiiH", int(row["Motion"]), int(row["StepsX"]), int(row["StepsY"]),
                                       int(row["FeedRate"])))
    return packets


def line_bytes(vcd, pin, baud):
    annotation = "rx-data" if pin == "uart_rx" else "tx-data"
    channel = "rx" if pin == "uart_rx" else "tx"
    decoder = "uart:%s=%s:baudrate=%d" % (channel, pin, round(baud))
    return [b[0] for b in decode(vcd, DOWNSAMPLE_TO_10MHZ, decoder, "uart=" + annotation)]


def check_fpga_uart(cncsim, scenario, workdir):
    vcd, report = run_cncsim(cncsim, workdir, "fpga_uart", scenario)
    packets = seed000_packets(job_of(scenario))
    link = report["fpga-uart"]["link"]
    sent = line_bytes(vcd, "uart_rx", link["line_baud"])
    acks = line_bytes(vcd, "uart_tx", FPGA_CLOCK_HZ / link["fpga_bit_cycles"])
    expect_equal("host -> FPGA bytes", bytes(sent).hex(" "), (SEED000_INIT + b"".join(packets)).hex(" "))
    expect_equal("FPGA -> host bytes", acks, [SEED000_ACK] * len(packets))
    expect_equal("bytes to the FPGA in the report", link["bytes_to_fpga"], len(sent))
    expect_equal("bytes from the FPGA in the report", link["bytes_from_fpga"], len(acks))
    print("fpga-uart: %d bytes to the FPGA (init + %d packets), %d ACKs, as sent" % (len(sent), len(packets),
                                                                                     len(acks)))


def check_atmega(cncsim, scenario, workdir):
    vcd, report = run_cncsim(cncsim, workdir, "atmega", scenario)
    link = report["atmega"]["link"]
    sent = line_bytes(vcd, "uart_rx", link["line_baud"])
    confirms = line_bytes(vcd, "uart_tx", link["mcu_baud"])
    expect_equal("PC -> MCU bytes", bytes(sent).hex(" "), PC_BYTES_SPEED_10_45.hex(" "))
    expect_equal("MCU -> PC bytes", confirms, [LASER_ENGRAVER_CONFIRM] * len(PC_BYTES_SPEED_10_45))
    expect_equal("bytes to the MCU in the report", link["bytes_to_mcu"], len(sent))
    expect_equal("bytes from the MCU in the report", link["bytes_from_mcu"], len(confirms))
    print("atmega: %s to the MCU, %d confirms, as sent" % (bytes(sent).hex(" "), len(confirms)))


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    cncsim, arch, scenario, workdir = sys.argv[1:]
    {"fpga-uart": check_fpga_uart, "atmega": check_atmega}[arch](cncsim, scenario, workdir)


if __name__ == "__main__":
    main()
