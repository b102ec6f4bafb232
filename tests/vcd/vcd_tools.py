"""What the VCD tests share: running cncsim, running sigrok-cli (the independent reader) and reading what its
protocol decoders print. A missing sigrok-cli is a failure, not a skip: scripts/setup.sh installs it."""
import json
import os
import subprocess
import sys

# On exact clocks (clock.ideal) cncsim writes its VCDs at 100 ps, which sigrok's VCD input takes as 10 GHz sampling;
# these factors bring that down to what each decoder needs. (An oscillator's jitter puts the edges on whole
# picoseconds and the VCD at 1 ps: docs/metrics.md, "Clocks".)
DOWNSAMPLE_TO_10MHZ = 1000  # UART bits of 8.7 us (115200 Bd) and 17 us (57600 Bd): 87+ samples per bit
DOWNSAMPLE_TO_25MHZ = 400   # SPI at SCLK 5 MHz: 5 samples per clock period


def fail(message):
    sys.exit("FAIL: " + message)


def run_cncsim(cncsim, workdir, name, scenario, *extra):
    """`cncsim run` with a VCD and a --detail report in workdir; returns (vcd path, report)."""
    os.makedirs(workdir, exist_ok=True)
    vcd = os.path.join(workdir, name + ".vcd")
    report = os.path.join(workdir, name + ".json")
    cmd = [cncsim, "run", scenario, "--vcd", vcd, "--report", report, "--detail", "--progress", "off",
           "--set", "clock.ideal=true", *extra]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        fail("%s: exit %d\n%s" % (" ".join(cmd), run.returncode, run.stderr))
    with open(report) as f:
        return vcd, json.load(f)


def analyze(cncsim, vcd, report, *options):
    """`cncsim analyze` of vcd with the given options; returns its JSON report."""
    cmd = [cncsim, "analyze", vcd, "--report", report, *options]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        fail("%s: exit %d\n%s" % (" ".join(cmd), run.returncode, run.stderr))
    with open(report) as f:
        return json.load(f)


def sigrok_cli(*args):
    """sigrok-cli's stdout; fails when it is missing or reports an error."""
    try:
        run = subprocess.run(["sigrok-cli", *args], capture_output=True, text=True)
    except FileNotFoundError:
        fail("sigrok-cli is not installed (scripts/setup.sh installs it: apt-get install sigrok-cli)")
    if run.returncode != 0 or run.stderr.strip():
        fail("sigrok-cli %s: exit %d\n%s" % (" ".join(args), run.returncode, run.stderr))
    return run.stdout


def decode(vcd, downsample, decoder, annotation):
    """What one annotation class of a sigrok decoder prints for the VCD, one list of byte values per line
    ("uart-1: AA" -> [0xAA], "spi-1: 52 80 09 89 68 ..." -> [0x52, 0x80, ...])."""
    out = sigrok_cli("-i", vcd, "-I", "vcd:downsample=%d" % downsample, "-P", decoder, "-A", annotation)
    return [[int(b, 16) for b in line.split(":", 1)[1].split()] for line in out.splitlines() if line.strip()]


def expect_equal(what, got, expected):
    if got != expected:
        fail("%s: %s, expected %s" % (what, got, expected))
