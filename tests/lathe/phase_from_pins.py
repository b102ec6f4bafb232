#!/usr/bin/env python3
"""The lathe's phase error between passes, read again without the code under test (docs/metrics.md "Lathe").

Reads the outputs of scenarios/lathe-sync/m6_thread.toml run with --vcd, --samples and --report (the ctest
fixture scenario/lathe.m6_outputs), and finds the passes from the
ATmega16's pins alone: a pass starts at the index fall after which OC1A starts switching (doCut starts the PID
there, seed 002 §2.5.3) and ends when DIR1 == DIR2 (doBrake). The carriage at each spindle pulse comes from the
samples (taken by the rig at the encoders' edges, at the edge's cycle), the motor pulses from INT0's falls.

Checks:
  1. The report's phase error max equals the carriage difference at the same spindle pulse, pass k - pass 1,
     after the settle revolutions, inside the common length, to 0.01 um: both read the same carriage at the same
     cycle, and the CSV carries x to 1e-9 mm. Its pass, revolution and sign are the report's too.
  2. Read from the pins alone (INT0 falls counted with the direction DIR1/DIR2 drive), the same max is within
     2 motor pulses: each count steps once per pulse, so it lies within one pulse of the carriage (plus a constant)
     and a difference of two passes within two.
  3. The firmware's input does not part company with the carriage: over each pass the INT0 falls since the pass's
     start equal the carriage's advance in motor pulses (3.175 mm / 780, seed 002 §2.5.3) within one pulse at every
     spindle pulse, so no motor pulse is lost or added at the pins.
  4. The explanation of the figure: the max is a later pass running ahead of pass 1 in mid-pass (after the settle
     revolutions), more than 20 pulses, for less than one revolution (fewer than 40 spindle pulses over 10
     pulses), and the passes end within 2 pulses (the bound of docs/architectures.md "lathe-sync").
  5. With lathe.pulse_isrs = "atomic" the settled phase error stays below 12 pulses.

Usage: phase_from_pins.py CNCSIM SOURCE_DIR M6_OUTPUTS WORKDIR
(M6_OUTPUTS: m6.vcd, m6_samples.csv and m6.json of that run; WORKDIR: the lathe.pulse_isrs = "atomic" run's report)
"""
import bisect
import csv
import json
import os
import subprocess
import sys

SPINDLE_SLOTS = 40  # seed 002 §2.5.3 SP_PPR
MM_PER_PULSE = 3.175 / 780  # leadscrew pitch over the motor pulses per leadscrew revolution (seed 002 §2.5.3)
PS_PER_VCD_TICK = 100  # the VCD's $timescale 100 ps (checked below)
SIGNALS = ("oc1a_ena_pd5", "dir1_in1_pd0", "dir2_in2_pd1", "int0_motor_pd2", "int1_spindle_pd3", "index_pd6")


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(cncsim, source, args):
    p = subprocess.run([cncsim, "run", os.path.join(source, "scenarios/lathe-sync/m6_thread.toml"),
                        "--progress", "off"] + args, capture_output=True, text=True)
    if p.returncode != 0:
        fail("cncsim exited %d: %s" % (p.returncode, p.stderr))


def read_vcd(path):
    """[(t_ps, name, level)] for SIGNALS, in file order."""
    ids, events, t = {}, [], 0
    with open(path) as f:
        for line in f:
            w = line.split()
            if w[:1] == ["$timescale"] and w[1:3] != ["100", "ps"]:
                fail("VCD timescale %s, expected 100 ps" % w[1:3])
            if w[:1] == ["$var"] and w[4] in SIGNALS:
                ids[w[3]] = w[4]
            if w[:1] == ["$enddefinitions"]:
                break
        for line in f:
            if line[0] == "#":
                t = int(line[1:]) * PS_PER_VCD_TICK
            elif line[0] in "01" and line[1:].strip() in ids:
                events.append((t, ids[line[1:].strip()], line[0] == "1"))
    return events


