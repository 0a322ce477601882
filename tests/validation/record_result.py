"""Runs one validation command, passes its output and exit status through unchanged, and records
the figures it printed as one JSON file in a records folder, for validation_report.py.

    record_result.py --records DIR --size ci|paper --problem ID --run NAME [--problems FILE] -- COMMAND...

Which figures a run prints, and where each one's bound comes from, is the run's entry in
validation_problems.json (a figure: a regular expression with one {num} for the measured value; a
bound that is a number, the value of one of COMMAND's options, a number printed beside the figure,
or null for a figure only reported). The record is DIR/<problem>.<run>.json:
{problem, run, size, command, exit_status, wall_seconds, finished, pass, figures: [{name, measured,
bound, compare, pass, reference, source}]}; a run's pass needs exit status 0 and every bounded
figure within its bound (a bounded figure the output lacks fails).
"""
import argparse
import datetime
import json
import math
import os
import re
import shlex
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_PROBLEMS = os.path.join(HERE, "validation_problems.json")
PROGRAM = "record_result"
# A number as the apps and checks print it (fixed, scientific, signed, inf, nan).
NUMBER = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?inf|nan)"


def pattern(text):
    """The figure's regular expression, {num} standing for the captured number."""
    return re.compile(text.replace("{num}", NUMBER))


def find_all(text, output):
    return [float(m) for m in pattern(text).findall(output)]


def option_value(tokens, spec):
    """The number after an option of the command: the token `offset` places after the option
    (1 by default), split at commas, item `index` (0 by default); None when absent."""
    name, offset, index = spec["option"], spec.get("offset", 1), spec.get("index", 0)
    if name not in tokens:
        return None
    position = len(tokens) - 1 - tokens[::-1].index(name) + offset  # the last occurrence wins, as --set
    if position >= len(tokens):
        return None
    try:
        return float(tokens[position].split(",")[index])
    except (IndexError, ValueError):
        return None


def bound_value(spec, tokens, output):
    """One bound: a number, {"option": ...}, {"printed": regex} (its last match) or None."""
    if spec is None or isinstance(spec, (int, float)):
        return spec
    if "option" in spec:
        return option_value(tokens, spec)
    values = find_all(spec["printed"], output)
    return values[-1] if values else None


def split_words(text):
    try:
        return shlex.split(text)
    except ValueError:  # an unbalanced quote: the word as it is
        return [text]


def aggregate(values, how):
    if not values:
        return None
    if how == "max":
        return max(values)
    if how == "first":
        return values[0]
    return values[-1]


def within(measured, bound, compare):
    """Whether the measured value meets its bound: max (<=), abs_max (|m| <=), min (>=),
    range ([low, high]) or near ([centre, width]: |m - centre| <= width)."""
    if measured is None or not math.isfinite(measured):
        return False
    if compare == "max":
        return measured <= bound
    if compare == "abs_max":
        return abs(measured) <= bound
    if compare == "min":
        return measured >= bound
    if compare == "range":
        return bound[0] <= measured <= bound[1]
    if compare == "near":
        return abs(measured - bound[0]) <= bound[1]
    raise ValueError("unknown comparison '%s'" % compare)


def figures_of(problem, run, tokens, output):
    """The run's figures measured in `output`, each with its bound and verdict (None: reported only)."""
    records = []
    for figure in run.get("figures", problem.get("figures", [])):
        measured = aggregate(find_all(figure["measured"], output), figure.get("aggregate", "last"))
        spec = figure.get("bound")
        bound = [bound_value(s, tokens, output) for s in spec] if isinstance(spec, list) else bound_value(spec, tokens,
                                                                                                          output)
        bounded = bound is not None and not (isinstance(bound, list) and None in bound)
        compare = figure.get("compare", "max")
        records.append({"name": figure["name"], "measured": measured, "bound": bound if bounded else None,
                        "compare": compare, "pass": within(measured, bound, compare) if bounded else None,
                        "reference": figure.get("reference", problem.get("reference")),
                        "source": figure.get("source", problem.get("source"))})
    return records


def run_command(command):
    """Runs the command with its output merged and echoed line by line; returns (status, output).
    A SIGTERM (CTest's timeout) is passed on to the command."""
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    signal.signal(signal.SIGTERM, lambda *_: child.terminate())
    lines = []
    for line in child.stdout:
        sys.stdout.write(line)
        sys.stdout.flush()
        lines.append(line)
    return child.wait(), "".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--records", required=True, help="the folder the record is written to")
    parser.add_argument("--size", required=True, choices=["ci", "paper"])
    parser.add_argument("--problem", required=True)
    parser.add_argument("--run", required=True)
    parser.add_argument("--problems", default=DEFAULT_PROBLEMS)
    parser.add_argument("command", nargs=argparse.REMAINDER)
    arguments = parser.parse_args()
    command = arguments.command[1:] if arguments.command[:1] == ["--"] else arguments.command
    if not command:
        parser.error("no command after --")
    with open(arguments.problems) as file:
        problems = {p["id"]: p for p in json.load(file)["problems"]}
    problem = problems.get(arguments.problem)
    if problem is None or arguments.run not in problem.get("runs", {}):
        print("%s: no run '%s' of problem '%s' in %s" % (PROGRAM, arguments.run, arguments.problem,
                                                        arguments.problems), file=sys.stderr)
        sys.exit(2)

    start = time.time()
    status, output = run_command(command)
    # Options are looked up in the words of the command, sh -c strings split as a shell would.
    tokens = [word for part in command for word in split_words(part)]
    figures = figures_of(problem, problem["runs"][arguments.run], tokens, output)
    record = {"problem": arguments.problem, "run": arguments.run, "size": arguments.size, "command": command,
              "exit_status": status, "wall_seconds": round(time.time() - start, 1),
              "finished": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
              "pass": status == 0 and all(f["pass"] is not False for f in figures), "figures": figures}
    os.makedirs(arguments.records, exist_ok=True)
    path = os.path.join(arguments.records, "%s.%s.json" % (arguments.problem, arguments.run))
    with open(path + ".part", "w") as file:
        json.dump(record, file, indent=1)
    os.replace(path + ".part", path)
    print("%s: %s / %s: %s (%s)" % (PROGRAM, arguments.problem, arguments.run, "pass" if record["pass"] else "FAIL",
                                    ", ".join("%s %s" % (f["name"], f["measured"]) for f in figures)))
    sys.exit(status)


if __name__ == "__main__":
    main()
