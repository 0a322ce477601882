#!/usr/bin/env bash
# Sanitizer build (issue 13): configures build-sanitize/ (Debug, -fsanitize=address,undefined,
# UBSan halting on the first error), builds it and runs the unit and MPI tests under it.
#
#   scripts/sanitize.sh [ctest regex]        default '^(unit|mpi)\.' ; e.g. '^mpi\.io\.' for a subset
#
# Environment: FLECSPH_SANITIZE_DIR (build folder), FLECSPH_JOBS (parallel jobs, default nproc),
# extra CMake arguments in FLECSPH_SANITIZE_CMAKE_ARGS (e.g. -DCMAKE_PREFIX_PATH=/opt/kokkos).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FLECSPH_SANITIZE_DIR:-$here/build-sanitize}"
jobs="${FLECSPH_JOBS:-$(nproc)}"
tests="${1:-^(unit|mpi)\.}"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# shellcheck disable=SC2086
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DFLECSPH_SANITIZE="address;undefined" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  ${FLECSPH_SANITIZE_CMAKE_ARGS:-} >"$build.configure.log" 2>&1 || { cat "$build.configure.log"; exit 1; }
# Only the programs of the selected tests (a full sanitizer build takes hours on a small machine):
# every target of each test's folder (<folder>/all) and the paths under $build in its command.
targets=$(cd "$build" && ctest --show-only=json-v1 -R "$tests" | python3 -c '
import json, os, sys
build, targets = sys.argv[1], set()
for test in json.load(sys.stdin)["tests"]:
    targets |= {os.path.basename(a) for a in test.get("command", []) if a.startswith(build + "/")}
    for p in test.get("properties", []):
        if p["name"] == "WORKING_DIRECTORY" and p["value"].startswith(build + "/"):
            targets.add(os.path.relpath(p["value"], build) + "/all")
print(" ".join(sorted(targets)))
' "$build")
[ -n "$targets" ] || { echo "sanitize.sh: no test matches '$tests'"; exit 1; }
# shellcheck disable=SC2086
cmake --build "$build" -j "$jobs" --target $targets
# detect_leaks=0: Open MPI and HDF5 keep allocations alive until exit by design (hundreds of
# "leaks" per MPI run that are not ours); memory errors and UB still stop the test.
# halt_on_error / abort_on_error: the first error fails the test with its report on stderr.
export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:abort_on_error=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
export OMP_PROC_BIND=false
cd "$build" && ctest -R "$tests" -j "$jobs" --output-on-failure
