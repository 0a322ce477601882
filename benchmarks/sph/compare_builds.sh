#!/usr/bin/env bash
# Runs bench_sedov of several builds on 1 rank x 1 thread, 1 rank x 2 threads and 2 ranks x 1
# thread, interleaved (build after build within each layout, ROUNDS times), and prints per build
# and layout: time per step, particle-steps per second, cycles per list entry of the forces and
# the density, search and refit per step, the share of each, peak bytes per particle, and the
# speed-up over the first build; writes the figures to OUT.csv and a PNG of them (OUT.png).
#
#   BUILDS="old=/tmp/old/build default=build native=build-native" \
#     benchmarks/sph/compare_builds.sh --per-side 50 --steps 5
#
# BUILDS: NAME=BUILD_DIR ... (default: "default=build"); ROUNDS (default 1); OUT (default
# compare_builds); LAYOUTS (default "1x1 1x2 2x1"). Other arguments go to bench_sedov.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
source "$here/scripts/mpirun_flags.sh"
export OMP_PROC_BIND=false
builds=(${BUILDS:-default=$here/build})
rounds=${ROUNDS:-1}
out=${OUT:-compare_builds}
layouts=(${LAYOUTS:-1x1 1x2 2x1})
for b in "${builds[@]}"; do
  [ -x "${b#*=}/benchmarks/sph/bench_sedov" ] || { echo "compare_builds.sh: ${b#*=}/benchmarks/sph/bench_sedov not built" >&2; exit 1; }
done

# One run: the figures of bench_sedov's report as one CSV row.
run() {  # name dir ranks threads args...
  local name=$1 dir=$2 ranks=$3 threads=$4 output
  shift 4
  if [ "$ranks" -eq 1 ]; then
    output=$(OMP_NUM_THREADS=$threads "$dir/benchmarks/sph/bench_sedov" "$@")
  else
    output=$(OMP_NUM_THREADS=$threads mpirun -np "$ranks" "${FLECSPH_MPIRUN_FLAGS[@]}" "$dir/benchmarks/sph/bench_sedov" "$@")
  fi
  # Cycles from the timers (so that builds older than bench_sedov's cycle line compare too).
  awk -v name="$name" -v layout="${ranks}x${threads}" -v ghz="$clock_ghz" '
    /^bench_sedov:/ { particles = $4; cores = $8 * $11 }
    /wall time per step/ { step = $5 }
    /^throughput:/ { throughput = $2 }
    /neighbours per particle/ { for (i = 1; i < NF; ++i) if ($(i + 1) == "in" && $(i + 2) == "the" && $(i + 3) == "lists") entries = $i }
    /sph::compute_forces / { forces = $4; forces_share = $NF }
    /sph::compute_density / { density = $4; density_share = $NF }
    /sph::search_neighbours / { search += $4; search_share = $NF }
    /ntree::refit / { search += $4 }
    /peak resident memory/ { peak = $8 }
    END { pairs = entries * particles; if (peak == "") peak = "nan"
          printf "%s,%s,%s,%s,%.2f,%.2f,%.5f,%s,%s,%s,%s\n", name, layout, step, throughput, forces * ghz * 1e9 * cores / pairs,
          density * ghz * 1e9 * cores / pairs, search, forces_share, density_share, search_share, peak }' <<<"$output"
}

clock_ghz=$(awk -F: '/^cpu MHz/ { printf "%.3f", $2 / 1000; exit }' /proc/cpuinfo)
echo "load before: $(uptime); cycles at ${clock_ghz} GHz (/proc/cpuinfo)"
echo "build,layout,s_per_step,particle_steps_per_s,forces_cycles_per_entry,density_cycles_per_entry,search_refit_s_per_step,forces_share,density_share,search_share,peak_bytes_per_particle" >"$out.csv"
for layout in "${layouts[@]}"; do
  for ((r = 0; r < rounds; ++r)); do
    for b in "${builds[@]}"; do run "${b%%=*}" "${b#*=}" "${layout%x*}" "${layout#*x}" "$@" >>"$out.csv"; done
  done
done
echo "load after:  $(uptime)"
# Medians over the rounds, the speed-up over the first build of each layout.
/usr/bin/python3 - "$out" <<'EOF'
import csv, statistics, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(out + ".csv")))
keys = ["s_per_step", "particle_steps_per_s", "forces_cycles_per_entry", "density_cycles_per_entry",
        "search_refit_s_per_step", "peak_bytes_per_particle"]
table = {}
for r in rows:
    table.setdefault((r["layout"], r["build"]), []).append(r)
builds = list(dict.fromkeys(r["build"] for r in rows))
layouts = list(dict.fromkeys(r["layout"] for r in rows))
print(f"{'layout':7} {'build':10} {'s/step':>8} {'p-steps/s':>10} {'speed-up':>8} {'forces cyc':>10} {'density cyc':>11} "
      f"{'search s':>9} {'shares f/d/s':>18} {'peak B/p':>8}")
median = {}
for layout in layouts:
    for b in builds:
        runs = table[(layout, b)]
        median[(layout, b)] = {k: statistics.median(float(r[k]) for r in runs) for k in keys}
        m = median[(layout, b)]
        first = median[(layout, builds[0])]
        shares = "/".join(runs[len(runs) // 2][k] for k in ("forces_share", "density_share", "search_share"))
        print(f"{layout:7} {b:10} {m['s_per_step']:8.4f} {m['particle_steps_per_s']:10.4g} "
              f"{first['s_per_step'] / m['s_per_step']:8.2f} {m['forces_cycles_per_entry']:10.1f} "
              f"{m['density_cycles_per_entry']:11.1f} {m['search_refit_s_per_step']:9.4f} {shares:>18} "
              f"{m['peak_bytes_per_particle']:8.0f}")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("compare_builds.sh: no matplotlib for /usr/bin/python3, no PNG")
    sys.exit(0)
fig, axes = plt.subplots(1, 3, figsize=(13, 4))
width = 0.8 / len(builds)
for i, b in enumerate(builds):
    xs = [j + i * width for j in range(len(layouts))]
    axes[0].bar(xs, [median[(l, b)]["particle_steps_per_s"] for l in layouts], width, label=b)
    axes[1].bar(xs, [median[(l, b)]["forces_cycles_per_entry"] for l in layouts], width, label=b)
    axes[2].bar(xs, [median[(l, b)]["density_cycles_per_entry"] for l in layouts], width, label=b)
for ax, title in zip(axes, ["particle-steps per second", "forces: cycles per list entry",
                            "density: cycles per list entry"]):
    ax.set_xticks([j + 0.4 - width / 2 for j in range(len(layouts))], layouts)
    ax.set_title(title)
axes[0].legend()
fig.suptitle(f"bench_sedov, Sedov 3D ({out})")
fig.tight_layout()
fig.savefig(out + ".png", dpi=110)
print(f"wrote {out}.csv and {out}.png")
EOF
