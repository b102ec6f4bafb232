#!/usr/bin/env bash
# The FPGA's Verilog in the loop (fpga.model = "rtl"): the plug-in's first build (an empty cache), a run from the
# cache, and the speed of the six-segment job on both FPGAs (seed 000 on fpga-uart, seed 004 on spi-fpga) against
# real time and against the event-driven model.
# Target: at least 0.5x real time. Clock edges per second = the FPGA's 50 MHz x simulated time / wall time (the
# edges of an idle, settled design are skipped, not run: the job's stretches of waiting for the host count too).
# Usage: bench/rtl_bench.sh [build dir] [repetitions]. Prints Markdown rows.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
REPS=${2:-3}
CNCSIM=$BUILD/sim/cncsim
CACHE=$(mktemp -d)
trap 'rm -rf "$CACHE"' EXIT
export CNCSIM_RTL_CACHE=$CACHE

. bench/timing.sh

SIX=scenarios/fpga-uart/six_segment.toml
SHORT=scenarios/fpga-uart/worked_example.toml
build=$(wall_ns "$SHORT" --set fpga.model=rtl)
cached=()
for _ in $(seq "$REPS"); do cached+=("$(wall_ns "$SHORT" --set fpga.model=rtl)"); done
short_event=()
for _ in $(seq "$REPS"); do short_event+=("$(wall_ns "$SHORT")"); done
awk -v b="$build" -v c="$(median "${cached[@]}")" -v e="$(median "${short_event[@]}")" 'BEGIN {
    printf "| plug-in: first build and run | %.1f s |\n| the same run from the cache | %.2f s (event model: %.2f s) |\n",
           b / 1e9, c / 1e9, e / 1e9 }'

# Seed 000's six-segment job on fpga-uart and seed 004's on spi-fpga: wall and CPU time, real-time factor and clock
# edges per second (the 50 MHz clock over the simulated time: skipped edges of a design at rest count too).
for arch in fpga-uart spi-fpga; do
    six=scenarios/$arch/six_segment.toml
    report=$CACHE/$arch.json
    "$CNCSIM" run "$six" --set fpga.model=rtl --progress off --report "$report" > /dev/null
    sim_s=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['metrics']['job']['job_time_s'])" "$report")
    rtl=() cpu=() event=()
    for _ in $(seq "$REPS"); do
        read -r wall_rtl cpu_rtl < <(wall_cpu_ns "$six" --set fpga.model=rtl)
        rtl+=("$wall_rtl")
        cpu+=("$cpu_rtl")
        event+=("$(wall_ns "$six")")
    done
    awk -v a="$arch" -v s="$sim_s" -v r="$(median "${rtl[@]}")" -v c="$(median "${cpu[@]}")" \
        -v e="$(median "${event[@]}")" 'BEGIN {
        printf "| %s six-segment job, %.3f s simulated | RTL %.2f s wall: %.2fx real time, %.1f M clock edges/s | CPU %.2f s: %.2fx, %.1f M edges/s | event model %.2f s |\n",
               a, s, r / 1e9, s / (r / 1e9), 50e6 * s / (r / 1e9) / 1e6, c / 1e9, s / (c / 1e9),
               50e6 * s / (c / 1e9) / 1e6, e / 1e9 }'
done
