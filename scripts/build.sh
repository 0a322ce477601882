#!/usr/bin/env bash
# Installs the dependencies (idempotent), configures and builds FleCSPH-lite in build/ (Release).
# Extra arguments go to CMake's configure step, e.g. -DCMAKE_BUILD_TYPE=Debug.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/install-deps.sh"
build="${FLECSPH_BUILD_DIR:-$here/build}"
mkdir -p "$build"
# With the clients (scripts/run-tests.sh): the snapshot client tests run on the venv that
# install-deps.sh made, and fail (instead of being skipped) when a reader is missing there.
clients=()
if [ "${FLECSPH_INSTALL_CLIENTS:-0}" = 1 ]; then
  clients=(-DFLECSPH_SNAPSHOT_PYTHON="$here/.deps/snapshot-clients/bin/python" -DFLECSPH_REQUIRE_SNAPSHOT_CLIENTS=ON)
fi
cmake -S "$here" -B "$build" -G Ninja "${clients[@]}" "$@" >"$build/configure.log" 2>&1 || {
  cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"
