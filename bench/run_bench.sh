#!/usr/bin/env bash
# Speed of the whole cncsim process. Targets: fpga-uart six-segment job >= 100x real time, the atmega square job
# >= 5x and spi-fpga square >= 100x, VCD off; the 41,289-line laser pocket of the G-code corpus >= 100x on
# fpga-uart and >= 20x on spi-fpga, and the atmega rate on a 4,379-line milling-style job
# (bench/make_milling_job.sh), reported. Those targets were set and met with the
# ideal carriage, then the default; each configuration runs with each carriage model named (mechanics.model).
# Usage: bench/run_bench.sh [build dir] [repetitions] [models]. Prints one Markdown row per configuration and model:
# simulated seconds per wall second and STEP edges per wall second (median of the repetitions), and peak memory.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
REPS=${2:-7}
MODELS=${3:-dynamic ideal}
CNCSIM=$BUILD/sim/cncsim
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

bench() {  # name scenario [extra args...]: one row per model
    local model
    for model in $MODELS; do
        bench_model "$model" "$@"
    done
}

bench_model() {  # model name scenario [extra args...]
    local model=$1 name=$2 scenario=$3
    shift 3
    local walls=() mem=0
    for _ in $(seq "$REPS"); do
        local t0 t1 kb
        t0=$(date +%s%N)
        kb=$( { /usr/bin/time -f "%M" "$CNCSIM" run "$scenario" --report "$OUT/r.json" --set "mechanics.model=$model" \
                "$@" > /dev/null; } 2>&1 | tail -1)
        t1=$(date +%s%N)
        walls+=($(( t1 - t0 )))
        (( kb > mem )) && mem=$kb
    done
    local median
    median=$(printf '%s\n' "${walls[@]}" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    # simulated time = the job time; STEP edges = rising + falling edges of every axis
    local sim edges
    sim=$(grep -o '"job_time_s": [0-9.e+-]*' "$OUT/r.json" | head -1 | awk '{print $2}')
    edges=$(grep -o '"\(rising\|falling\)_edges": [0-9]*' "$OUT/r.json" | awk '{s += $2} END {print s}')
    awk -v n="$name" -v k="$model" -v w="$median" -v s="$sim" -v e="$edges" -v m="$mem" 'BEGIN {
        ws = w / 1e9;
        printf "| %s | %s | %.3f | %.4f | %.0fx | %.2f M | %.1f |\n", n, k, s, ws, s / ws, e / ws / 1e6, m / 1024 }'
}

echo "| configuration | mechanics | simulated [s] | wall [s] | sim/wall | STEP edges/s | peak RSS [MiB] |"
echo "|---|---|---|---|---|---|---|"
bench "six-segment, VCD off" scenarios/fpga-uart/six_segment.toml
bench "six-segment, VCD on" scenarios/fpga-uart/six_segment.toml --vcd "$OUT/six.vcd"
bench "square 20 mm, VCD off" scenarios/fpga-uart/square_20mm.toml
bench "circle r10 (177 chords), VCD off" scenarios/fpga-uart/circle_r10.toml
bench "spi-fpga square 20 mm, VCD off" scenarios/spi-fpga/square_20mm.toml
bench "spi-fpga six-segment, VCD off" scenarios/spi-fpga/six_segment.toml
# Real jobs. The pocket's last rapid (212 mm at 1200 mm/min) outlasts send_steps.py's 10 s ACK timeout.
real_job() {  # file architecture -> scenario path
    local s="$OUT/$(basename "$1").$2.toml"
    printf '[scenario]\njob = "%s"\narchitecture = "%s"\n[host]\nack_timeout_s = 60\n' "$(realpath "$1")" "$2" > "$s"
    echo "$s"
}
POCKET=tests/data/gcode-corpus/laser_pocket_40k.gcode
bench "laser pocket 41,289 lines, fpga-uart" "$(real_job "$POCKET" fpga-uart)"
bench "laser pocket 41,289 lines, spi-fpga" "$(real_job "$POCKET" spi-fpga)"
if grep -q "CNC_WITH_AVR:BOOL=ON" "$BUILD/CMakeCache.txt"; then
    bench/make_milling_job.sh > "$OUT/milling_4379.nc"
    bench "atmega milling job 4,379 lines" "$(real_job "$OUT/milling_4379.nc" atmega)"
    bench "atmega square 20 mm, VCD off" scenarios/atmega/square_20mm.toml
    bench "atmega square 20 mm, VCD on" scenarios/atmega/square_20mm.toml --vcd "$OUT/atmega.vcd"
    bench "atmega six-segment, VCD off" scenarios/atmega/six_segment.toml
fi
