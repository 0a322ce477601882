#!/usr/bin/env bash
# Runs bench_sedov on 1 rank x 1 thread, 1 rank x 2 threads and 2 ranks x 1 thread, one after the
# other, and prints each throughput and the speed-ups of 2 threads and of 2 ranks over 1 x 1, with
# the machine's load before and after (the ratios are only meaningful from one invocation).
#
#   benchmarks/sph/run_scaling.sh                       # 50^3, 10 timed steps
#   benchmarks/sph/run_scaling.sh --per-side 100 --steps 5
#
# Arguments go to bench_sedov; FLECSPH_BUILD_DIR chooses the build (default: build/).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bench="${FLECSPH_BUILD_DIR:-$here/build}/benchmarks/sph/bench_sedov"
[ -x "$bench" ] || { echo "run_scaling.sh: $bench not built" >&2; exit 1; }
source "$here/scripts/mpirun_flags.sh"
export OMP_PROC_BIND=false

# The throughput of one run: ranks threads [bench_sedov options]. One rank runs without mpirun,
# which would bind it, and both its threads, to one core.
throughput() {
  local output
  if [ "$1" -eq 1 ]; then
    output=$(OMP_NUM_THREADS=$2 "$bench" --no-timers "${@:3}")
  else
    output=$(OMP_NUM_THREADS=$2 mpirun -np "$1" "${FLECSPH_MPIRUN_FLAGS[@]}" "$bench" --no-timers "${@:3}")
  fi
  echo "$output" >&2
  awk '/^throughput:/ { print $2 }' <<<"$output"
}

echo "load before: $(uptime)"
serial=$(throughput 1 1 "$@")
threads=$(throughput 1 2 "$@")
ranks=$(throughput 2 1 "$@")
echo "load after:  $(uptime)"
awk -v s="$serial" -v t="$threads" -v r="$ranks" 'BEGIN {
  printf "particle-steps/s: 1 rank x 1 thread %.4g, 1 rank x 2 threads %.4g, 2 ranks x 1 thread %.4g\n", s, t, r
  printf "speed-up over 1 x 1: 2 threads %.2f, 2 ranks %.2f\n", t / s, r / s
}'
