#!/usr/bin/env python3
# scripts/trace_summary.py on a small generated trace with known answers: overlapped fraction of
# copy time, idle time per rank and the critical path (through a copy, not the shorter task).
import json
import subprocess
import sys
import tempfile


def event(pid, tid, name, cat, begin, end, sequence, dependencies):
    return {"name": name, "cat": cat, "ph": "X", "pid": pid, "tid": tid, "ts": begin * 1e6,
            "dur": (end - begin) * 1e6, "args": {"sequence": sequence, "dependencies": dependencies}}


events = [
    {"name": "process_name", "ph": "M", "pid": 0, "tid": 0, "args": {"name": "rank 0"}},
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
check(close(r0["idle_time"], 2) and close(r1["idle_time"], 10), "idle 2 s and 10 s")
c = s["critical_path"]
check(c["rank"] == 0 and c["launches"] == ["A", "ghost copy x", "D"], f"critical path A, copy, D: {c['launches']}")
check(close(c["span"], 20) and close(c["task_time"], 14) and close(c["communication_time"], 6),
      "critical path: 20 s, 14 s of tasks, 6 s of communication")
check("overlapped" in text and "critical path (rank 0)" in text, "the text summary")
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
