#!/usr/bin/env python3
# Summary of a flecsi_lite executor trace (Chrome trace JSON written with --trace FILE): per rank,
# the overlapped fraction of communication time (time a copy is in flight while a task runs on
# the same rank, over the time any copy is in flight), the idle time (no task running within the
# run's span), and the critical path (walked back from the last launch to finish: at each launch,
# the dependency or previous task on the compute track that finished last).
#
#   python3 scripts/trace_summary.py trace.json [--json]
import argparse
import json
import sys


def union(intervals):
    """Sorted disjoint intervals covering the given ones."""
    merged = []
    for begin, end in sorted(intervals):
        if merged and begin <= merged[-1][1]:
            merged[-1][1] = max(merged[-1][1], end)
        else:
            merged.append([begin, end])
    return merged


def length(intervals):
    return sum(end - begin for begin, end in intervals)


def intersection(a, b):
    """Length of the intersection of two sorted disjoint interval lists."""
    total, i, j = 0.0, 0, 0
    while i < len(a) and j < len(b):
        begin, end = max(a[i][0], b[j][0]), min(a[i][1], b[j][1])
        if end > begin:
            total += end - begin
        if a[i][1] < b[j][1]:
            i += 1
        else:
            j += 1
    return total


def load(path):
    with open(path) as f:
        data = json.load(f)
    events = data["traceEvents"] if isinstance(data, dict) else data
    launches = {}
    for e in events:
        if e.get("ph") != "X":
            continue
        begin = e["ts"] * 1e-6
        launch = {"name": e["name"], "kind": e.get("cat", "task"), "tid": e.get("tid", 0), "begin": begin,
                  "end": begin + e.get("dur", 0) * 1e-6, "sequence": e.get("args", {}).get("sequence"),
                  "dependencies": e.get("args", {}).get("dependencies", [])}
        launches.setdefault(e["pid"], []).append(launch)
    return launches


def is_task(launch):
    """Tasks compute; ghost copies and collectives ("ghost_copy", "reduction") communicate."""
    return launch["kind"] == "task" or (launch["kind"] == "failed" and launch["tid"] == 0)


def critical_path(launches):
    """The chain that ends with the last launch to finish, over all ranks (within one rank)."""
    last_rank, last = None, None
    for rank, events in launches.items():
        for e in events:
            if last is None or e["end"] > last["end"]:
                last_rank, last = rank, e
    if last is None:
        return [], None
    events = launches[last_rank]
    by_sequence = {e["sequence"]: e for e in events if e["sequence"] is not None}
    tasks = sorted((e for e in events if is_task(e)), key=lambda e: e["begin"])
    path = [last]
    current = last
    while True:
        candidates = [by_sequence[s] for s in current["dependencies"] if s in by_sequence]
        if is_task(current):
            earlier = [t for t in tasks if t["end"] <= current["begin"] and t is not current]
            if earlier:
                candidates.append(max(earlier, key=lambda t: t["end"]))
        candidates = [c for c in candidates if c["end"] <= current["end"] and c is not current]
        if not candidates:
            break
        current = max(candidates, key=lambda c: c["end"])
        path.append(current)
    path.reverse()
    return path, last_rank


def summarise(launches):
    start = min(e["begin"] for events in launches.values() for e in events)
    stop = max(e["end"] for events in launches.values() for e in events)
    ranks = {}
    all_copy = all_overlap = 0.0
    for rank in sorted(launches):
        events = launches[rank]
        tasks = union([(e["begin"], e["end"]) for e in events if is_task(e)])
        copies = union([(e["begin"], e["end"]) for e in events if e["kind"] == "ghost_copy"])
        communication = union([(e["begin"], e["end"]) for e in events if not is_task(e)])
        copy_time, overlapped = length(copies), intersection(copies, tasks)
        all_copy += copy_time
        all_overlap += overlapped
        ranks[rank] = {
            "copy_time": copy_time, "copy_overlapped": overlapped,
            "copy_overlapped_fraction": overlapped / copy_time if copy_time > 0 else 0.0,
            "communication_time": length(communication),
            "communication_overlapped": intersection(communication, tasks),
            "compute_time": length(tasks), "idle_time": (stop - start) - length(tasks),
        }
    path, path_rank = critical_path(launches)
    path_tasks = sum(e["end"] - e["begin"] for e in path if is_task(e))
    path_communication = length(union([(e["begin"], e["end"]) for e in path if not is_task(e)]))
    path_span = (path[-1]["end"] - path[0]["begin"]) if path else 0.0
    by_name = {}
    for e in path:
        by_name[e["name"]] = by_name.get(e["name"], 0.0) + e["end"] - e["begin"]
    return {
        "span": stop - start, "ranks": ranks,
        "copy_overlapped_fraction": all_overlap / all_copy if all_copy > 0 else 0.0,
        "critical_path": {"rank": path_rank, "launches": [e["name"] for e in path], "span": path_span,
                          "task_time": path_tasks, "communication_time": path_communication,
                          "waiting_time": max(0.0, path_span - path_tasks - path_communication),
                          "by_name": dict(sorted(by_name.items(), key=lambda kv: -kv[1]))},
    }


def main():
    parser = argparse.ArgumentParser(description="Overlap, idle time and critical path of a flecsi_lite trace.")
    parser.add_argument("trace", help="Chrome trace JSON written with --trace FILE")
    parser.add_argument("--json", action="store_true", help="print the summary as JSON")
    arguments = parser.parse_args()
    try:
        launches = load(arguments.trace)
    except (OSError, ValueError, KeyError) as error:
        print(f"trace_summary: cannot read '{arguments.trace}': {error}", file=sys.stderr)
        return 2
    if not launches:
        print(f"trace_summary: '{arguments.trace}' holds no events", file=sys.stderr)
        return 2
    s = summarise(launches)
    if arguments.json:
        json.dump(s, sys.stdout, indent=1)
        print()
        return 0
    print(f"run span {s['span']:.6f} s; ghost-copy time overlapped with tasks: {100 * s['copy_overlapped_fraction']:.1f}%")
    for rank, r in s["ranks"].items():
        print(f"rank {rank}: compute {r['compute_time']:.6f} s, idle {r['idle_time']:.6f} s, "
              f"copies in flight {r['copy_time']:.6f} s of which {100 * r['copy_overlapped_fraction']:.1f}% "
              f"overlapped, all communication {r['communication_time']:.6f} s "
              f"({r['communication_overlapped']:.6f} s overlapped)")
    c = s["critical_path"]
    print(f"critical path (rank {c['rank']}): {len(c['launches'])} launches over {c['span']:.6f} s: "
          f"tasks {c['task_time']:.6f} s, communication {c['communication_time']:.6f} s, "
          f"waiting {c['waiting_time']:.6f} s")
    for name, seconds in list(c["by_name"].items())[:8]:
        print(f"  {seconds:.6f} s  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
