#!/usr/bin/python3
"""LinuxCNC [DISPLAY] program for cncsim_ref.ini: run one G-code job headless and sample it.

Environment: LCNC_JOB (the .ngc, absolute path), LCNC_SAMPLES (output file of halsampler -t).
Steps: estop reset, machine on, home all (HOME_SEARCH_VEL = 0: homes in place), start halsampler,
AUTO_RUN the program, wait until the interpreter is idle and motion is in position, let 0.3 s of idle
samples accumulate, stop halsampler (SIGINT), exit (LinuxCNC then shuts down).
"""
import os, signal, subprocess, sys, time
import linuxcnc

job = os.environ["LCNC_JOB"]
out = os.environ["LCNC_SAMPLES"]
s, c, e = linuxcnc.stat(), linuxcnc.command(), linuxcnc.error_channel()

def wait(pred, timeout, what):
    t0 = time.time()
    while time.time() - t0 < timeout:
        s.poll()
        if pred():
            return
        err = e.poll()
        if err:
            print("linuxcnc error:", err, file=sys.stderr)
        time.sleep(0.02)
    sys.exit("timeout waiting for " + what)

for _ in range(200):
    try:
        s.poll(); break
    except linuxcnc.error:
        time.sleep(0.1)
c.state(linuxcnc.STATE_ESTOP_RESET); c.wait_complete()
c.state(linuxcnc.STATE_ON); c.wait_complete()
wait(lambda: s.task_state == linuxcnc.STATE_ON, 10, "machine on")
c.mode(linuxcnc.MODE_MANUAL); c.wait_complete()
c.home(-1); c.wait_complete()
wait(lambda: all(s.homed[i] for i in range(3)), 10, "homing")
time.sleep(0.2)
with open(out, "w") as f:
    sampler = subprocess.Popen(["halsampler", "-t"], stdout=f)
    time.sleep(0.3)
    c.mode(linuxcnc.MODE_AUTO); c.wait_complete()
    c.program_open(job); c.wait_complete()
    c.auto(linuxcnc.AUTO_RUN, 0)
    wait(lambda: s.interp_state != linuxcnc.INTERP_IDLE, 10, "program start")
    wait(lambda: s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0 and s.inpos, 300, "program end")
    time.sleep(0.3)
    sampler.send_signal(signal.SIGINT)
    sampler.wait(5)
err = e.poll()
if err:
    print("linuxcnc error:", err, file=sys.stderr)
print("drive_job: done", job, file=sys.stderr)
