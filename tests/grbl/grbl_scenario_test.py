#!/usr/bin/env python3
"""The grbl architecture with our grbl-protocol test firmware, through `cncsim run`.

Usage: grbl_scenario_test.py MODE CNCSIM SOURCE_DIR FIRMWARE_ELF FIRMWARE_HEX [--set KEY=VALUE ...]
  (the --set options go to every run: --set avr.mcu=atmega16 with the firmware built for the ATmega16)
  square    the 20 mm square: 9600 STEP pulses on each axis that the drivers take (10 + 20 + 20 + 10 mm at 160
            steps/mm, counted here from the report's edges), every line answered, the job ends on a status report
            that says Idle at machine 0,0, no error.
  error     a line the firmware does not support (M8, coolant) in a lenient run: reported as a warning at its G-code
            line with grbl's error:20, and the job goes on to its end.
  setting   a setting the firmware refuses ($999=1): exit 2, the message names the setting and where it was set.
  hex       the firmware's Intel HEX image (avr-objcopy's) runs as its ELF does: the same report but for the file name.
  jitter    software STEP jitter: G1 X10 Y3 F300, Bresenham in the Timer1 ISR. X (dominant) steps every ISR, the
            period the firmware computes in float32 (emulated here: 20881 cycles); Y steps on the ISRs where its
            Bresenham counter overflows, so its periods are 3 or 4 ISR periods. The report's Y period jitter
            (peak to peak) and TIE (max and rms, against the least-squares grid) equal what that pattern predicts
            within one cycle (62.5 ns, ideal clock), and are far above it; X's are within one cycle of 0. The
            status interval is longer than the move, so no serial interrupt delays an ISR.
  laser     laser power from OC2A: in laser mode ($32 = 1, from the job's M3 S), G1 X10 F600 at S250, S500 and S1000
            ($30 = 1000). The firmware's compare value is floor(S x 255 / $30), and fast PWM at clk/8 sets OC2A at
            BOTTOM and clears it at the match: high (OCR2A + 1) x 8 of every 2048 cycles (ATmega328P datasheet
            §18.7.3; the ATmega16's OCR2 on OC2 the same, doc2466 Timer2 "Fast PWM Mode"), 25 %, 50 %; OCR2A = 255
            = MAX holds it high (100 %). The PWM periods' high times, read from
            the VCD, are that to the cycle, every one of them, and the report's laser-on time follows the duty (each run's against the S1000 run's, within 1 %).
"""
import math
import struct
import json
import os
import subprocess
import sys
import tempfile


COMMON_SETS = []


def run(cncsim, source, scenario, firmware, extra):
    report = tempfile.NamedTemporaryFile(suffix=".json", delete=False).name
    os.remove(report)
    args = [cncsim, "run", scenario, "--set", "avr.firmware=" + firmware, "--report", report,
            "--progress", "off"] + COMMON_SETS + extra
    p = subprocess.run(args, cwd=source, capture_output=True, text=True)
    data = None
    if os.path.exists(report):
        with open(report) as f:
            data = json.load(f)
        os.remove(report)
    return p, data


def f32(x):
    """x rounded to the AVR's float (IEEE single precision)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def firmware_isr_cycles(dx_mm, dy_mm, steps_per_mm, feed_mm_per_min):
    """The test firmware's stepper ISR period (gcode.c queue_move), in its float32 arithmetic, at 16 MHz."""
    spm = f32(steps_per_mm)
    dx, dy = round(dx_mm * steps_per_mm), round(dy_mm * steps_per_mm)
    dxm, dym = f32(dx / spm), f32(dy / spm)
    length = f32(math.sqrt(f32(f32(dxm * dxm) + f32(dym * dym))))
    events = max(dx, dy)
    per_s = f32(f32(f32(f32(feed_mm_per_min) / f32(60.0)) * f32(float(events))) / length)
    return int(f32(f32(16e6 / per_s) + f32(0.5)))


def bresenham_ticks(events, steps):
    """The ISR numbers (1-based) at which the subordinate axis steps: its counter starts at -(events / 2) and
    gains `steps` per ISR; past 0 it steps and loses `events` (motion.c)."""
    counter, out = -(events >> 1), []
    for tick in range(1, events + 1):
        counter += steps
        if counter > 0:
            counter -= events
            out.append(tick)
    return out


