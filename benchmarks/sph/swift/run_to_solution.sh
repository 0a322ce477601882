#!/usr/bin/env bash
# Runs SWIFT and our sedov app on the same 3D Sedov blast to the same end time, both with
# individual time steps and the time-step limiter, interleaved, and prints for each: the wall time
# of the whole run, the particle updates, the time per update and the peak resident memory.
#
#   SWIFT_BINARY=/tmp/swift-build/swift benchmarks/sph/swift/run_to_solution.sh --per-side 50
#
# Options: --per-side N (50), --end-time T (0.02), --repeats R (3), --threads "1 2" (the layouts,
# 1 rank x T threads). Environment: SWIFT_BINARY (required: SWIFT built with gadget2 hydro and
# the cubic spline, README.md beside this file), BUILD (default build: our build folder),
# PYTHON (default /usr/bin/python3: numpy and h5py, for the initial conditions), SWIFT_CFL
# (default 0.075, below); OMP_WAIT_POLICY passes to ours (on a busy machine `passive`: below).
#
# The same problem as run_side_by_side.sh (README.md: lattice, mass, h, support of 93 neighbours,
# blast), now to the end time:
# - ours: `sedov apps/sedov/sedov_3d.par` with eta 1.42, time_steps = individual and
#   time_step_limiter = 4 (no particle's step more than 4 times its neighbours'), courant 0.3, no
#   output, the conserved totals and statistics row only at the start and the end (as SWIFT's
#   sedov.yml: no statistics; ours measures exact sums over every particle for a row, 21% of a
#   run with a row every step); the updates are its "particle updates" line.
# - SWIFT: `swift --hydro --limiter` (its limiter: at most 2 time bins, a factor 4, above the
#   neighbours'), dt_min 1e-12, dt_max the end time; the updates are the sum of its steps'
#   "Updates" (steps 1 on, its step 0 being the initial density and force pass). SWIFT's
#   Courant step is 2 kernel_gamma CFL h_swift / v_sig = 4 CFL h / v_sig with our h, ours
#   0.3 h / v_sig: SWIFT_CFL = 0.075 asks both for the same step.
# Both sides are timed as whole processes by /usr/bin/time (set-up and initial conditions
# included: the time to solution), which also gives their CPU seconds (user + system, all threads)
# and the peak resident set size (libraries included). The table gives medians over the repeats and the ratio ours / SWIFT (below 1: ours
# is faster). Other processes on the machine change both sides' times: `uptime` is printed before
# and after.
set -euo pipefail

usage() { sed -n '2,30p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
die() { echo "run_to_solution.sh: $*" >&2; exit 1; }

per_side=50 end_time=0.02 repeats=3 layouts="1 2"
while [ $# -gt 0 ]; do
  case "$1" in
    --per-side) per_side=${2:?--per-side needs a value}; shift 2 ;;
    --end-time) end_time=${2:?--end-time needs a value}; shift 2 ;;
    --repeats) repeats=${2:?--repeats needs a value}; shift 2 ;;
    --threads) layouts=${2:?--threads needs a value}; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; die "unknown argument '$1'" ;;
  esac
done
for pair in "per-side:$per_side" "repeats:$repeats"; do
  [[ "${pair#*:}" =~ ^[1-9][0-9]*$ ]] || die "--${pair%%:*} takes a whole number of at least 1, not '${pair#*:}'"
