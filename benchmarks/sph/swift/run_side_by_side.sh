#!/usr/bin/env bash
# Runs SWIFT and our bench_sedov on the same 3D Sedov blast (lattice, support, all particles
# active every step: see README.md beside this file), interleaved, and prints the time per step
# of each and their ratio.
#
#   SWIFT_BINARY=/tmp/swift-build/swift benchmarks/sph/swift/run_side_by_side.sh --per-side 50 --steps 5
#
# Options: --per-side N (50), --steps S (5: timed steps, after one warm-up step on both sides),
# --repeats R (3). Environment: SWIFT_BINARY (required: SWIFT built with gadget2 hydro and the
# cubic spline), BUILD (default build: our build folder, relative to the repository root
# or absolute), PYTHON (default /usr/bin/python3: numpy and h5py, for the initial conditions).
#
# Each repeat runs ours 1 rank x 1 thread, SWIFT 1 thread, ours 1 x 2 threads, SWIFT 2 threads.
# Ours: bench_sedov's wall time per step (mean over its timed steps, after 1 warm-up step), as
# N^3 / its "throughput:" line.
# SWIFT: the median of the "Wall-clock time [ms]" of its steps 2..S+1 (step 0 is its initial fake
# step, step 1 the warm-up). The table gives the median over the repeats of each, and the ratio
# ours / SWIFT (above 1: ours is slower).
set -euo pipefail

usage() { sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
die() { echo "run_side_by_side.sh: $*" >&2; exit 1; }

per_side=50 steps=5 repeats=3
while [ $# -gt 0 ]; do
  case "$1" in
    --per-side) per_side=${2:?--per-side needs a value}; shift 2 ;;
    --steps) steps=${2:?--steps needs a value}; shift 2 ;;
    --repeats) repeats=${2:?--repeats needs a value}; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; die "unknown argument '$1'" ;;
  esac
done
for pair in "per-side:$per_side" "steps:$steps" "repeats:$repeats"; do
  [[ "${pair#*:}" =~ ^[1-9][0-9]*$ ]] || die "--${pair%%:*} takes a whole number of at least 1, not '${pair#*:}'"
