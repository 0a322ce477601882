#!/usr/bin/env bash
# Sets everything up on a fresh Debian bookworm machine, builds, and runs the whole test suite
# (unit, MPI at several rank counts, application end-to-end tests). This is what CI runs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/build.sh"
build="${FLECSPH_BUILD_DIR:-$here/build}"
export OMP_PROC_BIND=false
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure --timeout 900
