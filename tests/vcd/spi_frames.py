#!/usr/bin/env python3
"""The spi-fpga frames, as sigrok-cli's `spi` decoder (mode 0, SS active low) reads them from cncsim's VCD, equal
what the host's servo thread sent and what the FPGA answered, as the run's report (--detail rate log) has them.

MOSI, one frame per transfer (models/spi/README.md): 9 bytes, command 0x52, then a big-endian rate word per axis:
bit 31 the direction (1 = forward), bit 30 the laser in the X word (reserved 0 in the Y word), bits 29..0 the
pulse period in FPGA clocks (0 = stopped). The report's rate log gives the period of every servo period, signed
by the direction; the laser bit is not in it, so the frames carrying it are counted against the laser pin's on time
(one 1 ms servo period each, within two periods).
MISO: the status byte (bit 7 always 1) and each axis's step counter; the host reads them as the feedback of the
next servo period, the rate log's count.

Usage: spi_frames.py CNCSIM SCENARIO WORKDIR
"""
import sys

from vcd_tools import DOWNSAMPLE_TO_25MHZ, decode, expect_equal, fail, run_cncsim

SPI = "spi:clk=sclk:mosi=mosi:miso=miso:cs=ss:cpol=0:cpha=0:cs_polarity=active-low"
CMD_RATES = 0x52
DIR_FORWARD = 1 << 31
LASER_ON = 1 << 30
PERIOD_MASK = (1 << 30) - 1
STATUS_ALIVE = 0x80
AXES = ("x", "y")


def words(frame):
    return [int.from_bytes(bytes(frame[1 + 4 * a:5 + 4 * a]), "big") for a in range(len(AXES))]


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    cncsim, scenario, workdir = sys.argv[1:]
    # The SPI wires are driven bit by bit, and traced, only when asked for (trace.signals names them).
    vcd, report = run_cncsim(cncsim, workdir, "spi_fpga", scenario,
                             "--set", 'trace.signals=["sclk", "mosi", "miso", "ss"]')
    mosi = decode(vcd, DOWNSAMPLE_TO_25MHZ, SPI, "spi=mosi-transfer")
    miso = decode(vcd, DOWNSAMPLE_TO_25MHZ, SPI, "spi=miso-transfer")
    details = report["spi-fpga"]
    log = details["rate_log"]
    expect_equal("frames decoded, MOSI", len(mosi), details["spi"]["transfers"])
    expect_equal("frames decoded, MISO", len(miso), details["spi"]["transfers"])
    # Every servo period sends a frame but the last, which finds the job done.
    expect_equal("rate log periods", log["mode"][len(mosi):], ["done"])

    laser_frames = 0
    for i, frame in enumerate(mosi):
        if len(frame) != 9 or frame[0] != CMD_RATES:
            fail("MOSI frame %d: %s is not 9 bytes starting 0x52" % (i, bytes(frame).hex(" ")))
        for a, (axis, word) in enumerate(zip(AXES, words(frame))):
            period = word & PERIOD_MASK
            signed = period if word & DIR_FORWARD else -period
            expect_equal("MOSI frame %d, %s period (signed by DIR)" % (i, axis), signed,
                         log["axes"][axis]["period_cycles"][i])
            if a > 0 and word & LASER_ON:
                fail("MOSI frame %d: the reserved bit 30 of the %s word is set" % (i, axis))
        laser_frames += 1 if words(frame)[0] & LASER_ON else 0
        reply = miso[i]
        if len(reply) != 9 or not reply[0] & STATUS_ALIVE:
            fail("MISO frame %d: %s is not 9 bytes with the alive bit" % (i, bytes(reply).hex(" ")))
        for axis, count in zip(AXES, words(reply)):
            expect_equal("MISO frame %d, %s count" % (i, axis), count,
                         log["axes"][axis]["count"][i + 1] & 0xFFFFFFFF)

    period_ms = details["servo"]["period_us"] / 1000.0
    laser_on_ms = report["metrics"]["laser"]["on_ms"]
    if abs(laser_frames * period_ms - laser_on_ms) > 2 * period_ms:
        fail("%d frames with the laser bit (%.3f ms) against the laser pin on for %.3f ms"
             % (laser_frames, laser_frames * period_ms, laser_on_ms))
    print("spi-fpga: %d frames, MOSI and MISO as sent; %d with the laser bit (pin on %.3f ms)"
          % (len(mosi), laser_frames, laser_on_ms))


if __name__ == "__main__":
    main()
