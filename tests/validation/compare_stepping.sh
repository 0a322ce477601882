#!/bin/sh
# Individual against global time steps on the same problem (issue 15):
#   compare_stepping.sh <sedov or sod binary> <parameter file> [--set key=value ...]
# runs the problem with time_steps = global and = individual, then checks: for Sedov, the shock
# front of the individual run within 1% of the global run's and its energy change within 1e-3; for
# Sod, each L1 error (density, pressure, velocity) within 10% of the global run's. Prints both.
set -eu
app=$1
parameters=$2
shift 2
name=$(basename "$parameters" .par)
for stepping in global individual; do
  "$app" "$parameters" "$@" --set time_steps=$stepping --set output_file=stepping_${name}_$stepping.h5part \
    --set progress_every=0 --set diagnostics_every=0 --no-timers > stepping_${name}_$stepping.log 2>&1 || {
    cat stepping_${name}_$stepping.log
    echo "compare_stepping: the $stepping run failed"
    exit 1
  }
  grep -E "shock front|L1 errors|individual time steps" stepping_${name}_$stepping.log || true
done
global=stepping_${name}_global.log
individual=stepping_${name}_individual.log
if grep -q "shock front" "$global"; then
  # "... the shock front (half height) is at r = R, ... relative energy change E"
  front() { sed -n 's/.*shock front (half height) is at r = \([^,]*\),.*/\1/p' "$1"; }
  energy() { sed -n 's/.*shock front.*relative energy change \([^ ]*\).*/\1/p' "$1"; }
  awk -v g="$(front "$global")" -v i="$(front "$individual")" -v e="$(energy "$individual")" 'BEGIN {
    d = i / g - 1; if (d < 0) d = -d; if (e < 0) e = -e
    printf "compare_stepping: shock front %.6f individual, %.6f global: relative difference %.3g (bound 0.01); energy change %.3g (bound 1e-3)\n", i, g, d, e
    exit !(d <= 0.01 && e <= 1e-3) }'
else
  # "sod: L1 errors at t = ... : density A, pressure B, velocity C"
  errors() { sed -n 's/.*L1 errors.*density \([^,]*\), pressure \([^,]*\), velocity \([^ ]*\).*/\1 \2 \3/p' "$1"; }
  awk -v g="$(errors "$global")" -v i="$(errors "$individual")" 'BEGIN {
    split(g, G, " "); split(i, I, " "); split("density pressure velocity", N, " "); ok = 1
    for (k = 1; k <= 3; ++k) {
      r = I[k] / G[k]
      printf "compare_stepping: L1 %s %.4e individual, %.4e global: ratio %.4f (bound 1.1)\n", N[k], I[k], G[k], r
      if (!(r <= 1.1)) ok = 0
    }
    exit !ok }'
fi
