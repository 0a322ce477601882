#!/usr/bin/env bash
# Installs the dependencies (idempotent), configures and builds FleCSPH-lite in build/ (Release).
# Extra arguments go to CMake's configure step, e.g. -DCMAKE_BUILD_TYPE=Debug.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/install-deps.sh"
build="${FLECSPH_BUILD_DIR:-$here/build}"
mkdir -p "$build"
cmake -S "$here" -B "$build" -G Ninja "$@" >"$build/configure.log" 2>&1 || {
  cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"