def tie(times):
    """Largest and RMS distance of the edges from their least-squares grid a + b k."""
    n = len(times)
    k_mean, t_mean = (n - 1) / 2, sum(times) / n
    b = sum((k - k_mean) * (t - t_mean) for k, t in enumerate(times)) / sum((k - k_mean) ** 2 for k in range(n))
    res = [t - (t_mean + b * (k - k_mean)) for k, t in enumerate(times)]
    return max(abs(e) for e in res), math.sqrt(sum(e * e for e in res) / n)


def high_times_cycles(vcd, signal):
    """Each high stretch of a 1-bit VCD signal, in 16 MHz cycles (62.5 ns)."""
    ids, scale_ps, t, rise, out = {}, None, 0, None, []
    lines = iter(open(vcd))
    for line in lines:
        if line.startswith("$timescale"):
            text = line.split()[1:-1] if "$end" in line else next(lines).split()
            value, unit = text[0], text[1] if len(text) > 1 else ""
            number = int("".join(c for c in value if c.isdigit()))
            unit = unit or value.lstrip("0123456789")
            scale_ps = number * {"fs": 1e-3, "ps": 1, "ns": 1e3, "us": 1e6}[unit]
        elif line.startswith("$var"):
            fields = line.split()
            ids[fields[3]] = fields[4]
        elif line.startswith("#"):
            t = int(line[1:]) * scale_ps
        elif line[:1] in "01" and ids.get(line[1:].strip()) == signal:
            if line[0] == "1":
                rise = t
            elif rise is not None:
                out.append(round((t - rise) / 62500.0))
    return out


def check(cond, what):
    if not cond:
        print("FAIL:", what)
        sys.exit(1)
    print("ok:", what)


