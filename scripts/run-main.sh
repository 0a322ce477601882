#!/usr/bin/env bash
# Sets everything up on a fresh Debian bookworm machine, builds, and runs the main job on 2 MPI
# ranks. Output goes to out/.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/build.sh"
build="${FLECSPH_BUILD_DIR:-$here/build}"
source "$here/scripts/mpirun-flags.sh"
mkdir -p "$here/out"
cd "$here/out"
export OMP_PROC_BIND=false OMP_NUM_THREADS=1
mpirun -np 2 "${FLECSPH_MPIRUN_FLAGS[@]}" "$build/apps/heat/heat" --cells 1024 --time 0.002 \
  --analyze-every 500 --trace heat-trace.json
echo "main job done: executor trace in $here/out/heat-trace.json (open in https://ui.perfetto.dev)"
