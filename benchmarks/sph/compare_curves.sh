#!/usr/bin/env bash
# Morton against Hilbert keys (seed sec. 2.3.1, issue 14 item 5): runs bench_sedov with each
# key_order on RANKS ranks of 1 thread, twice: as the run distributes (distribution_skin as in
# sedov_3d.par: time per step) and with a distribution in every step (distribution_skin = 0:
# particles and bytes moved per distribution, ghosts per owned particle, time per step with
# it). Prints a table, writes OUT.csv and OUT.png.
#
#   RANKS="2 4" benchmarks/sph/compare_curves.sh --per-side 50 --steps 5
#
# The moved particles and bytes are in the table and the CSV (the early Sedov steps move few).
# RANKS (default "2 4"); OUT (default compare_curves); BUILD (default build). Other arguments go to
# bench_sedov. With more ranks than cores the times are those of oversubscribed cores; the
# ghosts and the bytes moved do not depend on that.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
source "$here/scripts/mpirun_flags.sh"
cores=$(nproc)  # before OMP_NUM_THREADS, which nproc reports instead
export OMP_PROC_BIND=false OMP_NUM_THREADS=1
bench=${BUILD:-$here/build}/benchmarks/sph/bench_sedov
[ -x "$bench" ] || { echo "compare_curves.sh: $bench not built (cmake --build build --target bench_sedov)" >&2; exit 1; }
out=${OUT:-compare_curves}
ranks_list=(${RANKS:-2 4})

# One run: the figures of bench_sedov's report as one CSV row.
run() {  # ranks curve mode args...
  local ranks=$1 curve=$2 mode=$3 output
  shift 3
  local extra=()
  [ "$mode" = every_step ] && extra=(--set distribution_skin=0)
  output=$(mpirun -np "$ranks" --oversubscribe "${FLECSPH_MPIRUN_FLAGS[@]}" "$bench" --set key_order="$curve" \
    "${extra[@]}" "$@")
  awk -v ranks="$ranks" -v curve="$curve" -v mode="$mode" '
    /wall time per step/ { step = $5 }
    /^  distribution \(/ { ghosts = $4; ghosts_max = $9; moved = $21; bytes = $24; per_particle = $26
                           sub(/\(/, "", ghosts_max); sub(/\(/, "", per_particle) }
    /during the timed steps:/ { distributions = $5 }
    END { printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", ranks, curve, mode, step, distributions, ghosts, ghosts_max,
          moved, bytes, per_particle }' <<<"$output"
}

echo "load before: $(uptime); $cores cores"
echo "ranks,curve,mode,s_per_step,distributions,ghosts_per_owned,ghosts_per_owned_max_rank,moved_per_distribution,bytes_per_distribution,bytes_per_particle_per_distribution" >"$out.csv"
for ranks in "${ranks_list[@]}"; do
  for mode in as_needed every_step; do
    for curve in hilbert morton; do run "$ranks" "$curve" "$mode" "$@" >>"$out.csv"; done
  done
done
echo "load after:  $(uptime)"
/usr/bin/python3 - "$out" "$cores" <<'EOF'
import csv, sys
out, cores = sys.argv[1], int(sys.argv[2])
rows = list(csv.DictReader(open(out + ".csv")))
print(f"{'ranks':>5} {'curve':8} {'distribution':13} {'s/step':>8} {'distr.':>6} {'ghosts/owned':>12} {'(max rank)':>10} "
      f"{'moved/distr.':>12} {'bytes/distr.':>12}")
for r in rows:
    print(f"{r['ranks']:>5} {r['curve']:8} {r['mode']:13} {float(r['s_per_step']):8.4f} {r['distributions']:>6} "
          f"{float(r['ghosts_per_owned']):12.4f} {float(r['ghosts_per_owned_max_rank']):10.4f} "
          f"{float(r['moved_per_distribution']):12.0f} {float(r['bytes_per_distribution']):12.4g}"
          + ("  (oversubscribed)" if int(r["ranks"]) > cores else ""))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("compare_curves.sh: no matplotlib for /usr/bin/python3, no PNG")
    sys.exit(0)
ranks = list(dict.fromkeys(r["ranks"] for r in rows))
curves = ["hilbert", "morton"]
pick = lambda rk, c, mode, key: float(next(r[key] for r in rows if r["ranks"] == rk and r["curve"] == c and r["mode"] == mode))
panels = [("ghosts per owned particle (mean over ranks)", "as_needed", "ghosts_per_owned"),
          ("ghosts per owned particle (the worst rank)", "as_needed", "ghosts_per_owned_max_rank"),
          ("s per step (distribution as needed)", "as_needed", "s_per_step"),
          ("s per step (distribution every step)", "every_step", "s_per_step")]
fig, axes = plt.subplots(1, len(panels), figsize=(16, 4))
for ax, (title, mode, key) in zip(axes, panels):
    for i, c in enumerate(curves):
        ax.bar([j + 0.4 * i for j in range(len(ranks))], [pick(rk, c, mode, key) for rk in ranks], 0.4, label=c)
    ax.set_xticks([j + 0.2 for j in range(len(ranks))], [f"{rk} ranks" for rk in ranks])
    ax.set_title(title, fontsize=10)
axes[0].legend()
fig.suptitle(f"bench_sedov, Sedov 3D: Hilbert against Morton keys ({out}; 1 thread per rank, {cores} cores)")
fig.tight_layout()
fig.savefig(out + ".png", dpi=110)
print(f"wrote {out}.csv and {out}.png")
EOF