done
[ "$per_side" -ge 4 ] || die "--per-side must be at least 4"

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
[ -n "${SWIFT_BINARY:-}" ] || die "set SWIFT_BINARY to the swift executable (see $here/README.md for how to build it)"
[ -f "$SWIFT_BINARY" ] && [ -x "$SWIFT_BINARY" ] || die "SWIFT_BINARY='$SWIFT_BINARY' is not an executable file"
swift=$(cd "$(dirname "$SWIFT_BINARY")" && pwd)/$(basename "$SWIFT_BINARY")
build=${BUILD:-build}
[[ "$build" = /* ]] || build="$root/$build"
bench="$build/benchmarks/sph/bench_sedov"
[ -x "$bench" ] || die "$bench is not built (BUILD=$build)"
python=${PYTHON:-/usr/bin/python3}

work=$(mktemp -d "${TMPDIR:-/tmp}/side_by_side.XXXXXX")
trap 'rm -rf "$work"' EXIT

particles=$((per_side * per_side * per_side))
ics_line=$("$python" "$here/make_sedov_ics.py" "$per_side" "$work/sedov.hdf5")
echo "$ics_line"
dt=$(awk '{ for (i = 1; i < NF; ++i) if ($i == "courant_dt") print $(i + 1) }' <<<"$ics_line")
[ -n "$dt" ] || die "no courant_dt in the output of make_sedov_ics.py"
# SWIFT's time line is time_end / 2^k: time_end = 2^k dt with 2^k at least the steps run, and
# dt_max a hair above dt (dt_min a hair below: SWIFT aborts if a particle wants less).
read -r time_end dt_min dt_max < <(awk -v dt="$dt" -v n="$((steps + 2))" 'BEGIN {
  k = 64; while (k < n) k *= 2; printf "%.10e %.10e %.10e\n", k * dt, 0.9999 * dt, 1.0001 * dt }')

# Seconds per step of one SWIFT run on $1 threads; its log is kept as $work/swift_$1_$2.log.
swift_run() {
  local log="$work/swift_$1_$2.log"
  (cd "$work" && "$swift" --hydro --threads="$1" --no-io -n "$steps" \
      -P "TimeIntegration:time_end:$time_end" -P "TimeIntegration:dt_min:$dt_min" \
      -P "TimeIntegration:dt_max:$dt_max" -P "InitialConditions:file_name:$work/sedov.hdf5" \
      "$here/sedov.yml") >"$log" 2>&1 || { tail -20 "$log" >&2; die "SWIFT failed on $1 thread(s)"; }
  # Step lines: step, time, a, z, dt, 2 time bins, updates, g-, s-, sink-, b-updates, wall [ms], ...
  awk -v particles="$particles" -v steps="$steps" -v log_file="$log" '
    $1 ~ /^[0-9]+$/ && NF >= 15 && $2 ~ /^[0-9.]+e[-+][0-9]+$/ {
      if ($1 >= 1 && $8 != particles) {
        printf "run_side_by_side.sh: SWIFT step %d updated %s of %d particles (%s)\n", $1, $8, particles, log_file > "/dev/stderr"
        bad = 1
      }
      if ($1 >= 2) wall[++n] = $13 / 1000
    }
    END {
      if (n != steps || bad) { printf "run_side_by_side.sh: SWIFT ran %d timed steps of %d with all particles active: see %s\n", n, steps, log_file > "/dev/stderr"; exit 1 }
      for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (wall[j] < wall[i]) { t = wall[i]; wall[i] = wall[j]; wall[j] = t }
      printf "%.6f\n", n % 2 ? wall[(n + 1) / 2] : (wall[n / 2] + wall[n / 2 + 1]) / 2
    }' "$log" || { cat "$log" >&2; die "unexpected SWIFT output"; }
}

# Seconds per step of one bench_sedov run on 1 rank x $1 threads.
ours_run() {
  local output
  output=$(OMP_NUM_THREADS=$1 OMP_PROC_BIND=false "$bench" --per-side "$per_side" --steps "$steps" 2>&1) ||
    { echo "$output" >&2; die "bench_sedov failed on $1 thread(s)"; }
  # "throughput: X particle-steps/s" (5 digits; "wall time per step" prints 4 decimals) over N^3.
  awk -v particles="$particles" '/^throughput:/ { printf "%.6f\n", particles / $2 }' <<<"$output"
}

median() { tr ' ' '\n' | sort -g | awk '{ v[++n] = $1 } END { printf "%.6f", n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2 }'; }

echo "problem: ${per_side}^3 = $particles particles, $steps timed steps after 1 warm-up; SWIFT dt $dt fixed (time_end $time_end)"
echo "SWIFT: $swift"
echo "ours:  $bench"
echo "load before: $(uptime)"
declare -A ours theirs
for ((r = 1; r <= repeats; ++r)); do
  for threads in 1 2; do
    o=$(ours_run "$threads")
    [ -n "$o" ] || die "no 'throughput:' line in bench_sedov's output"
    s=$(swift_run "$threads" "$r")
    echo "repeat $r, 1x$threads: ours $o s/step, SWIFT $s s/step"
    ours[$threads]="${ours[$threads]:-} $o"
    theirs[$threads]="${theirs[$threads]:-} $s"
  done
done
echo "load after:  $(uptime)"

echo
echo "${per_side}^3 Sedov, $steps timed steps, median of $repeats repeats (ratio = ours / SWIFT)"
printf "%-8s %14s %14s %8s\n" layout "ours s/step" "SWIFT s/step" ratio
for threads in 1 2; do
  o=$(median <<<"${ours[$threads]# }") s=$(median <<<"${theirs[$threads]# }")
  printf "%-8s %14.4f %14.4f %8.2f\n" "1x$threads" "$o" "$s" "$(awk -v o="$o" -v s="$s" 'BEGIN { print o / s }')"
done
