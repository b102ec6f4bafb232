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

wall_cpu_ns() {  # scenario [--set ...]: "wall cpu", the run's wall time and its user + system CPU time in ns (a
                 # loaded machine stretches the first, hardly the second)
    python3 - "$CNCSIM" "$@" <<'PY'
import resource, subprocess, sys, time
t0 = time.perf_counter_ns()
subprocess.run([sys.argv[1], "run", *sys.argv[2:], "--progress", "off"], stdout=subprocess.DEVNULL, check=True)
wall = time.perf_counter_ns() - t0
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(wall, int((r.ru_utime + r.ru_stime) * 1e9))
PY
}
