"""Writes the validation report: every problem of validation_problems.json at one size (ci or
paper), its measured figures (the records of record_result.py) against their bounds and references
with a verdict, and its plots (the apps' plot scripts on the runs' files, or PNGs the tests made),
as OUTPUT/report.md and OUTPUT/figures/*.png.

    validation_report.py --size ci|paper --records DIR --inputs DIR --output DIR
                         [--exact PROGRAM] [--require-records] [--problems FILE]

--inputs: where the plots' input files lie (the build folder at ci, the run folder at paper).
--require-records: exit 1 when a run of the size has no record (a problem marked optional whose
app is absent is "not available", not missing).
"""
import argparse
import datetime
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
PROGRAM = "validation_report"
COMPARISONS = {"max": "<= %s", "abs_max": "abs <= %s", "min": ">= %s", "range": "in [%s, %s]", "near": "%s +- %s"}


def cell(text):
    """Text for a Markdown table cell (a | would end the cell)."""
    return str(text).replace("|", "\\|")


def number(value):
    return "-" if value is None else "%.4g" % value


def bound_text(figure):
    bound = figure["bound"]
    if bound is None:
        return "(reported)"
    values = bound if isinstance(bound, list) else [bound]
    return COMPARISONS[figure["compare"]] % tuple(number(v) for v in values)


def verdict(passed):
    return {True: "PASS", False: "**FAIL**", None: "reported"}[passed]


def available(problem):
    return os.path.isdir(os.path.join(ROOT, "apps", problem["app"]))


def load_records(folder, size):
    """{(problem, run): record} of the records of this size in the folder."""
    records = {}
    if os.path.isdir(folder):
        for name in sorted(os.listdir(folder)):
            if name.endswith(".json"):
                with open(os.path.join(folder, name)) as file:
                    record = json.load(file)
                if record.get("size") == size:
                    records[(record["problem"], record["run"])] = record
    return records


def make_plot(plot, size, arguments, figures):
    """The plot's PNG in `figures` (made or copied); returns (file name, None) or (None, why not)."""
    where = plot.get(size)
    if where is None:
        return None, None
    target = os.path.join(figures, plot["png"])
    if "copy" in where:
        source = os.path.join(arguments.inputs, where["copy"])
        if not os.path.isfile(source):
            return None, "%s was not made" % where["copy"]
        with open(source, "rb") as src, open(target, "wb") as dst:
            dst.write(src.read())
        return plot["png"], None
    source = os.path.join(arguments.inputs, where["input"])
    if not os.path.isfile(source):
        return None, "%s was not written" % where["input"]
    command = [sys.executable, os.path.join(ROOT, plot["script"]), source, "--output", target]
    if plot.get("exact"):
        command += ["--exact", arguments.exact]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    if done.returncode != 0 or not os.path.isfile(target):
        return None, "%s failed: %s" % (plot["script"], done.stdout.strip().splitlines()[-1:] or "")
    return plot["png"], None


def problem_rows(problem, size, records):
    """(run, description, record or None) for each run of the problem at this size."""
    return [(run, spec["sizes"][size], records.get((problem["id"], run)))
            for run, spec in problem["runs"].items() if size in spec["sizes"]]


def summary_rows(problems, size, records):
    lines = ["| Problem | Run | Figure | Measured | Bound | Reference | Verdict |", "|---|---|---|---|---|---|---|"]
    for problem in problems:
        rows = problem_rows(problem, size, records)
        if not available(problem):
            lines.append("| %s | | | | | %s | not available (no apps/%s) |" % (problem["title"],
                                                                              cell(problem["reference"]), problem["app"]))
            continue
        if not rows:
            lines.append("| %s | | | | | %s | not run at this size |" % (problem["title"], cell(problem["reference"])))
        for run, _, record in rows:
            if record is None:
                lines.append("| %s | %s | | | | | **NO RECORD** |" % (problem["title"], run))
                continue
            if record["exit_status"] != 0:
                lines.append("| %s | %s | exit status | %d | 0 | | **FAIL** |" % (problem["title"], run,
                                                                                  record["exit_status"]))
            for figure in record["figures"]:
                lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
                    problem["title"], run, cell(figure["name"]), number(figure["measured"]), bound_text(figure),
                    cell(figure["reference"]), verdict(figure["pass"])))
    return lines


def problem_section(problem, size, records, arguments, figures):
    lines = ["", "## %s" % problem["title"], "",
             "Reference: %s. Source: %s. Details: [%s](%s)." % (problem["reference"], problem["source"], problem["docs"],
                                                                os.path.relpath(os.path.join(ROOT, problem["docs"]),
                                                                                arguments.link_root))]
    if not available(problem):
        lines += ["", "Not available: this tree has no apps/%s." % problem["app"]]
        return lines
    rows = problem_rows(problem, size, records)
    if not rows:
        lines += ["", "No run at this size."]
    else:
        lines += ["", "| Run | Size | Wall time | Exit status | Verdict |", "|---|---|---|---|---|"]
        for run, description, record in rows:
            if record is None:
                lines.append("| %s | %s | | | **NO RECORD** |" % (run, description))
            else:
                lines.append("| %s | %s | %.0f s | %d | %s |" % (run, description, record["wall_seconds"],
                                                                 record["exit_status"], verdict(record["pass"])))
    for plot in problem.get("plots", []):
        made, why_not = make_plot(plot, size, arguments, figures)
        if made:
            lines += ["", "![%s](figures/%s)" % (made, made)]
        elif why_not:
            lines += ["", "Plot %s not made: %s." % (plot["png"], why_not)]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", required=True, choices=["ci", "paper"])
    parser.add_argument("--records", required=True)
    parser.add_argument("--inputs", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--exact", default=os.path.join(ROOT, "build", "apps", "exact", "exact_solution"))
    parser.add_argument("--problems", default=os.path.join(HERE, "validation_problems.json"))
    parser.add_argument("--require-records", action="store_true")
    parser.add_argument("--link-root", help="the folder the report's links to docs/ are relative to (default: OUTPUT)")
    arguments = parser.parse_args()
    arguments.link_root = arguments.link_root or arguments.output
    with open(arguments.problems) as file:
        problems = json.load(file)["problems"]
    records = load_records(arguments.records, arguments.size)
    figures = os.path.join(arguments.output, "figures")
    os.makedirs(figures, exist_ok=True)

    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True).stdout.strip() or "unknown"
    lines = ["# Validation report (size: %s)" % arguments.size, "",
             "Written by `scripts/validation_report.sh %s` (tests/validation/validation_report.py) on %s, commit %s. "
             "Each figure is what the run printed, against the bound its check applies; \"reported\" figures have no "
             "bound. Known unmet bounds fail here as they do in the runs: they are not tuned away." %
             (arguments.size, datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"), commit),
             "", "## Summary", ""]
    lines += summary_rows(problems, arguments.size, records)
    for problem in problems:
        lines += problem_section(problem, arguments.size, records, arguments, figures)
    with open(os.path.join(arguments.output, "report.md"), "w") as file:
        file.write("\n".join(lines) + "\n")

    missing = [(p["id"], run) for p in problems if available(p) for run, _, record in
               problem_rows(p, arguments.size, records) if record is None]
    failed = [key for key, record in records.items() if not record["pass"]]
    print("%s: %s/report.md: %d problems, %d records, %d failing, %d missing%s" %
          (PROGRAM, arguments.output, len(problems), len(records), len(failed), len(missing),
           "".join("\n  no record: %s / %s" % key for key in missing)))
    sys.exit(1 if arguments.require_records and missing else 0)


if __name__ == "__main__":
    main()
