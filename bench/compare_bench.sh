#!/usr/bin/env bash
# Speed of `cncsim compare` with its plots: the three architectures on the radius-10 circle, --out with
# every plot, report and VCD. Target: under 30 s wall on the 2-core project machine. Prints one Markdown row per
# repetition: the whole command's wall time, each architecture's simulated time over its own wall time (they run
# side by side, as many at once as there are cores), and the time gnuplot took for the plots.
# Usage: bench/compare_bench.sh [build dir] [repetitions]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
REPS=${2:-3}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "| run | wall [s] | fpga-uart sim/wall | atmega sim/wall | spi-fpga sim/wall | plots [s] |"
echo "|---|---|---|---|---|---|"
for r in $(seq "$REPS"); do
    rm -rf "$OUT/circle"
    t0=$(date +%s%N)
    "$BUILD/sim/cncsim" compare scenarios/compare/circle_r10.toml --arch fpga-uart,atmega,spi-fpga \
        --out "$OUT/circle" > /dev/null 2> "$OUT/log"
    t1=$(date +%s%N)
    ratio() { grep -o "compare: $1 ok after .* real time" "$OUT/log" | grep -o '[0-9.]*x real' | tr -d 'x real'; }
    plots=$(grep -o 'plots rendered in [0-9.]*' "$OUT/log" | awk '{print $4}')
    awk -v r="$r" -v w="$(( t1 - t0 ))" -v a="$(ratio fpga-uart)" -v b="$(ratio atmega)" -v c="$(ratio spi-fpga)" \
        -v p="$plots" 'BEGIN { printf "| %d | %.2f | %sx | %sx | %sx | %s |\n", r, w / 1e9, a, b, c, p }'
done