done
[ "$per_side" -ge 4 ] || die "--per-side must be at least 4"
[[ "$end_time" =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || die "--end-time takes a positive number, not '$end_time'"
for threads in $layouts; do
  [[ "$threads" =~ ^[1-9][0-9]*$ ]] || die "--threads takes whole numbers of at least 1, not '$threads'"
done

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
[ -n "${SWIFT_BINARY:-}" ] || die "set SWIFT_BINARY to the swift executable (see $here/README.md for how to build it)"
[ -f "$SWIFT_BINARY" ] && [ -x "$SWIFT_BINARY" ] || die "SWIFT_BINARY='$SWIFT_BINARY' is not an executable file"
swift=$(cd "$(dirname "$SWIFT_BINARY")" && pwd)/$(basename "$SWIFT_BINARY")
build=${BUILD:-build}
[[ "$build" = /* ]] || build="$root/$build"
sedov="$build/apps/sedov/sedov"
[ -x "$sedov" ] || die "$sedov is not built (BUILD=$build)"
[ -x /usr/bin/time ] || die "/usr/bin/time is needed for the wall time and peak memory (apt-get install time)"
python=${PYTHON:-/usr/bin/python3}
swift_cfl=${SWIFT_CFL:-0.075}

work=$(mktemp -d "${TMPDIR:-/tmp}/to_solution.XXXXXX")
trap 'rm -rf "$work"' EXIT
particles=$((per_side * per_side * per_side))
"$python" "$here/make_sedov_ics.py" "$per_side" "$work/sedov.hdf5"

# "wall_seconds peak_kbytes cpu_seconds" from a /usr/bin/time -v report (cpu: user + system, all
# threads: on a busy machine the figure that other processes change least).
time_report() {
  awk '/Elapsed \(wall clock\) time/ { n = split($NF, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = 60 * s + t[i] }
       /Maximum resident set size/ { kb = $NF }
       /User time \(seconds\)/ || /System time \(seconds\)/ { cpu += $NF }
       END { if (s == "" || kb == "") exit 1; printf "%.3f %d %.3f\n", s, kb, cpu }' "$1"
}

# One run of ours on 1 rank x $1 threads: "wall_seconds peak_kbytes cpu_seconds updates steps".
ours_run() {
  local dir="$work/ours_$1_$2"
  mkdir -p "$dir"
  (cd "$dir" && OMP_NUM_THREADS=$1 OMP_PROC_BIND=false /usr/bin/time -v -o time.txt "$sedov" \
      "$root/apps/sedov/sedov_3d.par" --set particles_per_side="$per_side" --set eta=1.42 \
      --set end_time="$end_time" --set time_steps=individual --set time_step_limiter=4 \
      --set output_every=0 --set progress_every=1000000 --set diagnostics_every=1000000 \
      --set statistics_every=1000000 --no-timers >stdout.txt 2>&1) ||
    { tail -20 "$dir/stdout.txt" >&2; die "our sedov failed on $1 thread(s)"; }
  local measured updates
  measured=$(time_report "$dir/time.txt") || die "no /usr/bin/time report in $dir/time.txt"
  # "sph: individual time steps: U particle updates in S steps (...)"
  updates=$(awk '/particle updates in/ { for (i = 1; i < NF; ++i) if ($(i + 1) == "particle") u = $i
                                        for (i = 1; i < NF; ++i) if ($i == "in") s = $(i + 1) }
                 END { if (u == "") exit 1; print u, s }' "$dir/stdout.txt") ||
    { cat "$dir/stdout.txt" >&2; die "no 'particle updates' line in our output"; }
  echo "$measured $updates"
}

# One SWIFT run on $1 threads: "wall_seconds peak_kbytes cpu_seconds updates steps".
swift_run() {
  local dir="$work/swift_$1_$2"
  mkdir -p "$dir"
  (cd "$dir" && /usr/bin/time -v -o time.txt "$swift" --hydro --limiter --threads="$1" --no-io \
      -P "TimeIntegration:time_end:$end_time" -P "TimeIntegration:dt_min:1e-12" \
      -P "TimeIntegration:dt_max:$end_time" -P "SPH:CFL_condition:$swift_cfl" \
      -P "InitialConditions:file_name:$work/sedov.hdf5" "$here/sedov.yml" >swift.log 2>&1) ||
    { tail -20 "$dir/swift.log" >&2; die "SWIFT failed on $1 thread(s)"; }
  local measured updates
  measured=$(time_report "$dir/time.txt") || die "no /usr/bin/time report in $dir/time.txt"
  # Step lines: step, time, a, z, dt, 2 time bins, updates, g-, s-, sink-, b-updates, wall [ms], ...
  updates=$(awk '$1 ~ /^[0-9]+$/ && NF >= 15 && $2 ~ /^[0-9.]+e[-+][0-9]+$/ && $1 >= 1 { u += $8; ++s }
                 END { if (s == 0) exit 1; printf "%d %d\n", u, s }' "$dir/swift.log") ||
    { tail -20 "$dir/swift.log" >&2; die "no step lines in SWIFT's log"; }
  echo "$measured $updates"
}

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[++n] = $1 } END { printf "%.6g", n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2 }'; }

echo "problem: Sedov 3D ${per_side}^3 = $particles particles to t = $end_time, individual time steps, limiter 4"
echo "SWIFT: $swift (CFL_condition $swift_cfl)"
echo "ours:  $sedov (OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-unset}: passive keeps waiting threads off a busy machine's cores)"
echo "load before: $(uptime)"
declare -A results
for ((r = 1; r <= repeats; ++r)); do
  for threads in $layouts; do
    for code in ours swift; do
      # A failure inside the process substitution cannot stop this shell: an empty line does.
      wall="" kb="" cpu="" updates="" steps=""
      read -r wall kb cpu updates steps < <("${code}_run" "$threads" "$r") || true
      [ -n "${steps:-}" ] || die "the $code run (1x$threads, repeat $r) gave no result"
      echo "repeat $r, 1x$threads, $code: $wall s ($cpu s cpu), $updates updates in $steps steps, peak $kb kB"
      results[$code,$threads,wall]+=" $wall"
      results[$code,$threads,cpu]+=" $cpu"
      results[$code,$threads,updates]+=" $updates"
      results[$code,$threads,steps]+=" $steps"
      results[$code,$threads,per_update]+=" $(awk -v w="$wall" -v u="$updates" 'BEGIN { printf "%.6g", 1e6 * w / u }')"
      results[$code,$threads,bytes]+=" $(awk -v k="$kb" -v n="$particles" 'BEGIN { printf "%.1f", 1024 * k / n }')"
    done
  done
done
echo "load after:  $(uptime)"

echo
echo "Sedov 3D ${per_side}^3 to t = $end_time, medians of $repeats repeats (ratio = ours / SWIFT: below 1, ours is faster)"
printf "%-7s %-6s %10s %10s %12s %7s %14s %16s\n" layout code "wall s" "cpu s" updates steps "us / update" "peak B / part."
for threads in $layouts; do
  for code in ours swift; do
    printf "%-7s %-6s %10s %10s %12s %7s %14s %16s\n" "1x$threads" "$code" \
      "$(median <<<"${results[$code,$threads,wall]}")" "$(median <<<"${results[$code,$threads,cpu]}")" \
      "$(median <<<"${results[$code,$threads,updates]}")" \
      "$(median <<<"${results[$code,$threads,steps]}")" "$(median <<<"${results[$code,$threads,per_update]}")" \
      "$(median <<<"${results[$code,$threads,bytes]}")"
  done
  printf "%-7s %-6s %10.3f %10.3f %12s %7s %14.3f %16.3f\n" "1x$threads" ratio \
    "$(awk -v o="$(median <<<"${results[ours,$threads,wall]}")" -v s="$(median <<<"${results[swift,$threads,wall]}")" 'BEGIN { print o / s }')" \
    "$(awk -v o="$(median <<<"${results[ours,$threads,cpu]}")" -v s="$(median <<<"${results[swift,$threads,cpu]}")" 'BEGIN { print o / s }')" \
    "" "" \
    "$(awk -v o="$(median <<<"${results[ours,$threads,per_update]}")" -v s="$(median <<<"${results[swift,$threads,per_update]}")" 'BEGIN { print o / s }')" \
    "$(awk -v o="$(median <<<"${results[ours,$threads,bytes]}")" -v s="$(median <<<"${results[swift,$threads,bytes]}")" 'BEGIN { print o / s }')"
done
