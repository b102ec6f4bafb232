#!/usr/bin/env python3
"""`cncsim sweep --slurm` and `cncsim sweep collect`: usage slurm_test.py MODE CNCSIM SOURCE_DIR WORKDIR.

- cluster: starts a one-node Slurm cluster of its own (munged, slurmctld and slurmd, their configuration, keys,
  sockets, state and logs in a temp dir, on free ports), submits tests/data/sweeps/square_slurm.toml with --slurm in
  tasks of 4 points (the last task short), waits for the job array, and checks that `cncsim sweep collect` gives
  results.csv, results.json and summary.md byte for byte as the local sweep does, and each point's report as the local
  one. Every daemon it started is stopped by its pid, whatever happened. Skipped (exit 77) when slurm-wlm or munge is
  not installed.
- tasks: the same without a cluster (an sbatch that notes its arguments; the tasks run as Slurm runs the script):
  the array lists the tasks with points to run, a collect after one task lists the others' points as missing with the
  line to submit just them, and results for the points finished.
- bad_input: --point out of range, collect on a folder that is not a submitted sweep's, --points-per-task without
  --slurm and --slurm with a [search] exit 2 naming what is wrong.
"""
import csv
import ctypes
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from cncsim_report import check, check_bad_input  # noqa: E402

SKIP = 77
DAEMONS = ("munged", "mungekey", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel")
RESULTS = ("results.csv", "results.json", "summary.md")


def read(path):
    with open(path, "rb") as f:
        return f.read()


def free_ports(n):
    """n TCP ports nothing listens on now (the kernel's choice, so another cluster's or service's are not taken)."""
    socks = [socket.socket() for _ in range(n)]
    for s in socks:
        s.bind(("", 0))
    ports = [s.getsockname()[1] for s in socks]
    for s in socks:
        s.close()
    return ports


def slurm_conf(tmp, host, ports, munge_socket):
    cpus = os.cpu_count()
    return "\n".join([
        "ClusterName=cncsimtest",
        "SlurmctldHost=" + host,
        "SlurmUser=root",
        "SlurmdUser=root",
        "AuthType=auth/munge",
        "CredType=cred/munge",
        "AuthInfo=socket=" + munge_socket,
        "SlurmctldPort=%d" % ports[0],
        "SlurmdPort=%d" % ports[1],
        "StateSaveLocation=" + os.path.join(tmp, "state"),
        "SlurmdSpoolDir=" + os.path.join(tmp, "spool"),
        "SlurmctldPidFile=" + os.path.join(tmp, "slurmctld.pid"),
        "SlurmdPidFile=" + os.path.join(tmp, "slurmd.pid"),
        "SlurmctldLogFile=" + os.path.join(tmp, "slurmctld.log"),
        "SlurmdLogFile=" + os.path.join(tmp, "slurmd.log"),
        "ProctrackType=proctrack/linuxproc",
        "TaskPlugin=task/none",
        "SelectType=select/cons_tres",
        "SelectTypeParameters=CR_Core",
        "MpiDefault=none",
        "SwitchType=switch/none",
        "JobAcctGatherType=jobacct_gather/none",
        "AccountingStorageType=accounting_storage/none",
        "ReturnToService=2",
        "SchedulerType=sched/builtin",
        "NodeName=%s CPUs=%d RealMemory=1000 State=UNKNOWN" % (host, cpus),
        "PartitionName=debug Nodes=%s Default=YES State=UP MaxTime=INFINITE" % host,
        "",
    ])


PR_SET_CHILD_SUBREAPER = 36  # <linux/prctl.h>


def our_children():
    """The pids whose parent is this process (/proc/PID/stat's fourth field)."""
    pids = []
    for entry in os.listdir("/proc"):
        try:
            with open("/proc/%s/stat" % entry) as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[1]) == os.getpid():
            pids.append(int(entry))
    return pids


