#!/bin/sh
# A rerun that writes fewer snapshots than an earlier run of the same name: the earlier run's later
# `<stem>_NNNN.hdf5` are removed only once the new run has written its series and index and passed
# its checks; a run that fails its checks removes nothing; a file there that is not a FleCSPH-lite
# snapshot is never removed. check_snapshots.py then finds one snapshot per H5Part step.
#
#   check_stale_snapshots.sh PYTHON CHECK_SCRIPT APP PARAMETERS MPIEXEC [FLAGS...] NUMPROC_FLAG
set -eu
python=$1 check=$2 app=$3 parameters=$4
shift 4  # the rest launches n ranks when followed by n
rm -f stale*
common="$parameters --set particles=100 --set output_format=both --set output_file=stale.h5part
  --set output_every=0.05 --set progress_every=0 --set diagnostics_every=0 --no-timers"
# shellcheck disable=SC2086
"$@" 2 "$app" $common  # t = 0 ... 0.2: stale_0000 ... stale_0004
test -f stale_0004.hdf5 && test ! -f stale_0005.hdf5
# To t = 0.1 (3 snapshots), failing its check (bounds no run meets): the later two stay.
# shellcheck disable=SC2086
if "$@" 2 "$app" $common --set end_time=0.1 --check-l1 1e-12,1e-12,1e-12 >stale_failed.log 2>&1; then
  echo "the run with impossible L1 bounds passed"; exit 1
fi
test -f stale_0003.hdf5 && test -f stale_0004.hdf5 || { echo "a failed run removed snapshots"; exit 1; }
# The same run passing: stale_0003 and stale_0004 removed and named.
# shellcheck disable=SC2086
"$@" 2 "$app" $common --set end_time=0.1 >stale_passed.log 2>&1 || { cat stale_passed.log; exit 1; }
test ! -f stale_0003.hdf5 && test ! -f stale_0004.hdf5 || { echo "stale snapshots left"; exit 1; }
grep -q "removed 'stale_0004.hdf5', a snapshot of an earlier run beyond this series" stale_passed.log ||
  { cat stale_passed.log; echo "the removal was not reported"; exit 1; }
"$python" "$check" stale.h5part
# A file of another origin where the next snapshot would be: left in place, with a warning.
echo "not a snapshot" >stale_0003.hdf5
# shellcheck disable=SC2086
"$@" 2 "$app" $common --set end_time=0.1 >stale_foreign.log 2>&1 || { cat stale_foreign.log; exit 1; }
test "$(cat stale_0003.hdf5)" = "not a snapshot" || { echo "a foreign file was removed"; exit 1; }
grep -q "'stale_0003.hdf5' follows this run's snapshots but is not a FleCSPH-lite snapshot: left in place" \
  stale_foreign.log || { cat stale_foreign.log; exit 1; }
echo "check_stale_snapshots: stale snapshots removed after a successful rerun only; a failed run and foreign files keep theirs"
