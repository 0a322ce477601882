#!/bin/sh
# A run with output_format = both stopped early (max_steps, checkpoint) and resumed on another
# rank count must leave one snapshot per H5Part step, each equal to it (check_snapshots.py): the
# resumed run keeps the snapshots before its restart time and numbers on after them.
#
#   check_snapshot_restart.sh PYTHON CHECK_SCRIPT APP PARAMETERS MPIEXEC [FLAGS...] NUMPROC_FLAG
set -eu
python=$1 check=$2 app=$3 parameters=$4
shift 4  # the rest launches n ranks when followed by n
rm -f snapshot_restart*
common="$parameters --set particles=100 --set output_format=both --set output_file=snapshot_restart.h5part
  --set checkpoint_file=snapshot_restart_checkpoint.h5part --set progress_every=0 --set diagnostics_every=0 --no-timers"
# shellcheck disable=SC2086
"$@" 2 "$app" $common --set max_steps=150
test -f snapshot_restart_0003.hdf5 && test ! -f snapshot_restart_0004.hdf5
# shellcheck disable=SC2086
"$@" 1 "$app" $common --set max_steps=0 --set restart_file=snapshot_restart_checkpoint.h5part
"$python" "$check" snapshot_restart.h5part
