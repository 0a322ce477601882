#!/usr/bin/env bash
# Benchmark (not a test) of the interior/boundary split and communication overlap: Sedov 3D 50^3
# on 1 and 2 ranks with default threads and --trace; prints step time and the 2-rank speed-up, then
# overlap and idle time from the traces when scripts/trace_summary.py exists.
# Usage: scripts/bench_overlap.sh [build dir] [steps]   (default: build, 20 steps)
set -euo pipefail
build=${1:-build}; steps=${2:-20}; side=${3:-50}
here=$(cd "$(dirname "$0")" && pwd); root=$(dirname "$here")
source "$here/mpirun_flags.sh"
out=$(mktemp -d); declare -A seconds
for ranks in 1 2; do
  start=$(date +%s.%N)
  mpirun "${FLECSPH_MPIRUN_FLAGS[@]}" -np $ranks "$build/apps/sedov/sedov" "$root/apps/sedov/sedov_3d.par" \
    --set particles_per_side=$side --set max_steps=$steps --set output_file="$out/sedov_$ranks.h5part" \
    --set progress_every=0 --set diagnostics_every=0 --set checkpoint_file=none --trace "$out/trace_$ranks.json" > "$out/log_$ranks" 2>&1
  end=$(date +%s.%N)
  seconds[$ranks]=$(echo "$end - $start" | bc -l)
  printf '%d rank(s): %.3f s total, %.4f s per step\n' $ranks "${seconds[$ranks]}" "$(echo "${seconds[$ranks]} / $steps" | bc -l)"
done
printf '2-rank speed-up: %.2f\n' "$(echo "${seconds[1]} / ${seconds[2]}" | bc -l)"
for ranks in 1 2; do
  start=$(date +%s.%N)
  mpirun "${FLECSPH_MPIRUN_FLAGS[@]}" -np $ranks "$build/apps/sod/sod" "$root/apps/sod/sod_1d.par" \
    --set output_file="$out/sod_$ranks.h5part" --set progress_every=0 --set diagnostics_every=0 > "$out/sod_log_$ranks" 2>&1
  end=$(date +%s.%N)
  printf 'Sod 1D, %d rank(s): %.3f s\n' $ranks "$(echo "$end - $start" | bc -l)"
done
if [ -f "$here/trace_summary.py" ]; then
  for ranks in 1 2; do /usr/bin/python3 "$here/trace_summary.py" "$out/trace_$ranks.json"; done
else
  echo "(scripts/trace_summary.py not present: traces left in $out)"
fi
