#!/usr/bin/env bash
# Wall time of the ideal and the dynamic mechanics (issue 10's speed target): fpga-uart square and
# six-segment, atmega square; best of 3 runs each, with the job's simulated time and the real-time factor.
# usage: bench/mechanics_bench.sh [build/sim/cncsim]
set -euo pipefail
cd "$(dirname "$0")/.."
CNCSIM=${1:-build/sim/cncsim}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-28s %-8s %9s %9s %10s\n' scenario model "sim [s]" "wall [s]" "x real"
for scenario in scenarios/fpga-uart/square_20mm.toml scenarios/fpga-uart/six_segment.toml scenarios/atmega/square_20mm.toml; do
  for model in ideal dynamic; do
    best=""
    for _ in 1 2 3; do
      start=$(date +%s.%N)
      "$CNCSIM" run "$scenario" --set mechanics.model=$model --progress off --report "$tmp/r.json" >/dev/null
      end=$(date +%s.%N)
      wall=$(echo "$end - $start" | bc -l)
      if [ -z "$best" ] || [ "$(echo "$wall < $best" | bc -l)" = 1 ]; then best=$wall; fi
    done
    sim=$(python3 -c "import json;print(json.load(open('$tmp/r.json'))['metrics']['job']['job_time_s'])")
    printf '%-28s %-8s %9s %9.3f %10s\n' "${scenario#scenarios/}" $model "$sim" "$best" \
      "$(python3 -c "print('%.0f' % ($sim / $best))")"
  done
done
