#!/usr/bin/env bash
# Every app's output at small sizes, at 1 and 2 ranks, and its bitwise comparison with the output
# of another build: the evidence that a change of layout (moves, splits, deduplication) changed no
# bit of any result.
#
#   scripts/compare_app_outputs.sh run BUILD_DIR OUT_DIR        # every case below, at 1 and 2 ranks
#   scripts/compare_app_outputs.sh compare BASELINE_DIR OUT_DIR  # exit 0 when every file is the same
#
# `run` writes OUT_DIR/<case>/np<N>/ (the files a case writes, its stdout and exit status);
# `compare` compares every file of BASELINE_DIR with the file of the same name in OUT_DIR, and
# fails on a file present in only one: HDF5 files (H5Part, snapshots, checkpoints) dataset by
# dataset and attribute by attribute, bit for bit, with compare_outputs.py (all steps) and the last
# step again with compare_h5part; text files (statistics, used parameters, XDMF index, exit
# status; the lines of standard output that state results) line by line. What a build stamps on its files (the program's version and git commit,
# the wall-clock seconds of a run) is left out of the comparison, nothing else.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage() {
  sed -n '6,7p' "$0" | sed 's/^# *//' >&2
  exit 2
}
[ $# -eq 3 ] || usage
mode=$1

if [ "$mode" = run ]; then
  build=$(cd "$2" && pwd)
  out=$(mkdir -p "$3" && cd "$3" && pwd)
  source "$root/scripts/mpirun_flags.sh"
  # name | program | arguments (parameter files relative to the source tree)
  cases=(
    "sod_1d|sod|$root/apps/sod/sod_1d.par --set particles=200 --set end_time=0.02 --set output_format=both"
    "sod_2d|sod|$root/apps/sod/sod_2d.par --set particles=40 --set end_time=0.01"
    "sod_3d|sod|$root/apps/sod/sod_3d.par --set particles=16 --set end_time=0.005"
    "sedov_2d|sedov|$root/apps/sedov/sedov_2d.par --set particles_per_side=30 --set end_time=0.004"
    "sedov_2d_individual|sedov|$root/apps/sedov/sedov_2d.par --set particles_per_side=30 --set end_time=0.004 --set time_steps=individual --set output_format=both"
    "sedov_3d|sedov|$root/apps/sedov/sedov_3d.par --set particles_per_side=12 --set end_time=0.003"
    "evrard|evrard|$root/apps/evrard/evrard.par --set particles=400 --set end_time=0.05 --set output_format=both"
    "cold_collapse|cold_collapse|$root/apps/cold_collapse/cold_collapse.par --set particles=400 --set end_time=0.05"
    "still_tank|fluid|$root/apps/fluid/still_tank.par --set particles=8 --set end_time=0.02 --set output_format=both"
    "poiseuille|fluid|$root/apps/fluid/poiseuille.par --set particles=20 --set end_time=0.01"
    "couette|fluid|$root/apps/fluid/couette.par --set particles=20 --set end_time=0.01"
    "dam_break|fluid|$root/apps/fluid/dam_break.par --set particles=10 --set end_time=0.005"
    "dam_break_3d|fluid|$root/apps/fluid/dam_break_3d.par --set particles=4 --set end_time=0.003"
    "bns_single_star|bns|$root/apps/bns/single_star.par --set particles=300 --set relaxation_time=0.3 --set relaxation_min_time=0.1 --set end_time=0.3"
    "heat|heat|--cells 256 --time 0.001"
    # A run stopped by max_steps (checkpoint), its restart, and a run from initial data.
    "sod_1d_stop|sod|$root/apps/sod/sod_1d.par --set particles=200 --set max_steps=6 --set checkpoint_every=3 --set output_every=0"
    "sod_1d_restart|sod|$root/apps/sod/sod_1d.par --set particles=200 --set max_steps=12 --set output_every=0 --set restart_file=../../sod_1d_stop/np@/sod.checkpoint.h5part --set output_file=../../sod_1d_stop/np@/sod.h5part --set statistics_file=restart.statistics.txt --set used_parameters_file=restart.used.par"
    "sod_1d_initial_data|sod|$root/apps/sod/sod_1d.par --set end_time=0.03 --set initial_data=../../sod_1d/np@/sod.h5part --set output_file=from_file.h5part"
  )
  for ranks in 1 2; do
    for entry in "${cases[@]}"; do
      IFS='|' read -r name program arguments <<<"$entry"
      dir="$out/$name/np$ranks"
      rm -rf "$dir" && mkdir -p "$dir"
      arguments=${arguments//@/$ranks}
      # shellcheck disable=SC2086
      (cd "$dir" && mpirun -np "$ranks" "${FLECSPH_MPIRUN_FLAGS[@]}" "$build/apps/$program/$program" $arguments \
        --no-timers >stdout.txt 2>&1; echo $? >exit_status.txt) || true
      echo "$name np$ranks: exit $(cat "$dir/exit_status.txt"), $(find "$dir" -type f | wc -l) files"
    done
  done
  exit 0
fi

[ "$mode" = compare ] || usage
baseline=$(cd "$2" && pwd)
out=$(cd "$3" && pwd)
exec /usr/bin/python3 "$root/tests/validation/compare_outputs.py" "$baseline" "$out" \
  --compare-h5part "${FLECSPH_COMPARE_H5PART:-$root/build/tests/validation/compare_h5part}"
