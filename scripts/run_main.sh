#!/usr/bin/env bash
# Sets everything up on a fresh Debian bookworm machine, builds, and runs the main job: the Sod
# shock tube (1D, 1000 particles, t = 0.2) on 2 MPI ranks, with H5Part output, the L1 errors
# against the exact Riemann solution, and a PNG plot. Output goes to out/.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/build.sh"
build="${FLECSPH_BUILD_DIR:-$here/build}"
source "$here/scripts/mpirun_flags.sh"
mkdir -p "$here/out"
cd "$here/out"
export OMP_PROC_BIND=false OMP_NUM_THREADS=1
mpirun -np 2 "${FLECSPH_MPIRUN_FLAGS[@]}" "$build/apps/sod/sod" "$here/apps/sod/sod_1d.par" \
  --set output_file=sod.h5part
/usr/bin/python3 "$here/apps/sod/plot_sod.py" sod.h5part --output sod.png \
  --exact "$build/apps/exact/exact_solution"
echo "main job done: output $here/out/sod.h5part (ParaView: H5PartReader), plot $here/out/sod.png"
