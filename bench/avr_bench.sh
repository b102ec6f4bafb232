#!/usr/bin/env bash
# Speed of the AVR core: seed 003's firmware on the atmega square, and the grbl architecture's square with the
# grbl-protocol test firmware; with GRBL_SRC naming a built grbl 1.1h tree (its grbl.hex), real grbl on the square and
# on `G1 X10 F600` (start-up included). Targets: 20x, 10x, 10x, 10x real time. Usage: bench/avr_bench.sh [build dir]
# [repetitions]. Prints Markdown rows: the machine time simulated (the report's job time), the lowest and highest user
# + system CPU time and wall time of the whole cncsim process (GNU time), and the simulated time over the CPU time.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
REPS=${2:-5}
CNCSIM="$BUILD/sim/cncsim"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

row() {  # label scenario [--set ...]
    local label=$1
    shift
    local walls=() cpus=()
    for _ in $(seq "$REPS"); do
        read -r w u s < <({ /usr/bin/time -f "%e %U %S" "$CNCSIM" run "$@" --progress off --report "$OUT/r.json" \
            > /dev/null; } 2>&1 | tail -1)
        walls+=("$(awk -v w="$w" 'BEGIN { printf "%d", w * 1e9 }')")
        cpus+=("$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%d", (u + s) * 1e9 }')")
    done
    local sim
    sim=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['metrics']['job']['job_time_s'])" "$OUT/r.json")
    printf '%s\n' "${cpus[@]}" | sort -n > "$OUT/cpu"
    printf '%s\n' "${walls[@]}" | sort -n > "$OUT/wall"
    awk -v label="$label" -v s="$sim" -v c0="$(head -1 "$OUT/cpu")" -v c1="$(tail -1 "$OUT/cpu")" \
        -v w0="$(head -1 "$OUT/wall")" -v w1="$(tail -1 "$OUT/wall")" 'BEGIN {
        printf "| %s | %.2f | %.2f-%.2f | %.2f-%.2f | %.1f-%.1fx |\n", label, s, c0 / 1e9, c1 / 1e9, w0 / 1e9, w1 / 1e9,
            s / (c1 / 1e9), s / (c0 / 1e9) }'
}

echo "| run | simulated [s] | CPU [s] | wall [s] | x real time (CPU) |"
echo "|---|---|---|---|---|"
row "seed 003 firmware, atmega square 20 mm" scenarios/atmega/square_20mm.toml
row "grbl-protocol test firmware, grbl square 20 mm" tests/data/grbl/square_20mm.toml \
    --set "avr.firmware=$(realpath "$BUILD")/models/avr/firmware/tests/grbl_protocol.elf"
if [[ -n "${GRBL_SRC:-}" ]]; then
    row "real grbl 1.1h, grbl square 20 mm" tests/data/grbl/square_20mm.toml --set "avr.firmware=$GRBL_SRC/grbl.hex"
    printf 'G21 G90\nG1 X10 F600\n' > "$OUT/x10.nc"
    sed "s#^job = .*#job = \"$OUT/x10.nc\"#" tests/data/grbl/square_20mm.toml > "$OUT/x10.toml"
    row "real grbl 1.1h, G1 X10 F600 (start-up included)" "$OUT/x10.toml" --set "avr.firmware=$GRBL_SRC/grbl.hex"
else
    echo "(real grbl not measured: set GRBL_SRC to a built grbl 1.1h tree)" >&2
fi
