#!/bin/bash
# Runs each job of ../jobs (or the named ones) through LinuxCNC 2.9 headless, one instance at a time, and writes
# ../times.csv from the samples (job_times.py). Needs Debian 12's linuxcnc-uspace; about 2 minutes in all.
#   LCNC_JOB=jobs/NAME.ngc LCNC_SAMPLES=samples/NAME.samples linuxcnc cncsim_ref.ini
# drive_job.py (the ini's DISPLAY) homes in place, starts "halsampler -t", runs the job and exits.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
jobs_dir="$here/../jobs"
samples="${SAMPLES_DIR:-/tmp/linuxcnc_planner_samples}"
mkdir -p "$samples"
names=("$@")
[ ${#names[@]} -eq 0 ] && names=($(ls "$jobs_dir"/*.ngc | xargs -n1 basename | sed 's/\.ngc$//'))
cd "$here"
for n in "${names[@]}"; do
    rm -f position_mm.txt  # every job starts at X0 Y0 Z0
    # rtapi_app refuses to run as root unless given a fallback uid; it then runs POSIX non-realtime, which does
    # not change the plan: the planner advances one 1 ms period per servo-thread run however late it wakes.
    env -u DISPLAY RTAPI_UID=65534 RTAPI_FIFO_PATH=/tmp/rtapi_fifo_lcnc LCNC_JOB="$jobs_dir/$n.ngc" \
        LCNC_SAMPLES="$samples/$n.samples" linuxcnc "$here/cncsim_ref.ini" > "$samples/$n.log" 2>&1
done
python3 "$here/job_times.py" "$samples"/*.samples > "$here/../times.csv"
