#!/bin/sh
# Self-gravity with individual time steps walks only the active particles' groups and defers the
# rest until the totals or the files read every particle's potential (step/gravity.hh):
#   check_deferred_gravity.sh <evrard> <compare_h5part> <mpiexec> <numproc flag> <parameter file> [--set ...]
# runs the problem twice: with totals every step (each step walks every group) and, on 2 ranks,
# with a statistics row every 5th step and no conserved lines between (most steps walk the active
# groups only). The last output steps must be bitwise equal, and so must every statistics row of
# the second run and the first run's row of the same step.
set -eu
app=$1 compare=$2 mpiexec=$3 numproc=$4 parameters=$5
shift 5
run() {  # name ranks args...
  name=$1 ranks=$2
  shift 2
  "$mpiexec" "$numproc" "$ranks" ${FLECSPH_MPIEXEC_FLAGS:-} "$app" "$parameters" "$@" --set output_file=deferred_$name.h5part \
    --set statistics_file=deferred_$name.statistics.txt --set progress_every=0 > deferred_$name.log 2>&1 || {
    cat deferred_$name.log
    echo "check_deferred_gravity: the $name run failed"
    exit 1
  }
}
run every_step 1 "$@" --set diagnostics_every=1 --set statistics_every=1
run deferred 2 "$@" --set diagnostics_every=0 --set statistics_every=5
"$compare" deferred_every_step.h5part deferred_deferred.h5part
grep -v '^#' deferred_deferred.statistics.txt > deferred_rows.txt
rows=$(wc -l < deferred_rows.txt)
awk 'NR == FNR { if ($0 !~ /^#/) row[$1] = $0; next }
     { if (!($1 in row)) { print "check_deferred_gravity: step " $1 " missing in the every-step run"; bad = 1 }
       else if (row[$1] != $0) { print "check_deferred_gravity: the rows of step " $1 " differ:\n" row[$1] "\n" $0; bad = 1 } }
     END { exit bad }' deferred_every_step.statistics.txt deferred_rows.txt
echo "check_deferred_gravity: the last output steps are bitwise equal, and the $rows statistics rows of the deferred run equal the every-step run's"

