#!/usr/bin/env bash
# Speed of the lathe-sync architecture: the three-pass M6 thread of scenarios/lathe-sync/m6_thread.toml,
# target >= 3x real time. Usage: bench/lathe_bench.sh [build dir] [repetitions]. Prints one Markdown row: the
# machine time simulated, the wall time of the whole cncsim process (median of the repetitions), their ratio and
# the peak memory.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
REPS=${2:-3}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
walls=()
mem=0
for _ in $(seq "$REPS"); do
    t0=$(date +%s%N)
    kb=$( { /usr/bin/time -f "%M" "$BUILD/sim/cncsim" run scenarios/lathe-sync/m6_thread.toml --progress off \
        --report "$OUT/r.json" > /dev/null; } 2>&1 | tail -1)
    t1=$(date +%s%N)
    walls+=($(( t1 - t0 )))
    (( kb > mem )) && mem=$kb
done
median=$(printf '%s\n' "${walls[@]}" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
sim=$(grep -o '"simulated_s": [0-9.e+-]*' "$OUT/r.json" | head -1 | awk '{print $2}')
echo "| configuration | simulated [s] | wall [s] | sim/wall | peak RSS [MiB] |"
echo "|---|---|---|---|---|"
awk -v w="$median" -v s="$sim" -v m="$mem" 'BEGIN {
    ws = w / 1e9;
    printf "| lathe-sync M6 thread, 3 passes at 60 rpm | %.3f | %.2f | %.1fx | %.1f |\n", s, ws, s / ws, m / 1024 }'
