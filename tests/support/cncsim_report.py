"""Runs `cncsim run` with a JSON report, for the Python tests that read a run's figures."""
import json
import os
import subprocess


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
