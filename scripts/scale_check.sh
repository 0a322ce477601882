#!/usr/bin/env bash
# Beyond this machine's cores: runs Sod 1D and a small Sedov 3D on 1, 2, 4, 8 and 16 ranks
# (oversubscribed, one thread each), checks that every final step is bitwise the 1-rank one
# (compare_h5part), and prints the ghost-copy messages and bytes sent per rank per step.
# Usage: scripts/scale_check.sh [build dir] [rank counts...]   (not a test: minutes on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$here/build}; shift || true
ranks=("$@"); [ ${#ranks[@]} -gt 0 ] || ranks=(1 2 4 8 16)
source "$here/scripts/mpirun_flags.sh"
export OMP_NUM_THREADS=1 OMP_PROC_BIND=false
export OMPI_MCA_mpi_yield_when_idle=1  # oversubscribed ranks give the cores up while they wait
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
compare=$build/tests/validation/compare_h5part
status=0
run_case() {  # name app parameter-file options...
  local name=$1 app=$2 par=$3; shift 3
  printf '%-10s %5s %6s %14s %14s %14s  %s\n' case ranks steps "msgs/rank/step" "bytes/rank/step" "max B/rank/step" bitwise
  for n in "${ranks[@]}"; do
    local out=$work/${name}_$n.h5part log=$work/${name}_$n.log
    mpirun -np "$n" "${FLECSPH_MPIRUN_FLAGS[@]}" "$build/apps/$app/$app" "$par" "$@" \
      --set output_file="$out" --set progress_every=0 --set diagnostics_every=0 >"$log" 2>&1 || {
      echo "$name on $n ranks failed:"; tail -5 "$log"; status=1; continue; }
    local steps line same=reference
    steps=$(/usr/bin/python3 -c "import h5py, sys
f = h5py.File(sys.argv[1], 'r')
print(f['Step#%d' % max(int(k.split('#')[1]) for k in f if k.startswith('Step#'))].attrs['step'])" "$out")
    line=$(grep '^Ghost copies per rank' "$log")  # messages sent min / mean / max, bytes sent ...
    if [ "$n" != "${ranks[0]}" ]; then
      if "$compare" "$work/${name}_${ranks[0]}.h5part" "$out" >/dev/null; then same=same; else same=DIFFERENT; status=1; fi
    fi
    echo "$line" | awk -v c="$name" -v n="$n" -v s="$steps" -v b="$same" '{
      split($0, m, "messages sent "); split(m[2], mm, " / "); split($0, q, "bytes sent "); split(q[2], bb, " / ");
      printf "%-10s %5d %6d %14.2f %14.0f %14.0f  %s\n", c, n, s, mm[2] / s, bb[2] / s, bb[3] / s, b }'
  done
}
run_case sod_1d sod "$here/apps/sod/sod_1d.par" --set end_time=0.02
run_case sedov_3d sedov "$here/apps/sedov/sedov_3d.par" --set particles_per_side=12 --set end_time=0.004
exit $status
