#!/usr/bin/env python3
# Summary of a flecsi_lite executor trace (Chrome trace JSON written with --trace FILE): per rank,
# the overlapped fraction of communication time (time a copy is in flight while a task runs on
# the same rank, over the time any copy is in flight), also per phase (the copies grouped by the
# first task that reads them: the forces phase is the copies the forces read), the idle time (no task running within the
# run's span), and the critical path (walked back from the last launch to finish: at each launch,
# the dependency or previous task on the compute track that finished last).
# --check validates the file against the rules Perfetto's and chrome://tracing's JSON importers
# apply (strict JSON, X events with ts/dur/pid/tid, slices on one track nested perfectly, named
# processes and tracks) and exits 1 naming the first violations.
#
#   python3 scripts/trace_summary.py trace.json [--json] [--check]
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


def format_problems(path, limit=10):
    """Violations of the Trace Event Format as Perfetto imports it: "The Perfetto UI and trace
    processor do not support overlapping B/E/X events ... events are only allowed to perfectly
    nest" (perfetto.dev/docs/faq), so a slice that partly overlaps another of its track is lost."""
    def reject_constant(name):
        raise ValueError(f"non-JSON number {name}")
    with open(path) as f:
        data = json.load(f, parse_constant=reject_constant)
    events = data.get("traceEvents") if isinstance(data, dict) else data
    if not isinstance(events, list):
        return ["no traceEvents list"]
    problems, tracks, process_names, track_names = [], {}, set(), set()
    for i, e in enumerate(events):
        if not isinstance(e, dict) or not isinstance(e.get("ph"), str):
            problems.append(f"event {i}: not an object with a 'ph' phase")
            continue
        if not isinstance(e.get("pid"), int) or not isinstance(e.get("tid", 0), int):
            problems.append(f"event {i} ({e.get('name')}): pid and tid must be integers")
            continue
        if e["ph"] == "M":
            if e.get("name") == "process_name":
                process_names.add(e["pid"])
            elif e.get("name") == "thread_name":
                track_names.add((e["pid"], e["tid"]))
            continue
        if e["ph"] != "X":
            continue
        ts, dur = e.get("ts"), e.get("dur")
        if not isinstance(e.get("name"), str) or not isinstance(ts, (int, float)) \
                or not isinstance(dur, (int, float)) or dur < 0:
            problems.append(f"event {i} ({e.get('name')}): an X event needs a name, ts and dur >= 0")
            continue
        tracks.setdefault((e["pid"], e["tid"]), []).append((ts, ts + dur, e["name"]))
    for (pid, tid), slices in sorted(tracks.items()):
        if pid not in process_names:
            problems.append(f"process {pid} has no process_name")
        if (pid, tid) not in track_names:
            problems.append(f"track {tid} of process {pid} has no thread_name")
        open_slices = []  # the enclosing slices of the current one, outermost first
        for begin, end, name in sorted(slices, key=lambda s: (s[0], -s[1])):
            while open_slices and open_slices[-1][1] <= begin:
                open_slices.pop()
            if open_slices and end > open_slices[-1][1]:
                problems.append(f"process {pid} track {tid}: '{name}' [{begin}, {end}] partly overlaps "
                                f"'{open_slices[-1][2]}' [{open_slices[-1][0]}, {open_slices[-1][1]}]")
            open_slices.append((begin, end, name))
    return problems[:limit] + ([f"... and {len(problems) - limit} more"] if len(problems) > limit else [])


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
        # The phase of a copy: the first task that reads it (depends on its sequence).
        readers = {}
        for e in sorted((e for e in events if is_task(e)), key=lambda e: e["begin"]):
            for d in e["dependencies"]:
                readers.setdefault(d, e["name"])
        by_reader = {}
        for e in events:
            if e["kind"] == "ghost_copy":
                by_reader.setdefault(readers.get(e["sequence"], "(no reader)"), []).append((e["begin"], e["end"]))
        phases = {}
        for name, intervals in by_reader.items():
            flight = union(intervals)
            phases[name] = {"copy_time": length(flight), "copy_overlapped": intersection(flight, tasks)}
        all_copy += copy_time
        all_overlap += overlapped
        ranks[rank] = {
            "copy_time": copy_time, "copy_overlapped": overlapped,
            "copy_overlapped_fraction": overlapped / copy_time if copy_time > 0 else 0.0,
            "communication_time": length(communication),
            "communication_overlapped": intersection(communication, tasks),
            "compute_time": length(tasks), "idle_time": (stop - start) - length(tasks),
            "copies_by_reader": dict(sorted(phases.items(), key=lambda kv: -kv[1]["copy_time"])),
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
    parser.add_argument("--check", action="store_true",
                        help="validate the format as Perfetto and chrome://tracing import it; exit 1 on a violation")
    arguments = parser.parse_args()
    if arguments.check:
        try:
            problems = format_problems(arguments.trace)
        except (OSError, ValueError) as error:
            print(f"trace_summary: cannot read '{arguments.trace}': {error}", file=sys.stderr)
            return 2
        for problem in problems:
            print(f"trace_summary: {arguments.trace}: {problem}", file=sys.stderr)
        if problems:
            return 1
        print(f"{arguments.trace}: valid Trace Event Format (perfectly nested tracks, named processes and tracks)")
        return 0
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
        for name, p in list(r["copies_by_reader"].items())[:4]:
            fraction = p["copy_overlapped"] / p["copy_time"] if p["copy_time"] > 0 else 0.0
            print(f"  copies read first by {name}: {p['copy_time']:.6f} s in flight, {100 * fraction:.1f}% overlapped")
    c = s["critical_path"]
    print(f"critical path (rank {c['rank']}): {len(c['launches'])} launches over {c['span']:.6f} s: "
          f"tasks {c['task_time']:.6f} s, communication {c['communication_time']:.6f} s, "
          f"waiting {c['waiting_time']:.6f} s")
    for name, seconds in list(c["by_name"].items())[:8]:
        print(f"  {seconds:.6f} s  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
