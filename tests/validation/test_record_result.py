"""record_result.py on commands whose output is known: the figures and bounds it reads (from an
option of the command, from the printed text, a literal), the verdicts (within, beyond, missing
figure), and the exit status it passes through. Exit 1 on the first difference."""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PROBLEMS = {"problems": [{"id": "p", "reference": "exact", "source": "a paper", "runs": {"r": {"sizes": {"ci": "small"}, "figures": [
    {"name": "error", "measured": "error {num}", "bound": {"option": "--check", "index": 1}},
    {"name": "radius", "measured": "radius {num}", "bound": {"printed": "radius [^(]*\\(bound {num}\\)"},
     "compare": "abs_max"},
    {"name": "ratio", "measured": "ratio {num}", "bound": [1, 0.1], "compare": "near"},
    {"name": "largest gauge", "measured": "gauge {num}", "aggregate": "max", "bound": 0.5},
    {"name": "reported", "measured": "note {num}", "bound": None}]}}}]}


def record(folder, text, status, check="0.1,0.002"):
    """The record of a command that prints `text` and exits with `status`, and its exit status."""
    script = "import sys; print(%r); sys.exit(%d)" % (text, status)
    done = subprocess.run([sys.executable, os.path.join(HERE, "record_result.py"), "--records", folder, "--size", "ci",
                           "--problem", "p", "--run", "r", "--problems", os.path.join(folder, "problems.json"), "--",
                           sys.executable, "-c", script, "--check", check], stdout=subprocess.PIPE, text=True)
    with open(os.path.join(folder, "p.r.json")) as file:
        return json.load(file), done.returncode, done.stdout


def expect(what, got, wanted):
    if got != wanted:
        sys.exit("test_record_result: %s: %r, expected %r" % (what, got, wanted))


def main():
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "problems.json"), "w") as file:
            json.dump(PROBLEMS, file)
        text = "error 1.5e-3\nradius -0.04 (bound 0.05)\nratio 1.08\ngauge 0.2\ngauge 0.4\nnote 7"
        r, status, output = record(folder, text, 0)
        expect("output passed through", output.startswith(text), True)
        expect("exit status", status, 0)
        expect("measured", [f["measured"] for f in r["figures"]], [1.5e-3, -0.04, 1.08, 0.4, 7.0])
        expect("bounds", [f["bound"] for f in r["figures"]], [0.002, 0.05, [1, 0.1], 0.5, None])
        expect("verdicts", [f["pass"] for f in r["figures"]], [True, True, True, True, None])
        expect("run verdict", r["pass"], True)

        r, status, _ = record(folder, text.replace("error 1.5e-3", "error 2.5e-3"), 0)
        expect("beyond an option's bound", (r["figures"][0]["pass"], r["pass"]), (False, False))
        r, status, _ = record(folder, text.replace("ratio 1.08\n", ""), 0)
        expect("missing figure", (r["figures"][2]["measured"], r["figures"][2]["pass"], r["pass"]), (None, False, False))
        r, status, _ = record(folder, text, 3)
        expect("failing command", (status, r["exit_status"], r["pass"]), (3, 3, False))
    print("test_record_result: passed")


if __name__ == "__main__":
    main()