def main():
    mode, cncsim, source, firmware, hex_image = sys.argv[1:6]
    COMMON_SETS.extend(sys.argv[6:])
    scenario = "tests/data/grbl/square_20mm.toml"
    if mode == "square":
        p, r = run(cncsim, source, scenario, firmware, [])
        check(p.returncode == 0, "exit 0 (stderr: %s)" % p.stderr.strip())
        for a in r["metrics"]["axes"]:
            check(a["rising_edges"] == 9600, "%s: %d STEP pulses taken, 9600 expected" % (a["axis"], a["rising_edges"]))
        sender = r["grbl"]["sender"]
        check(sender["lines_sent"] == 10 and sender["lines_answered"] == 10,
              "10 lines sent and answered (%d, %d)" % (sender["lines_sent"], sender["lines_answered"]))
        check(sender["last_status"].startswith("<Idle|MPos:0.000,0.000,"), "ends Idle at 0,0: " + sender["last_status"])
        check(sender["errors"] == [], "no error")
    elif mode == "error":
        job = os.path.join(tempfile.mkdtemp(), "with_m8.nc")
        with open(job, "w") as f:
            f.write("G21 G90\nG1 X2 Y1 F600\nM8\nG1 X0 Y0\n")
        p, r = run(cncsim, source, scenario, firmware, ["--set", "scenario.job=" + job])
        check(p.returncode == 0, "exit 0 (stderr: %s)" % p.stderr.strip())
        errors = r["grbl"]["sender"]["errors"]
        check(errors == [{"where": job + ":3", "line": "M8", "answer": "error:20"}], "M8 answered error:20: %s" % errors)
        warnings = [w for w in r["warnings"] if w["kind"] == "grbl_error"]
        check(len(warnings) == 1 and warnings[0]["first"] == [job + ":3"], "a warning at its line: %s" % warnings)
        check(r["grbl"]["sender"]["last_status"].startswith("<Idle|MPos:0.000,0.000,"),
              "the job went on to its end")
    elif mode == "setting":
        p, r = run(cncsim, source, scenario, firmware, ["--set", 'grbl.settings=["$999=1"]'])
        check(p.returncode == 2, "exit 2, got %d" % p.returncode)
        check("$999=1" in p.stderr and "--set grbl.settings" in p.stderr and "error:3" in p.stderr,
              "the message names the setting: " + p.stderr.strip())
        check(r is None, "no report")
    elif mode == "hex":
        p_elf, r_elf = run(cncsim, source, scenario, firmware, [])
        p_hex, r_hex = run(cncsim, source, scenario, hex_image, [])
        check(p_elf.returncode == 0 and p_hex.returncode == 0, "both run")
        check(r_hex["grbl"]["firmware"] == hex_image, "the report names the HEX file")
        r_hex["grbl"]["firmware"] = r_elf["grbl"]["firmware"]
        check(r_hex == r_elf, "the HEX run's report equals the ELF run's")
    elif mode == "jitter":
        job = os.path.join(tempfile.mkdtemp(), "diagonal.nc")
        with open(job, "w") as f:
            f.write("G21 G90\nG1 X10 Y3 F300\n")
        p, r = run(cncsim, source, scenario, firmware, ["--set", "scenario.job=" + job, "--set", "clock.ideal=true",
                                                          "--set", "grbl.status_interval_ms=3000"])
        check(p.returncode == 0, "exit 0 (stderr: %s)" % p.stderr.strip())
        cycle_ns = 62.5
        period_cycles = firmware_isr_cycles(10.0, 3.0, 160.0, 300.0)
        ticks = bresenham_ticks(1600, 480)
        y_ns = [k * period_cycles * cycle_ns for k in ticks]
        periods = [b - a for a, b in zip(y_ns, y_ns[1:])]
        pp, tie_max, tie_rms = max(periods) - min(periods), *tie(y_ns)
        axes = {a["axis"]: a for a in r["metrics"]["axes"]}
        y, x = axes["y"], axes["x"]
        print("ISR period %d cycles; Y predicted p-p %.1f ns, TIE max %.1f rms %.1f; report %.1f, %.1f, %.1f" %
              (period_cycles, pp, tie_max, tie_rms, y["jitter_pp_max_ns"], y["tie_max_ns"], y["tie_rms_max_ns"]))
        check(y["rising_edges"] == 480 and x["rising_edges"] == 1600, "1600 X and 480 Y steps")
        check(pp > 100 * cycle_ns and abs(y["jitter_pp_max_ns"] - pp) <= cycle_ns, "Y period jitter as predicted")
        check(abs(y["tie_max_ns"] - tie_max) <= cycle_ns, "Y TIE max as predicted")
        check(abs(y["tie_rms_max_ns"] - tie_rms) <= cycle_ns, "Y TIE rms as predicted")
        check(x["jitter_pp_max_ns"] <= cycle_ns and x["tie_max_ns"] <= cycle_ns, "X: no jitter beyond a cycle")
    elif mode == "laser":
        on_ms = {}
        for power in (250, 500, 1000):
            folder = tempfile.mkdtemp()
            job = os.path.join(folder, "line.nc")
            vcd = os.path.join(folder, "line.vcd")
            with open(job, "w") as f:
                f.write("G21 G90\nM3 S%d\nG1 X10 F600\nM5\n" % power)
            p, r = run(cncsim, source, scenario, firmware, ["--set", "scenario.job=" + job, "--set", "clock.ideal=true",
                                                              "--set", 'grbl.settings=["$30=1000"]', "--vcd", vcd])
            check(p.returncode == 0, "S%d: exit 0 (stderr: %s)" % (power, p.stderr.strip()))
            ocr = power * 255 // 1000
            highs = high_times_cycles(vcd, "laser")
            if ocr == 255:
                check(len(highs) == 1, "S%d: OCR2A 255, the pin held high through the move (%d pulses)" %
                      (power, len(highs)))
            else:
                inner = highs[1:-1]  # the first and last are cut by the block's start and end
                want = (ocr + 1) * 8
                exact = sum(1 for h in inner if h == want)
                check(len(inner) > 1000 and exact == len(inner),
                      "S%d: OCR2A %d, PWM periods high %d cycles: %d of %d (%s)" %
                      (power, ocr, want, exact, len(inner), sorted(set(inner))))
            on_ms[power] = r["metrics"]["laser"]["on_ms"]
        for power in (250, 500):
            duty = (power * 255 // 1000 + 1) / 256
            ratio = on_ms[power] / on_ms[1000]
            check(abs(ratio - duty) < 0.01 * duty, "S%d: laser on %.3f ms, %.4f of S1000's, duty %.4f" %
                  (power, on_ms[power], ratio, duty))
    else:
        sys.exit("unknown mode " + mode)


if __name__ == "__main__":
    main()
