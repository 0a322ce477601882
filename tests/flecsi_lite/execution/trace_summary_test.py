#!/usr/bin/env python3
# scripts/trace_summary.py on a small generated trace with known answers: overlapped fraction of
# copy time, idle time per rank and the critical path (through a copy, not the shorter task); --check
# accepts it and rejects a slice that partly overlaps another on its track, and an unnamed track.
import json
import subprocess
import sys
import tempfile


def event(pid, tid, name, cat, begin, end, sequence, dependencies):
    return {"name": name, "cat": cat, "ph": "X", "pid": pid, "tid": tid, "ts": begin * 1e6,
            "dur": (end - begin) * 1e6, "args": {"sequence": sequence, "dependencies": dependencies}}


def names(pid):
    return [{"name": "process_name", "ph": "M", "pid": pid, "tid": 0, "args": {"name": f"rank {pid}"}},
            {"name": "thread_name", "ph": "M", "pid": pid, "tid": 0, "args": {"name": "compute"}},
            {"name": "thread_name", "ph": "M", "pid": pid, "tid": 1, "args": {"name": "communication"}}]


events = names(0) + names(1) + [
    event(0, 0, "A", "task", 0, 10, 0, []),
    event(0, 1, "ghost copy x", "ghost_copy", 10, 16, 1, [0]),
    event(0, 0, "B", "task", 10, 14, 2, []),
    event(0, 0, "D", "task", 16, 20, 3, [1]),
    event(1, 0, "A", "task", 0, 8, 0, []),
    event(1, 1, "ghost copy x", "ghost_copy", 8, 16, 1, [0]),
    event(1, 0, "D", "task", 16, 18, 3, [1]),
]
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(events, f)
script = sys.argv[1]
s = json.loads(subprocess.run([sys.executable, script, f.name, "--json"], check=True, capture_output=True,
                              text=True).stdout)
text = subprocess.run([sys.executable, script, f.name], check=True, capture_output=True, text=True).stdout
print(text)


def check_status(trace_events):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as g:
        json.dump({"traceEvents": trace_events}, g)
    return subprocess.run([sys.executable, script, g.name, "--check"], capture_output=True, text=True)


valid = check_status(events)
misnested = check_status(events + [event(0, 0, "E", "task", 18, 25, 4, [])])  # D is [16, 20]
nested = check_status(events + [event(0, 0, "inner", "task", 17, 19, 5, [])])
unnamed = check_status(events + [event(1, 2, "F", "ghost_copy", 1, 2, 6, [])])


def close(a, b):
    return abs(a - b) < 1e-9


failures = []
def check(condition, what):
    if not condition:
        failures.append(what)


r0, r1 = s["ranks"]["0"], s["ranks"]["1"]
check(close(s["span"], 20), "span 20")
check(close(r0["copy_time"], 6) and close(r0["copy_overlapped"], 4), "rank 0: 4 of 6 s of copy overlapped")
check(close(r0["copy_overlapped_fraction"], 4 / 6), "rank 0 fraction 2/3")
check(close(r1["copy_time"], 8) and close(r1["copy_overlapped"], 0), "rank 1: nothing overlapped")
check(close(s["copy_overlapped_fraction"], 4 / 14), "overall fraction 4/14")
phase = r0["copies_by_reader"].get("D", {})
check(list(r0["copies_by_reader"]) == ["D"] and close(phase.get("copy_time", 0), 6)
      and close(phase.get("copy_overlapped", 0), 4), f"rank 0: the copy's phase is its reader D: {r0['copies_by_reader']}")
check(close(r0["idle_time"], 2) and close(r1["idle_time"], 10), "idle 2 s and 10 s")
c = s["critical_path"]
check(c["rank"] == 0 and c["launches"] == ["A", "ghost copy x", "D"], f"critical path A, copy, D: {c['launches']}")
check(close(c["span"], 20) and close(c["task_time"], 14) and close(c["communication_time"], 6),
      "critical path: 20 s, 14 s of tasks, 6 s of communication")
check("overlapped" in text and "critical path (rank 0)" in text, "the text summary")
check(valid.returncode == 0, f"--check accepts the trace: {valid.stderr}")
check(misnested.returncode == 1 and "'E' [18000000.0, 25000000.0] partly overlaps 'D'" in misnested.stderr,
      f"--check names the partly overlapping slice: {misnested.stderr}")
check(nested.returncode == 0, f"--check accepts a perfectly nested slice: {nested.stderr}")
check(unnamed.returncode == 1 and "track 2 of process 1 has no thread_name" in unnamed.stderr,
      f"--check names the unnamed track: {unnamed.stderr}")
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
