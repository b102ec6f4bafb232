"""Runs `cncsim run` with a JSON report, and the checks, for the Python tests that read a run's figures."""
import json
import os
import subprocess
import sys


def run_report(cncsim, scenario, tmp, tag, sets=(), extra=()):
    """(report as a dict, summary text) of `cncsim run SCENARIO --set S... EXTRA...`; the report goes to TMP/TAG.json.
    A run that fails raises CalledProcessError with its message."""
    report = os.path.join(tmp, tag + ".json")
    cmd = [cncsim, "run", scenario, "--progress", "off", "--report", report]
    for s in sets:
        cmd += ["--set", s]
    out = subprocess.run(cmd + list(extra), check=True, capture_output=True, text=True).stdout
    with open(report) as f:
        return json.load(f), out


def check(cond, what):
    """Ends the test with FAIL: WHAT unless COND."""
    if not cond:
        print("FAIL:", what)
        sys.exit(1)


def args_and_workdir():
    """(cncsim, source dir, work dir) of a test called as TEST CNCSIM SOURCE_DIR WORKDIR; the work dir made."""
    cncsim, source, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    return cncsim, source, work


def check_bad_input(name, r, said, unwritten):
    """The command (a finished subprocess.run with text output) exited 2, its stderr says each of SAID, and the file
    UNWRITTEN does not exist; prints the message."""
    check(r.returncode == 2, "%s: exit %d, not 2: %s" % (name, r.returncode, r.stderr))
    for what in said:
        check(what in r.stderr, "%s: the message does not say '%s': %s" % (name, what, r.stderr))
    check(not os.path.exists(unwritten), "%s: %s written" % (name, unwritten))
    print(name + ":", r.stderr.strip().splitlines()[-1])