class Cluster:
    """munged, slurmctld and slurmd in the foreground as our children: stopped by their pids in stop(). The job
    steps slurmd starts detach from it; as a subreaper this process becomes their parent, so that stop() can end and
    reap any left behind instead of leaving them to init."""

    def __init__(self, tmp):
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
        self.tmp = tmp
        self.procs = []
        self.env = dict(os.environ, SLURM_CONF=os.path.join(tmp, "slurm.conf"))

    def start(self):
        tmp = self.tmp
        for d in ("state", "spool", "munge"):
            os.makedirs(os.path.join(tmp, d), mode=0o700, exist_ok=True)
        key = os.path.join(tmp, "munge", "munge.key")
        subprocess.run(["mungekey", "--create", "--keyfile", key], check=True, capture_output=True)
        munge_socket = os.path.join(tmp, "munge", "munge.socket")
        self.spawn(["munged", "--foreground", "--force", "--socket", munge_socket, "--key-file", key,
                    "--pid-file", os.path.join(tmp, "munge", "munged.pid"),
                    "--log-file", os.path.join(tmp, "munge", "munged.log"),
                    "--seed-file", os.path.join(tmp, "munge", "munged.seed")], "munged")
        self.wait_for(lambda: os.path.exists(munge_socket), "munged's socket", "munge/munged.log")
        host = socket.gethostname().split(".")[0]
        with open(self.env["SLURM_CONF"], "w") as f:
            f.write(slurm_conf(tmp, host, free_ports(2), munge_socket))
        self.spawn(["slurmctld", "-D", "-i", "-f", self.env["SLURM_CONF"]], "slurmctld")
        self.spawn(["slurmd", "-D", "-f", self.env["SLURM_CONF"]], "slurmd")
        self.wait_for(lambda: self.sinfo() in ("idle", "mixed", "allocated"), "the node idle in sinfo",
                      "slurmctld.log")

    def spawn(self, args, name):
        log = open(os.path.join(self.tmp, name + ".out"), "w")
        self.procs.append((name, subprocess.Popen(args, env=self.env, stdout=log, stderr=subprocess.STDOUT)))

    def sinfo(self):
        r = subprocess.run(["sinfo", "-h", "-o", "%T"], env=self.env, capture_output=True, text=True)
        return r.stdout.strip() if r.returncode == 0 else ""

    def wait_for(self, cond, what, log, timeout_s=30):
        deadline = time.time() + timeout_s
        while time.time() < deadline:
            if cond():
                return
            dead = [name for name, p in self.procs if p.poll() is not None]
            check(not dead, "%s ended: see %s" % (", ".join(dead), self.tmp))
            time.sleep(0.2)
        check(False, "no %s after %d s: see %s" % (what, timeout_s, os.path.join(self.tmp, log)))

    def jobs(self):
        r = subprocess.run(["squeue", "-h", "-o", "%i %T"], env=self.env, capture_output=True, text=True)
        return r.stdout.split("\n") if r.returncode == 0 and r.stdout.strip() else []

    def stop(self):
        """Every job cancelled and every daemon we started stopped, by its pid, slurmd first."""
        if any(p.poll() is None for name, p in self.procs if name == "slurmctld"):
            subprocess.run(["scancel", "--full", "--user", "root"], env=self.env, capture_output=True)
            deadline = time.time() + 10
            while self.jobs() and time.time() < deadline:
                time.sleep(0.2)
        for name, p in reversed(self.procs):
            if p.poll() is None:
                os.kill(p.pid, signal.SIGTERM)
                try:
                    p.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    os.kill(p.pid, signal.SIGKILL)
                    p.wait()
        for pid in our_children():
            if pid not in [p.pid for _, p in self.procs]:
                try:
                    os.kill(pid, signal.SIGKILL)
                    os.waitpid(pid, 0)
                except OSError:  # it ended and was reaped meanwhile
                    pass


def cluster(cncsim, source, work):
    missing = [d for d in DAEMONS if shutil.which(d) is None]
    if missing:
        print("SKIP: no %s on the PATH: install slurm-wlm and munge (scripts/setup.sh does) to run this test"
              % ", ".join(missing))
        sys.exit(SKIP)
    sweep_file = os.path.join(source, "tests", "data", "sweeps", "square_slurm.toml")
    local, remote = os.path.join(work, "local"), os.path.join(work, "slurm")
    for d in (local, remote):
        shutil.rmtree(d, ignore_errors=True)
    start = time.time()
    r = subprocess.run([cncsim, "sweep", sweep_file, "--out", local, "--jobs", "2"], capture_output=True, text=True)
    check(r.returncode == 0, "the local sweep failed: " + r.stderr)
    tmp = tempfile.mkdtemp(prefix="cncsim-slurm-")
    c = Cluster(tmp)
    try:
        c.start()
        print("cluster up after %.1f s" % (time.time() - start))
        r = subprocess.run([cncsim, "sweep", sweep_file, "--out", remote, "--slurm", "--partition", "debug",
                            "--time", "5", "--points-per-task", "4"], env=c.env, capture_output=True, text=True)
        check(r.returncode == 0, "--slurm: exit %d: %s" % (r.returncode, r.stderr))
        check("sbatch --array=0-1 " in r.stderr, "two tasks of 4 points are not what was submitted: " + r.stderr)
        deadline = time.time() + 60
        while c.jobs() and time.time() < deadline:
            time.sleep(0.3)
        check(not c.jobs(), "the job array did not end within 60 s: %s" % c.jobs())
        r = subprocess.run([cncsim, "sweep", "collect", remote], capture_output=True, text=True)
        logs = "".join(read(os.path.join(remote, "slurm", f)).decode() for f in sorted(os.listdir(
            os.path.join(remote, "slurm"))) if f.startswith("task_"))
        check(r.returncode == 0, "collect: exit %d: %s\ntask logs:\n%s" % (r.returncode, r.stderr, logs))
        check("6 of 6 points done, 0 failed, 0 missing" in r.stderr, "collect says: " + r.stderr)
    finally:
        c.stop()
        left = [name for name, p in c.procs if p.poll() is None]
        check(not left, "still running: " + ", ".join(left))
    shutil.rmtree(tmp, ignore_errors=True)
    for name in RESULTS:
        check(read(os.path.join(local, name)) == read(os.path.join(remote, name)),
              name + ": the Slurm sweep's differs from the local one's")
    with open(os.path.join(remote, "results.csv"), newline="") as f:
        status = [row["status"] for row in csv.DictReader(f)]
    check(status == ["ok"] * 6, "the points' status: %s, not 6 ok" % status)
    points = sorted(f for f in os.listdir(os.path.join(local, "points")) if f.endswith(".json"))
    check(len(points) == 12, "%d point files, not 6 reports and 6 records" % len(points))
    for f in points:
        check(read(os.path.join(local, "points", f)) == read(os.path.join(remote, "points", f)),
              f + ": the Slurm task's differs from the local run's")
    print("6 points in 2 tasks on Slurm: the results and reports as the local sweep's; %.1f s" % (time.time() - start))


