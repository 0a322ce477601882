#!/usr/bin/env bash
# Sets everything up on a fresh Debian bookworm machine, builds, and runs the whole test suite
# (unit, MPI at several rank counts, application end-to-end tests, and ParaView, splash and the
# plot scripts reading our output). This is what CI runs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
FLECSPH_INSTALL_CLIENTS=1 bash "$here/scripts/build.sh"  # with the viewers tests/clients runs
build="${FLECSPH_BUILD_DIR:-$here/build}"
export OMP_PROC_BIND=false
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure --timeout 900
