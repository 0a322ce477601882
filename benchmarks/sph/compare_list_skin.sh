#!/bin/bash
# Interleaved runs of bench_sedov: a reference binary (OLD, e.g. one built before the lists were
# kept over steps) against this build at several list_skin values, ROUNDS rounds of 1 rank x 1
# thread and 2 ranks x 1 thread; prints the medians per step. Arguments go to bench_sedov.
#   OLD=/path/to/old/bench_sedov SKINS="0 0.05 0.1" benchmarks/sph/compare_list_skin.sh --per-side 50 --steps 5
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
source "$here/scripts/mpirun_flags.sh"
NEW=${NEW:-${FLECSPH_BUILD_DIR:-$here/build}/benchmarks/sph/bench_sedov}
OLD=${OLD:-$NEW}
SKINS=${SKINS:-"0 0.05 0.1"}
ROUNDS=${ROUNDS:-3}
OUT=$(mktemp -d)
export OMP_NUM_THREADS=1 OMP_PROC_BIND=false
uptime
for round in $(seq "$ROUNDS"); do
  for cfg in old $SKINS; do
    if [ "$cfg" = old ]; then binary=$OLD; extra=(); else binary=$NEW; extra=(--set "list_skin=$cfg"); fi
    "$binary" "$@" "${extra[@]}" > "$OUT/r${round}_${cfg}_1x1.txt" 2>&1
    mpirun -np 2 "${FLECSPH_MPIRUN_FLAGS[@]}" "$binary" "$@" "${extra[@]}" > "$OUT/r${round}_${cfg}_2x1.txt" 2>&1
  done
done
uptime
python3 - "$OUT" old $SKINS <<'PY'
import glob, re, statistics, sys
out, configs = sys.argv[1], sys.argv[2:]
def value(text, pattern):
    m = re.search(pattern, text)
    return float(m.group(1)) if m else 0.0
def timer(text, name):
    return value(text, r"\n\s+" + re.escape(name) + r"\s+\d+ calls\s+([\d.]+) s")
for layout in ["1x1", "2x1"]:
    base = None
    for cfg in configs:
        rows = []
        for f in glob.glob(f"{out}/r*_{cfg}_{layout}.txt"):
            t = open(f).read()
            rows.append(dict(
                wall=value(t, r"wall time per step ([\d.]+)"), cpu=value(t, r"CPU time per step[^)]*\) ([\d.]+)"),
                search=sum(timer(t, n) for n in ["sph::search_neighbours", "ntree::refit", "sph::measure_neighbour_slack",
                                                 "sph::measure_distribution_slack"]),
                density=timer(t, "sph::compute_density"), forces=timer(t, "sph::compute_forces"),
                lives=value(t, r"a list lives ([\d.]+) steps") or 1.0, bytes=value(t, r"= (\d+); besides")))
        med = {k: statistics.median(r[k] for r in rows) for k in rows[0]}
        base = base or med
        label = "old" if cfg == "old" else f"skin {cfg}"
        print(f"{layout} {label:10s} wall {med['wall']:.4f} s ({base['wall'] / med['wall']:.3f}x)  cpu {med['cpu']:.4f} s  "
              f"search+refit {med['search']:.4f}  density {med['density']:.4f}  forces {med['forces']:.4f}  "
              f"list lives {med['lives']:.2f} steps  {med['bytes']:.0f} bytes/particle")
PY
