#!/usr/bin/env bash
# What the oscillators cost (docs/metrics.md, "Clocks"): each scenario run alternately on the ideal clock
# (clock.ideal = true) and on its default part with its offset and jitter, the median wall time of each, and the
# difference. Target: at most 5 % (a jittered clock draws every edge it times).
# Usage: bench/clock_bench.sh [build dir] [repetitions]. Prints one Markdown row per scenario. The sub-second runs
# repeat ten times as often: their spread from run to run is a few percent, as large as what is measured.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
REPS=${2:-5}
CNCSIM=$BUILD/sim/cncsim

. bench/timing.sh

echo "| scenario | ideal clock [s] | default clock [s] | cost |"
echo "|---|---|---|---|"
for case in scenarios/fpga-uart/six_segment.toml:10 scenarios/atmega/square_20mm.toml:1 \
            scenarios/spi-fpga/square_20mm.toml:10 scenarios/lathe-sync/m6_thread.toml:1; do
    scenario=${case%:*}
    ideal=() real=()
    for _ in $(seq $(( REPS * ${case##*:} ))); do
        ideal+=("$(wall_ns "$scenario" --set clock.ideal=true)")
        real+=("$(wall_ns "$scenario")")
    done
    mi=$(median "${ideal[@]}")
    mr=$(median "${real[@]}")
    awk -v s="$scenario" -v i="$mi" -v r="$mr" \
        'BEGIN { printf "| %s | %.3f | %.3f | %+.1f %% |\n", s, i / 1e9, r / 1e9, (r - i) / i * 100 }'
done
