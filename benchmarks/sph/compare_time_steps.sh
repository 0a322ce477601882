#!/usr/bin/env bash
# Individual against global time steps (issue 15) on the Sedov 3D blast to a fixed end time:
#   benchmarks/sph/compare_time_steps.sh [--per-side 50] [--end-time 0.02] [--ranks 1] [--balances count]
# runs apps/sedov/sedov_3d.par with time_steps = global, then individual, for each balance (count,
# work), on 1 thread per rank, one after the other, and prints per run: wall time, system steps,
# particle updates per step (fraction of the particles), searches, shock front and energy change,
# the balance over the distributions (max / mean per rank of the work and of the particles), and
# the speed-up of individual over global steps. FLECSPH_BUILD_DIR chooses the build; SEDOV_ARGS
# adds --set options to every run.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${FLECSPH_BUILD_DIR:-$here/build}
per_side=50 end_time=0.02 balances=count ranks=1
while [ $# -gt 0 ]; do
  case $1 in
    --per-side) per_side=$2; shift 2 ;;
    --end-time) end_time=$2; shift 2 ;;
    --balances) balances=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    *) echo "compare_time_steps: unknown option $1" >&2; exit 2 ;;
  esac
done
source "$here/scripts/mpirun_flags.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # name, then --set options
  local name=$1; shift
  local start end
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 mpirun -np "$ranks" "${FLECSPH_MPIRUN_FLAGS[@]}" "$build/apps/sedov/sedov" \
    "$here/apps/sedov/sedov_3d.par" --set particles_per_side="$per_side" --set end_time="$end_time" \
    --set output_file="$work/$name.h5part" --set output_every="$end_time" --set progress_every=0 \
    --set diagnostics_every=0 --set statistics_file=none --no-timers ${SEDOV_ARGS:-} "$@" > "$work/$name.log" 2>&1
  end=$(date +%s.%N)
  local wall steps updates searches front energy
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')
  steps=$(sed -n 's/^.*sph: \([0-9]*\) steps to.*/\1/p' "$work/$name.log")
  searches=$(sed -n 's/.* \([0-9]*\) neighbour searches.*/\1/p' "$work/$name.log")
  updates=$(sed -n 's/.*individual time steps: .* updates in [0-9]* steps (\([^ ]*\) per step, \([^%]*\)%.*/\1 (\2%)/p' "$work/$name.log")
  front=$(sed -n 's/.*shock front (half height) is at r = \([^,]*\),.*/\1/p' "$work/$name.log")
  energy=$(sed -n 's/.*shock front.*relative energy change \([^ ]*\).*/\1/p' "$work/$name.log")
  printf "%-22s wall %8.2f s  steps %5s  searches %5s  updates/step %-18s front %.6f  energy %s\n" \
    "$name" "$wall" "$steps" "$searches" "${updates:-all}" "$front" "$energy"
  sed -n 's/.*sph: balance (\([^,]*\),.*max \/ mean per rank: \(.*\)/    balance \1: \2/p' "$work/$name.log"
  wall_of[$name]=$wall
}
declare -A wall_of
echo "Sedov 3D ${per_side}^3 to t = $end_time, $ranks rank(s) x 1 thread; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for balance in $balances; do
  run "global_$balance" --set time_steps=global --set balance="$balance"
  run "individual_$balance" --set time_steps=individual --set balance="$balance"
  echo "  speed-up of individual over global steps ($balance): $(awk -v g="${wall_of[global_$balance]}" \
    -v i="${wall_of[individual_$balance]}" 'BEGIN { printf "%.2f", g / i }')"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