def read_samples(path):
    """[(t_ps, x_mm)]: t_s is printed as whole seconds and 12 decimals, exactly the integer ps."""
    out = []
    with open(path) as f:
        for row in csv.DictReader(f):
            s, frac = row["t_s"].split(".")
            out.append((int(s) * 10**12 + int(frac), float(row["x_mm"])))
    return out


def passes_from_pins(events):
    """[(start_ps, end_ps, [spindle fall ps], [signed INT0 count at those falls])] with the count at the start."""
    level = {n: False for n in SIGNALS}
    level["int1_spindle_pd3"] = True
    sign, count = 1, 0
    index_falls, oc_rises, brakes, spindle = [], [], [], []  # spindle: (t, count after every edge at t)
    i = 0
    while i < len(events):
        t = events[i][0]
        fell = set()
        while i < len(events) and events[i][0] == t:  # every edge of one cycle before the spindle reading
            _, n, v = events[i]
            if level[n] and not v:
                fell.add(n)
            level[n] = v
            if n in ("dir1_in1_pd0", "dir2_in2_pd1"):
                if level["dir1_in1_pd0"] != level["dir2_in2_pd1"]:
                    sign = 1 if level["dir1_in1_pd0"] else -1
                else:
                    brakes.append(t)
            if n == "oc1a_ena_pd5" and v:
                oc_rises.append(t)
            i += 1
        if "int0_motor_pd2" in fell:
            count += sign
        if "index_pd6" in fell:
            index_falls.append((t, count))
        if "int1_spindle_pd3" in fell:
            spindle.append((t, count))
    out = []
    for t, c in index_falls:
        k = bisect.bisect_right(oc_rises, t)
        starts_pid = k < len(oc_rises) and oc_rises[k] - t < 10**9  # within 1 ms: the PWM's first period
        idle_before = k == 0 or t - oc_rises[k - 1] > 5 * 10**11  # nothing switched for 0.5 s
        if not (starts_pid and idle_before):
            continue
        end = brakes[bisect.bisect_right(brakes, t)]
        inner = [(ts, cs) for ts, cs in spindle if t < ts < end]
        out.append((t, end, [ts for ts, _ in inner], [c] + [cs for _, cs in inner]))
    return out


def carriage_at(samples, times_ps, t_ps):
    """The carriage at t: the last sample at or before it."""
    return samples[bisect.bisect_right(times_ps, t_ps) - 1][1]


def phase_max(passes_x, settle):
    """(|max|, signed, pass index, pulse j) of pass k - pass 1 inside the common length, j >= settle revs."""
    lo = max(p[0] for p in passes_x)
    hi = min(p[-1] for p in passes_x)
    best = (0.0, 0.0, 0, 0)
    first = passes_x[0]
    for k in range(1, len(passes_x)):
        for j in range(settle * SPINDLE_SLOTS, min(len(first), len(passes_x[k]))):
            if lo <= first[j] <= hi and lo <= passes_x[k][j] <= hi:
                d = passes_x[k][j] - first[j]
                if abs(d) > best[0]:
                    best = (abs(d), d, k, j)
    return best


