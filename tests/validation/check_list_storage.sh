#!/bin/sh
# Neighbour lists kept as runs (the default) and packed hold the same pairs in the same order
# (ntree/search/packed_entries.hh), so a run gives the same bits with either:
#   check_list_storage.sh <app> <compare_h5part> <mpiexec> <numproc flag> <parameter file> [--set ...]
# runs the problem with packed lists on 1 rank and with runs on 2 (rank invariance besides), and
# requires the last output steps to be bitwise equal.
set -eu
app=$1 compare=$2 mpiexec=$3 numproc=$4 parameters=$5
shift 5
stem=$(basename "$parameters" .par)_lists
run() {  # storage ranks args...
  storage=$1 ranks=$2
  shift 2
  "$mpiexec" "$numproc" "$ranks" ${FLECSPH_MPIEXEC_FLAGS:-} "$app" "$parameters" "$@" --set neighbour_lists=$storage \
    --set output_file=${stem}_$storage.h5part --set progress_every=0 --no-timers > ${stem}_$storage.log 2>&1 || {
    cat ${stem}_$storage.log
    echo "check_list_storage: the run with $storage lists failed"
    exit 1
  }
}
run packed 1 "$@"
run runs 2 "$@"
"$compare" ${stem}_packed.h5part ${stem}_runs.h5part
echo "check_list_storage: packed lists on 1 rank and runs on 2 give bitwise the same last output step"
