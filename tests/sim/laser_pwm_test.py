#!/usr/bin/env python3
"""The laser's PWM on fpga-uart (fpga.laser_pwm): usage CNCSIM SOURCE_DIR WORKDIR.

The grayscale raster of scenarios/improvements (five cuts, each at its own S), with the PWM and with the seed's
on/off laser. Everything expected is computed here from the job's S words and the PWM arithmetic of the keys'
defaults (7812.5 Hz from the 50 MHz clock: 6400 clocks; full power at S 1000), with the FPGA clock's frequency the
report states (its oscillator's drawn offset) to turn clocks into time:
- each cut's laser pulses are S / 1000 of 6400 clocks, rounded to a clock, one every 6400 clocks, from the clock after
  busy rises; S 1000 holds the pin high for the whole move;
- the laser-on time of the run is, over the cuts, the whole periods' high times and the last period's part of one,
  from each cut's busy time in clocks;
- the exposure per mm of lasered path is the seed's (the whole cut lasered) times that on-time over the seed's.
And the e-stop and lid study of scenarios/improvements with the PWM (the square's S255: 1632 of 6400 clocks): the
pin pulses until the lid opens, and is low from three clocks after the lid opens until it closes, and from three
clocks after the e-stop is pressed on (fpga.interlock, fpga.estop).
"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import args_and_workdir, check, run_report  # noqa: E402
from vcd_edges import high_intervals, vcd_edges  # noqa: E402

CLOCK_HZ = 50e6
PWM_HZ = 7812.5  # fpga.laser_pwm_hz's default
S_MAX = 1000.0   # fpga.laser_s_max's default
PERIOD = round(CLOCK_HZ / PWM_HZ)


def job_powers(job):
    """The S of each G1 line of the job, in order (the job programs one on every cut)."""
    out = []
    with open(job) as f:
        for line in f:
            code = line.split(";")[0]
            if re.match(r"\s*G1\b", code):
                out.append(float(re.search(r"S([0-9.]+)", code).group(1)))
    return out


def on_clocks(busy_clocks, high):
    """The clocks the pin is high in a move busy for BUSY_CLOCKS: the count restarts with the move."""
    return (busy_clocks // PERIOD) * high + min(busy_clocks % PERIOD, high)


def check_safety_inputs(cncsim, source, work):
    study = os.path.join(source, "scenarios", "improvements", "estop_square.toml")
    vcd = os.path.join(work, "estop.vcd")
    cmd = [cncsim, "run", study, "--progress", "off", "--set", "fpga.laser_pwm=true", "--vcd", vcd]
    done = subprocess.run(cmd, capture_output=True, text=True)
    check(done.returncode == 1, "the e-stop run exited %d, not 1 (stopped): %s" % (done.returncode, done.stderr))
    clock_ps = 1e12 / CLOCK_HZ
    pulses = high_intervals(vcd_edges(vcd, ["laser"])["laser"])
    lid_open_ps, lid_closed_ps, estop_ps = 1.5e12, 2.0e12, 5.0e12  # the study's [[events]]
    high = round(255.0 / S_MAX * PERIOD)
    before = [p for p in pulses if lid_open_ps - 1e10 < p[0] and p[1] < lid_open_ps]
    check(len(before) > 10 and all(abs((b - a) - high * clock_ps) < clock_ps for a, b in before),
          "the laser does not pulse %d clocks in each period before the lid opens" % high)
    off_by = 3 * clock_ps + clock_ps / 2  # three clocks, within the oscillator's offset and jitter
    for a, b in pulses:
        check(not (a < lid_closed_ps and b > lid_open_ps + off_by), "a pulse at %d-%d ps with the lid open" % (a, b))
        check(b <= estop_ps + off_by, "a pulse at %d-%d ps after the e-stop" % (a, b))
    print("e-stop and lid: the pin pulses %d of %d clocks until the lid opens, and is low within three clocks of "
          "each input" % (high, PERIOD))


def main():
    cncsim, source, work = args_and_workdir()
    study = os.path.join(source, "scenarios", "improvements", "laser_pwm_raster.toml")
    vcd = os.path.join(work, "pwm.vcd")
    pwm, _ = run_report(cncsim, study, work, "pwm", extra=["--vcd", vcd])
    seed, _ = run_report(cncsim, study, work, "seed", sets=["fpga.laser_pwm=false"])
    powers = job_powers(os.path.join(source, "scenarios", "jobs", "raster_grayscale.nc"))
    check(PERIOD == 6400, "the PWM period is %d clocks" % PERIOD)

    clock_ps = 1e12 / pwm["clock"]["hz"]
    edges = vcd_edges(vcd, ["busy", "laser"])
    moves = high_intervals(edges["busy"])
    pulses = high_intervals(edges["laser"])
    check(len(moves) == 2 * len(powers), "%d moves for %d cuts and their rapids" % (len(moves), len(powers)))
    expected_on_ps = 0.0
    seed_on_ps = 0.0
    for cut, s in enumerate(powers):
        rise, fall = moves[2 * cut]  # each cut, then the rapid back
        busy = round((fall - rise) / clock_ps)
        high = round(s / S_MAX * PERIOD)
        mine = [p for p in pulses if rise < p[0] <= fall + clock_ps * 1.5]
        check(mine and abs(mine[0][0] - rise - clock_ps) < 50, "cut %d (S %g): the laser does not rise a clock after "
              "busy" % (cut + 1, s))
        # Held high, one pulse as long as the move; else every pulse but the last (the move's end may cut it short)
        # the high time.
        whole, length = (mine, busy) if high >= PERIOD else (mine[:-1], high)
        check(high < PERIOD or len(mine) == 1, "cut %d (S %g): %d pulses at full power" % (cut + 1, s, len(mine)))
        for a, b in whole:
            check(abs((b - a) - length * clock_ps) < 50,
                  "cut %d (S %g): a pulse of %.1f clocks, not %d" % (cut + 1, s, (b - a) / clock_ps, length))
        for (a, _), (b, _) in zip(mine, mine[1:]):
            check(abs((b - a) - PERIOD * clock_ps) < 50,
                  "cut %d (S %g): pulses %.1f clocks apart" % (cut + 1, s, (b - a) / clock_ps))
        got = sum(b - a for a, b in mine)
        want = on_clocks(busy, min(high, PERIOD)) * clock_ps
        check(abs(got - want) < 50 * len(mine), "cut %d (S %g): %.0f ps on, %.0f expected" % (cut + 1, s, got, want))
        expected_on_ps += want
        seed_on_ps += busy * clock_ps
        print("cut %d: S %g -> %d of %d clocks high (duty %.4f), %d pulses, %.3f ms on of %.3f ms"
              % (cut + 1, s, high, PERIOD, high / PERIOD, len(mine), want * 1e-9, busy * clock_ps * 1e-9))

    on_ms = pwm["metrics"]["laser"]["on_ms"]
    check(abs(on_ms - expected_on_ps * 1e-9) < 1e-5, "laser on %.6f ms, %.6f expected" % (on_ms, expected_on_ps * 1e-9))
    seed_ms = seed["metrics"]["laser"]["on_ms"]
    check(abs(seed_ms - seed_on_ps * 1e-9) < 1e-5, "seed: laser on %.6f ms, %.6f expected" % (seed_ms, seed_on_ps * 1e-9))
    e_pwm = pwm["fpga-uart"]["mechanics"]["laser_exposure"]
    e_seed = seed["fpga-uart"]["mechanics"]["laser_exposure"]
    # The exposure spreads each tool sample interval's on-time over its path: over the job, the on-time expected.
    exposed_s = e_pwm["mean_s_per_mm"] * e_pwm["lasered_path_mm"]
    check(abs(exposed_s - expected_on_ps * 1e-12) < 1e-8,
          "exposure %.6f s/mm over %.4f mm is %.6f s on, %.6f expected" % (e_pwm["mean_s_per_mm"],
                                                                          e_pwm["lasered_path_mm"], exposed_s,
                                                                          expected_on_ps * 1e-12))
    # Against the seed's laser, on for the whole of each cut: the same path within the carriage's settling after a
    # cut (the seed's laser is on to the move's last clock, the PWM's may be off in its last period), so the ratio of
    # the exposures is the ratio of the on-times within that share.
    ratio = expected_on_ps / seed_on_ps
    path_share = abs(e_pwm["lasered_path_mm"] / e_seed["lasered_path_mm"] - 1)
    check(path_share < 0.01, "lasered path %.4f mm with the PWM, %.4f mm without" % (e_pwm["lasered_path_mm"],
                                                                                    e_seed["lasered_path_mm"]))
    check(abs(e_pwm["mean_s_per_mm"] / e_seed["mean_s_per_mm"] / ratio - 1) < 2 * path_share + 1e-6,
          "exposure %.6f s/mm with the PWM, %.6f without: %.4f of it, the on-times %.4f" % (
              e_pwm["mean_s_per_mm"], e_seed["mean_s_per_mm"], e_pwm["mean_s_per_mm"] / e_seed["mean_s_per_mm"],
              ratio))
    check_safety_inputs(cncsim, source, work)
    print("laser on %.3f ms with the PWM, %.3f ms without; exposure %.5f s/mm against %.5f s/mm over %.2f mm"
          % (on_ms, seed_ms, e_pwm["mean_s_per_mm"], e_seed["mean_s_per_mm"], e_pwm["lasered_path_mm"]))


if __name__ == "__main__":
    main()