def main():
    cncsim, source, outputs, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    vcd, samples_csv = os.path.join(outputs, "m6.vcd"), os.path.join(outputs, "m6_samples.csv")
    report, atomic_report = os.path.join(outputs, "m6.json"), os.path.join(work, "m6_atomic.json")
    run(cncsim, source, ["--set", "lathe.pulse_isrs=atomic", "--report", atomic_report])
    thread = json.load(open(report))["lathe-sync"]["thread"]
    settle = thread["settle_revolutions"]

    samples = read_samples(samples_csv)
    times = [t for t, _ in samples]
    pin_passes = passes_from_pins(read_vcd(vcd))
    if len(pin_passes) != 3:
        fail("%d passes found on the pins, the scenario cuts 3" % len(pin_passes))
    start_x, end_x = carriage_at(samples, times, pin_passes[0][0]), carriage_at(samples, times, pin_passes[0][1])
    cut_sign = 1.0 if end_x > start_x else -1.0
    passes_x, passes_pulses = [], []
    for start, _, falls, counts in pin_passes:
        x = [cut_sign * carriage_at(samples, times, t) for t in [start] + falls]
        passes_x.append(x)
        passes_pulses.append([cut_sign * c for c in counts])

    # 1. The report against the samples.
    um, signed_mm, k, j = phase_max(passes_x, settle)
    um *= 1000.0
    print("from the samples: phase error max %.3f um, pass %d %s pass 1 at revolution %.3f; report: %.3f um, "
          "pass %d at revolution %.3f" % (um, k + 1, "ahead of" if signed_mm > 0 else "behind", j / SPINDLE_SLOTS,
                                          thread["phase_error_max_um"], thread["phase_error_max_pass"],
                                          thread["phase_error_max_revolution"]))
    if abs(um - thread["phase_error_max_um"]) > 0.01:
        fail("report's phase error max %.3f um, the samples give %.3f um" % (thread["phase_error_max_um"], um))
    if (k + 1, j / SPINDLE_SLOTS) != (thread["phase_error_max_pass"], thread["phase_error_max_revolution"]):
        fail("the report puts the max elsewhere")
    if abs(signed_mm * 1000.0 - thread["phase_error_max_signed_um"]) > 0.01:
        fail("the report's signed max %.3f um" % thread["phase_error_max_signed_um"])

    # 2. The pins alone.
    pulses, _, _, _ = phase_max(passes_pulses, settle)
    print("from the pins alone: %d pulses = %.2f um" % (pulses, pulses * MM_PER_PULSE * 1000.0))
    if abs(pulses * MM_PER_PULSE * 1000.0 - um) > 2 * MM_PER_PULSE * 1000.0:
        fail("the pins' count gives %d pulses, more than 2 pulses from the samples' %.3f um" % (pulses, um))

    # 3. The count against the carriage over each pass.
    worst = 0.0
    for x, c in zip(passes_x, passes_pulses):
        for xj, cj in zip(x, c):
            worst = max(worst, abs((cj - c[0]) - (xj - x[0]) / MM_PER_PULSE))
    print("INT0 count - carriage advance: at most %.3f pulses over the passes" % worst)
    if worst >= 1.0:
        fail("the INT0 count and the carriage part company by %.3f pulses" % worst)

    # 4. What the figure is.
    pulses_off = signed_mm / MM_PER_PULSE
    d = [(passes_x[k][i] - passes_x[0][i]) / MM_PER_PULSE for i in range(settle * SPINDLE_SLOTS,
                                                                          min(len(passes_x[0]), len(passes_x[k])))]
    wide = sum(1 for v in d if abs(v) > 10.0)
    end_pulses = thread["phase_error_end_um"] / 1000.0 / MM_PER_PULSE
    print("pass %d runs %.1f pulses ahead of pass 1; over 10 pulses apart for %d spindle pulses; the passes end "
          "%.2f pulses apart" % (k + 1, pulses_off, wide, end_pulses))
    if not (k >= 1 and j >= settle * SPINDLE_SLOTS and pulses_off > 20.0):
        fail("the max is not a later pass running ahead in mid-pass")
    if wide >= SPINDLE_SLOTS:
        fail("the passes stay over 10 pulses apart for %d spindle pulses: not a transient" % wide)
    if end_pulses >= 2.0:
        fail("the passes end %.2f pulses apart" % end_pulses)

    # 5. The seed's atomic-ISR option.
    atomic = json.load(open(atomic_report))["lathe-sync"]["thread"]["phase_error_max_um"]
    print("atomic pulse ISRs: phase error max %.2f um (%.1f pulses)" % (atomic, atomic / 1000.0 / MM_PER_PULSE))
    if atomic / 1000.0 / MM_PER_PULSE >= 12.0:
        fail("with atomic ISRs the settled phase error is %.2f um" % atomic)
    print("OK")


if __name__ == "__main__":
    main()
