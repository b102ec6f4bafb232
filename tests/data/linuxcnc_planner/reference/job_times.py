#!/usr/bin/env python3
"""LinuxCNC's job time of each halsampler file, as times.csv lists it.

A row of NAME.samples (halsampler -t; sampler.0 runs after motion-controller in the 1 ms servo thread, see
sample.hal): sample number, joint.0/1/2.motor-pos-cmd (mm), motion.current-vel, motion.requested-vel (mm/s),
motion.distance-to-go (mm), motion.in-position, motion.motion-type, motion.program-line.

Job time = (the first period after the motion starts whose motion.in-position is 1 again) - (the last period
before the first one with motion.current-vel > 0), in periods of 1 ms.

Usage: job_times.py SAMPLES... > times.csv
"""
import os
import sys

PERIOD_S = 0.001


def job_time_s(path):
    rows = [line.split() for line in open(path)]
    rows = [(float(r[4]), int(r[7])) for r in rows if len(r) == 10]
    first = next(i for i, (v, _) in enumerate(rows) if v > 0.0)
    end = next(i for i in range(first, len(rows)) if rows[i][1] == 1)
    return (end - (first - 1)) * PERIOD_S


print("job,linuxcnc_s")
for path in sorted(sys.argv[1:]):
    print("%s,%.3f" % (os.path.basename(path)[:-len(".samples")], job_time_s(path)))
