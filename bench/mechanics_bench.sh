#!/usr/bin/env bash
# Wall time of the ideal and the dynamic mechanics against their speed target, the latter with its worker threads
# (one per axis, the default) and without ("dynamic-1"): fpga-uart square and six-segment, atmega square; best of 3 runs each,
# with the job's simulated time and the real-time factor, the CPU time (user + system: less disturbed than the
# wall time by other work on a shared machine; with the worker threads, all threads' time) and the dynamic runs'
# integration steps (both axes; deterministic).
# Then the peak memory of the dynamic square at the default tolerances and at tolerances 1000 x tighter (several
# times the integration steps): it must not grow with them.
# usage: bench/mechanics_bench.sh [build/sim/cncsim]
set -euo pipefail
cd "$(dirname "$0")/.."
CNCSIM=${1:-build/sim/cncsim}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-28s %-8s %9s %9s %9s %10s %12s\n' scenario model "sim [s]" "wall [s]" "CPU [s]" "x real" "int. steps"
for scenario in scenarios/fpga-uart/square_20mm.toml scenarios/fpga-uart/six_segment.toml scenarios/atmega/square_20mm.toml; do
  # "dynamic-1": the dynamic mechanics on the simulation's thread (mechanics.worker_thread = false)
  for model in ideal dynamic dynamic-1; do
    sets=(--set mechanics.model=${model%-1})
    if [ "$model" = dynamic-1 ]; then sets+=(--set mechanics.worker_thread=false); fi
    best=""
    best_cpu=""
    for _ in 1 2 3; do
      # wall and CPU time of the child (getrusage: the kernel's runtime to the microsecond, not ticks)
      # (os.wait4: the child's own figures; RUSAGE_CHILDREN would add whatever a python3 shim ran before exec)
      read -r wall cpu < <(python3 -c 'import os, subprocess, sys, time
t = time.monotonic(); p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL)
_, status, r = os.wait4(p.pid, 0); p.returncode = os.waitstatus_to_exitcode(status)
assert p.returncode == 0, p.returncode; print(time.monotonic() - t, r.ru_utime + r.ru_stime)' \
        "$CNCSIM" run "$scenario" "${sets[@]}" --progress off --report "$tmp/r.json")
      if [ -z "$best" ] || [ "$(echo "$wall < $best" | bc -l)" = 1 ]; then best=$wall; fi
      if [ -z "$best_cpu" ] || [ "$(echo "$cpu < $best_cpu" | bc -l)" = 1 ]; then best_cpu=$cpu; fi
    done
    sim=$(python3 -c "import json;print(json.load(open('$tmp/r.json'))['metrics']['job']['job_time_s'])")
    steps=$(python3 -c "import json;r=json.load(open('$tmp/r.json'));m=[v['mechanics'] for v in r.values() \
      if isinstance(v, dict) and 'mechanics' in v];print(m[0]['x']['integration_steps'] + m[0]['y']['integration_steps'] \
      if m else '-')")
    printf '%-28s %-8s %9s %9.3f %9.3f %10s %12s\n' "${scenario#scenarios/}" $model "$sim" "$best" "$best_cpu" \
      "$(python3 -c "print('%.0f' % ($sim / $best))")" "$steps"
  done
done
printf '\n%-28s %-22s %12s %15s\n' scenario "tolerances (rel, abs)" "int. steps" "peak RSS [MiB]"
for tol in "1e-4 1e-8" "1e-7 1e-11"; do
  set -- $tol
  rss_kb=$( { /usr/bin/time -f %M "$CNCSIM" run scenarios/fpga-uart/square_20mm.toml --set mechanics.model=dynamic \
    --set mechanics.rel_tol=$1 --set mechanics.abs_tol=$2 --progress off --report "$tmp/r.json" >/dev/null; } 2>&1 | tail -1)
  steps=$(python3 -c "import json;m=json.load(open('$tmp/r.json'))['fpga-uart']['mechanics'];\
print(m['x']['integration_steps'] + m['y']['integration_steps'])")
  printf '%-28s %-22s %12s %15.1f\n' fpga-uart/square_20mm.toml "$1, $2" "$steps" "$(echo "$rss_kb / 1024" | bc -l)"
done
