#!/bin/sh
# Sod 1D converges: the L1 density error falls by at least ORDER powers of the resolution between
# N and 4 N particles (with the density-consistent lattice masses; without them it stalls at a
# floor of 1.3e-3, observed order ~0.4 between 1000 and 4000).
#   check_convergence.sh SOD PARAMETER_FILE N ORDER
set -eu
sod=$1 file=$2 n=$3 order=$4
l1() {
  "$sod" "$file" --set "particles=$1" --set "output_file=convergence_$1.h5part" --set output_every=0 \
    --set progress_every=0 --set diagnostics_every=0 --no-timers | sed -n 's/.*L1 errors.*: density \([^,]*\),.*/\1/p'
}
coarse=$(l1 "$n")
fine=$(l1 $((4 * n)))
echo "L1(rho) at $n particles: $coarse, at $((4 * n)): $fine"
awk -v c="$coarse" -v f="$fine" -v p="$order" 'BEGIN {
  if (!(c > 0 && f > 0)) { print "no L1 errors read"; exit 1 }
  observed = log(c / f) / log(4); printf "observed order %.3f (required > %s)\n", observed, p
  exit !(observed > p) }'
