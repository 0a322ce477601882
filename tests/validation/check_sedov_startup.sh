#!/bin/sh
# Sedov's start-up energy error is the leapfrog's time-integration error (issue 13, item 16;
# docs/sedov.md): the relative energy change over the first steps (to t = END) falls by at least
# RATIO between Courant factors 0.3 and 0.1 (second order: 9; reached 7.1 at 64^2). An error of
# another source (a non-conservative force, the h iteration, a dt jump) would not fall with dt.
#   check_sedov_startup.sh SEDOV PARAMETER_FILE END RATIO [--set ...]
set -eu
sedov=$1 file=$2 end=$3 ratio=$4
shift 4
change() {  # COURANT [--set ...]
  courant=$1
  shift
  "$sedov" "$file" --set "courant=$courant" --set "end_time=$end" --set "output_file=startup_$courant.h5part" \
    --set checkpoint_file=none --set output_every=0 --set progress_every=0 --set diagnostics_every=0 --no-timers "$@" |
    sed -n 's/.*relative energy change \([^ ]*\)$/\1/p' | tail -1
}
coarse=$(change 0.3 "$@")
fine=$(change 0.1 "$@")
echo "relative energy change to t = $end: $coarse at courant 0.3, $fine at courant 0.1"
awk -v c="$coarse" -v f="$fine" -v r="$ratio" 'BEGIN {
  if (c == "" || f == "" || f == 0) { print "no energy change read"; exit 1 }
  c = c < 0 ? -c : c; f = f < 0 ? -f : f; printf "ratio %.2f (required > %s)\n", c / f, r
  exit !(c / f > r) }'
