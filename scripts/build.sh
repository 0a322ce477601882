#!/usr/bin/env bash
# Installs the dependencies (idempotent), configures and builds FleCSPH-lite in build/ (Release).
# Extra arguments go to CMake's configure step, e.g. -DCMAKE_BUILD_TYPE=Debug.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/install_deps.sh"
build="${FLECSPH_BUILD_DIR:-$here/build}"
mkdir -p "$build"
# With the clients (scripts/run_tests.sh): the snapshot readers are installed while the code
# builds (their download takes minutes), the snapshot client tests run on their venv and fail
# (instead of being skipped) when a reader is missing there.
clients=() installer=""
if [ "${FLECSPH_INSTALL_CLIENTS:-0}" = 1 ]; then
  clients=(-DFLECSPH_SNAPSHOT_PYTHON="$here/.deps/snapshot-clients/bin/python" -DFLECSPH_REQUIRE_SNAPSHOT_CLIENTS=ON)
  bash "$here/scripts/install_snapshot_clients.sh" >"$build/snapshot-clients.log" 2>&1 &
  installer=$!
fi
cmake -S "$here" -B "$build" -G Ninja "${clients[@]}" "$@" >"$build/configure.log" 2>&1 || {
  cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"
if [ -n "$installer" ]; then
  wait "$installer" || { cat "$build/snapshot-clients.log"; echo "build.sh: the snapshot readers failed to install"; exit 1; }
  cat "$build/snapshot-clients.log"
fi
