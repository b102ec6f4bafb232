"""A command's wall time and its own peak RSS, measured through child_peak_rss (bench/child_peak_rss.cpp): a child
forked straight from this Python process would report the script's memory (the generated job) as its peak."""
import os
import subprocess
import tempfile
import time


def run_measured(launcher, argv, stderr=subprocess.DEVNULL):
    """Runs argv; returns (exit code, wall seconds, peak RSS in MiB, stderr bytes or None)."""
    with tempfile.NamedTemporaryFile(mode="r", suffix=".rss") as result:
        start = time.monotonic()
        child = subprocess.run([launcher, result.name] + list(argv), stdout=subprocess.DEVNULL, stderr=stderr)
        wall_s = time.monotonic() - start
        kib = result.read().strip()
    if not kib:
        raise RuntimeError("child_peak_rss measured nothing for %s" % " ".join(argv))
    return child.returncode, wall_s, int(kib) / 1024.0, child.stderr
