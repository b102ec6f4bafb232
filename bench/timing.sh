# Sourced by the benchmark scripts: the median of numbers, and a cncsim run's wall time in ns ($CNCSIM).
median() {
    printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}

wall_ns() {  # scenario [--set ...]
    local t0 t1
    t0=$(date +%s%N)
    "$CNCSIM" run "$@" --progress off > /dev/null
    t1=$(date +%s%N)
    echo $(( t1 - t0 ))
}
