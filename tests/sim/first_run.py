#!/usr/bin/env python3
"""A first run: `cncsim run JOB.nc` without a scenario, `--machine`, `cncsim init` and `cncsim keys PREFIX`.

Modes (one ctest each):
  same_report   `run scenarios/jobs/square_20mm.nc` (the default machine and architecture) writes the report of
                scenarios/fpga-uart/square_20mm.toml, whose machine tables hold the default values and whose
                architecture is the default: the same job on the same machine through the same controller.
  machine_file  `--machine` with a file of that scenario's own [machine] tables gives that report again; a file of
                1/16 microstepping gives 200 x 16 / (20 x 2 mm) = 80 steps/mm.
  atmega        `--arch atmega` runs the job on the ATmega328P.
  init          `init DIR` writes files whose scenario runs as written, on the default machine (the job alone on
                the default machine gives its report); a second `init DIR` stops with exit 2 and writes nothing.
  keys          `keys machine.x` prints the rows of `keys` whose key starts with machine.x, and nothing else; on a
                terminal of 72 columns no line is wider (but a single word).
The reports are compared whole but for the paths and the name, which name the files and not the run.

Usage: first_run.py CNCSIM SOURCE_DIR WORK_DIR MODE
"""
import fcntl
import json
import os
import pty
import shutil
import struct
import subprocess
import sys
import termios
import tomllib


def run(cncsim, *args, expect=0):
    r = subprocess.run([cncsim, *args], capture_output=True, text=True)
    if r.returncode != expect:
        raise SystemExit("cncsim %s: exit %d, expected %d\n%s%s" % (" ".join(args), r.returncode, expect, r.stdout,
                                                                     r.stderr))
    return r


def report(cncsim, work, name, *args):
    path = os.path.join(work, name + ".json")
    run(cncsim, "run", *args, "--report", path, "--progress", "off")
    with open(path) as f:
        j = json.load(f)
    for key in ("file", "job", "name"):
        del j["scenario"][key]
    return j


def same(a, b, what):
    if a != b:
        diff = [k for k in sorted(set(a) | set(b)) if a.get(k) != b.get(k)]
        raise SystemExit("%s: the reports differ in %s" % (what, ", ".join(diff)))


def toml_tables(tables, prefix=""):
    """Flat tables of scalars as TOML text."""
    out = ""
    for name, table in tables.items():
        full = prefix + name
        scalars = {k: v for k, v in table.items() if not isinstance(v, dict)}
        if scalars:
            out += "[%s]\n" % full
            out += "".join("%s = %s\n" % (k, json.dumps(v)) for k, v in scalars.items())
        out += toml_tables({k: v for k, v in table.items() if isinstance(v, dict)}, full + ".")
    return out


def main():
    cncsim, source, work, mode = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    job = os.path.join(source, "scenarios", "jobs", "square_20mm.nc")
    scenario = os.path.join(source, "scenarios", "fpga-uart", "square_20mm.toml")
    if mode == "same_report":
        same(report(cncsim, work, "job", job), report(cncsim, work, "scenario", scenario), "job vs scenario")
    elif mode == "machine_file":
        with open(scenario, "rb") as f:
            tables = {"machine": tomllib.load(f)["machine"]}
        machine = os.path.join(work, "seed_000.toml")
        with open(machine, "w") as f:
            f.write(toml_tables(tables))
        same(report(cncsim, work, "machine", job, "--machine", machine), report(cncsim, work, "default", job),
             "the scenario's machine tables vs the default machine")
        sixteenth = os.path.join(work, "sixteenth.toml")
        with open(sixteenth, "w") as f:
            f.write("[machine.x]\nmicrosteps = 16\n[machine.y]\nmicrosteps = 16\n")
        j = report(cncsim, work, "sixteenth", job, "--machine", sixteenth)
        spm = [j["scenario"]["machine"][a]["steps_per_mm"] for a in ("x", "y")]
        if spm != [80.0, 80.0]:
            raise SystemExit("1/16 machine: %r steps/mm, expected 80 on both axes" % spm)
    elif mode == "atmega":
        j = report(cncsim, work, "atmega", job, "--arch", "atmega")
        if j["scenario"]["architecture"] != "atmega" or "atmega" not in j or not j["ok"]:
            raise SystemExit("--arch atmega: ran %s, ok %s" % (j["scenario"]["architecture"], j["ok"]))
    elif mode == "init":
        folder = os.path.join(work, "start")
        out = run(cncsim, "init", folder).stdout
        if "cncsim run " + os.path.join(folder, "scenario.toml") not in out:
            raise SystemExit("init does not say how to run what it wrote:\n" + out)
        written = {n: open(os.path.join(folder, n)).read() for n in ("scenario.toml", "machine.toml", "job.nc")}
        same(report(cncsim, work, "init_scenario", os.path.join(folder, "scenario.toml")),
             report(cncsim, work, "init_job", os.path.join(folder, "job.nc")), "init's scenario vs its job alone")
        again = run(cncsim, "init", folder, expect=2)
        if "scenario.toml: exists: cncsim init overwrites no file" not in again.stderr:
            raise SystemExit("a second init: " + again.stderr)
        for name, text in written.items():
            if open(os.path.join(folder, name)).read() != text:
                raise SystemExit("a second init changed " + name)
    elif mode == "keys":
        rows = [l for l in run(cncsim, "keys").stdout.splitlines() if l.startswith("| `")]
        chosen = run(cncsim, "keys", "machine.x").stdout.splitlines()
        expected = [l for l in rows if l.startswith("| `machine.x.")]
        if not expected or chosen[2:] != expected or not chosen[0].startswith("| key |"):
            raise SystemExit("keys machine.x:\n" + "\n".join(chosen))
        width = 72
        leader, follower = pty.openpty()
        fcntl.ioctl(follower, termios.TIOCSWINSZ, struct.pack("HHHH", 24, width, 0, 0))
        p = subprocess.Popen([cncsim, "keys", "machine"], stdout=follower, stderr=subprocess.PIPE)
        os.close(follower)
        text = b""
        while True:
            try:
                chunk = os.read(leader, 65536)
            except OSError:  # the terminal closed with the process
                break
            if not chunk:
                break
            text += chunk
        if p.wait() != 0:
            raise SystemExit("keys on a terminal: exit %d" % p.returncode)
        lines = text.decode().replace("\r\n", "\n").splitlines()
        wide = [l for l in lines if len(l) > width and " " in l.strip()]
        if len(lines) < len([r for r in rows if r.startswith("| `machine.")]) or wide or any(l.startswith("|") for l in lines):
            raise SystemExit("keys on a %d-column terminal:\n%s" % (width, "\n".join(wide or lines[:10])))
    else:
        raise SystemExit("unknown mode " + mode)
    print(mode + ": ok")


if __name__ == "__main__":
    main()