def tasks(cncsim, source, work):
    """The submission and collect without a cluster: an sbatch on the PATH that notes its arguments, and the tasks run
    here as Slurm would run the script."""
    sweep_file = os.path.join(source, "tests", "data", "sweeps", "square_slurm.toml")
    out = os.path.join(work, "out")
    shutil.rmtree(out, ignore_errors=True)
    bin_dir = os.path.join(work, "bin")
    os.makedirs(bin_dir, exist_ok=True)
    noted = os.path.join(work, "sbatch.args")
    with open(os.path.join(bin_dir, "sbatch"), "w") as f:
        f.write('#!/bin/sh\necho "$@" > %s\necho 41\n' % noted)
    os.chmod(os.path.join(bin_dir, "sbatch"), 0o755)
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"])
    script = os.path.join(out, "slurm", "sweep.sh")

    def submit(array):
        r = subprocess.run([cncsim, "sweep", sweep_file, "--out", out, "--slurm", "--points-per-task", "4"], env=env,
                           capture_output=True, text=True)
        check(r.returncode == 0, "--slurm: exit %d: %s" % (r.returncode, r.stderr))
        with open(noted) as f:
            args = f.read().split()
        check(args == ["--parsable", "--array=" + array, script], "sbatch got %s, not --array=%s" % (args, array))
        check("Slurm job 41" in r.stderr, "the job number is not said: " + r.stderr)

    def task(k):
        r = subprocess.run(["sh", script], env=dict(os.environ, SLURM_ARRAY_TASK_ID=str(k)), capture_output=True,
                           text=True)
        check(r.returncode == 0, "task %d: exit %d: %s" % (k, r.returncode, r.stderr))

    def collect():
        return subprocess.run([cncsim, "sweep", "collect", out], capture_output=True, text=True)

    submit("0-1")
    task(1)
    r = collect()
    check(r.returncode == 1, "collect with task 0 not run: exit %d, not 1: %s" % (r.returncode, r.stderr))
    for said in ("2 of 6 points done, 0 failed, 4 missing", "missing: 00000 00001 00002 00003",
                 "  sbatch --array=0 " + script):
        check(said in r.stderr, "collect does not say '%s': %s" % (said, r.stderr))
    with open(os.path.join(out, "results.csv")) as f:
        points = [line.split(",")[0] for line in f.read().splitlines()[1:]]
    check(points == ["00004", "00005"], "results.csv has points %s, not task 1's 00004 and 00005" % points)
    submit("0")
    task(0)
    r = collect()
    check(r.returncode == 0 and "6 of 6 points done, 0 failed, 0 missing" in r.stderr,
          "collect after both tasks: exit %d: %s" % (r.returncode, r.stderr))
    print("task 1, then task 0 resubmitted alone: collect lists what is missing, then has every point")


def bad_input(cncsim, source, work):
    sweep_file = os.path.join(source, "tests", "data", "sweeps", "square_slurm.toml")
    search_file = os.path.join(source, "sweeps", "lost_step_feed.toml")
    out = os.path.join(work, "out")
    not_sweep = os.path.join(work, "not_a_sweep")
    os.makedirs(not_sweep, exist_ok=True)
    cases = [
        ("point out of range", ["sweep", sweep_file, "--out", out, "--point", "2", "--points-per-task", "4"],
         "--point: 2: %s has 6 points, tasks 0 .. 1 at 4 a task" % sweep_file),
        ("collect elsewhere", ["sweep", "collect", not_sweep],
         "%s: not a sweep submitted with --slurm: it has no slurm/sweep.json" % not_sweep),
        ("per task alone", ["sweep", sweep_file, "--out", out, "--points-per-task", "4"],
         "--points-per-task: goes with --slurm"),
        ("search on slurm", ["sweep", search_file, "--out", out, "--slurm"],
         "[search]: --slurm: a search tries its values one after another"),
        ("partition alone", ["sweep", sweep_file, "--out", out, "--partition", "debug"], "--partition requires --slurm"),
    ]
    for name, args, what in cases:
        check_bad_input(name, subprocess.run([cncsim] + args, capture_output=True, text=True), [what],
                        os.path.join(out, "points"))


def main():
    mode, cncsim, source, work = sys.argv[1:5]
    source = os.path.abspath(source)
    os.makedirs(work, exist_ok=True)
    {"cluster": cluster, "tasks": tasks, "bad_input": bad_input}[mode](cncsim, source, work)


if __name__ == "__main__":
    main()
