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
import math
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


def load_records(folder, size, records):
    """Adds {(size, problem, run): record} of the records of this size in the folder."""
    if folder and os.path.isdir(folder):
        for name in sorted(os.listdir(folder)):
            if name.endswith(".json"):
                with open(os.path.join(folder, name)) as file:
                    record = json.load(file)
                if record.get("size") == size:
                    records[(size, record["problem"], record["run"])] = record


def make_plot(plot, size, arguments, figures):
    """The plot's PNG in `figures` (made or copied); returns (file name, None) or (None, why not)."""
    where, inputs = plot.get(size), arguments.inputs
    if where == "ci":  # the paper size of this run is the CI size
        where, inputs = plot["ci"], arguments.ci_inputs
    if where is None or inputs is None:
        return None, None
    target = os.path.join(figures, plot["png"])
    if "copy" in where:
        source = os.path.join(inputs, where["copy"])
        if not os.path.isfile(source):
            return None, "%s was not made" % where["copy"]
        with open(source, "rb") as src, open(target, "wb") as dst:
            dst.write(src.read())
        return plot["png"], None
    source = os.path.join(inputs, where["input"])
    if not os.path.isfile(source):
        return None, "%s was not written" % where["input"]
    command = [sys.executable, os.path.join(ROOT, plot["script"]), source, "--output", target]
    if plot.get("exact"):
        command += ["--exact", arguments.exact]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    if done.returncode != 0 or not os.path.isfile(target):
        return None, "%s failed: %s" % (plot["script"], done.stdout.strip().splitlines()[-1:] or "")
    return plot["png"], None


def shrink(path, width):
    """The PNG at most `width` pixels wide, in 256 colours (plots need no more; the committed
    reports stay small)."""
    from PIL import Image
    image = Image.open(path).convert("RGB")
    if image.width > width:
        image = image.resize((width, round(image.height * width / image.width)), Image.LANCZOS)
    image.quantize(colors=256).save(path, optimize=True)


def derived_figures(problem, size, records):
    """The problem's derived figures (reported only): an order of convergence,
    log(e_coarse / e_fine) / log(factor), from one figure of two runs."""
    rows = []
    for derived in problem.get("derived", []):
        coarse, fine = (records.get((size, problem["id"], run)) for run in derived["runs"])
        if coarse is None or fine is None or not all(run in problem["runs"] and size in problem["runs"][run]["sizes"]
                                                     for run in derived["runs"]):
            continue
        values = [next((f["measured"] for f in r["figures"] if f["name"] == derived["figure"]), None)
                  for r in (coarse, fine)]
        order = None
        if None not in values and min(values) > 0:
            order = math.log(values[0] / values[1]) / math.log(derived["factor"])
        rows.append(("/".join(derived["runs"]), {"name": derived["name"], "measured": order, "bound": None,
                                                 "compare": "max", "pass": None,
                                                 "reference": derived.get("reference", problem["reference"])}))
    return rows


def problem_rows(problem, size, records):
    """(run, description, record or None) for each run of the problem at this size; a run whose
    paper size is "ci" is its CI run, with the CI record."""
    rows = []
    for run, spec in problem["runs"].items():
        if size not in spec["sizes"]:
            continue
        if spec["sizes"][size] == "ci":
            rows.append((run, "the CI run: " + spec["sizes"]["ci"], records.get(("ci", problem["id"], run))))
        else:
            rows.append((run, spec["sizes"][size], records.get((size, problem["id"], run))))
    return rows


def figure_row(problem, run, figure):
    return "| %s | %s | %s | %s | %s | %s | %s |" % (problem["title"], run, cell(figure["name"]),
                                                    number(figure["measured"]), bound_text(figure),
                                                    cell(figure["reference"]), verdict(figure["pass"]))


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
                lines.append(figure_row(problem, run, figure))
        for run, figure in derived_figures(problem, size, records):
            lines.append(figure_row(problem, run, figure))
    return lines


def problem_section(problem, size, records, arguments, figures):
    lines = ["", "## %s" % problem["title"], "", "Reference: %s. Source: %s." % (problem["reference"], problem["source"])]
    if not available(problem):
        lines += ["", "Not available: this tree has no apps/%s." % problem["app"]]
        return lines
    lines[-1] += " Details: [%s](%s)." % (problem["docs"], os.path.relpath(os.path.join(ROOT, problem["docs"]),
                                                                          arguments.link_root))
    rows = problem_rows(problem, size, records)
    if not rows:
        lines += ["", "No run at this size."]
    else:
        lines += ["", "| Run | Size | Wall time | Exit status | Verdict |", "|---|---|---|---|---|"]
        for run, description, record in rows:
            if record is None:
                lines.append("| %s | %s | | | **NO RECORD** |" % (run, cell(description)))
            else:
                bounded = any(f["pass"] is not None for f in record["figures"]) or record["exit_status"] != 0
                lines.append("| %s | %s | %.0f s | %d | %s |" % (run, cell(description), record["wall_seconds"],
                                                                 record["exit_status"],
                                                                 verdict(record["pass"] if bounded else None)))
    for plot in problem.get("plots", []):
        made, why_not = make_plot(plot, size, arguments, figures)
        if made:
            shrink(os.path.join(figures, made), arguments.figure_width)
            lines += ["", "![%s](%s/%s)" % (made, arguments.figures_name, made)]
        elif why_not:
            lines += ["", "Plot %s not made: %s." % (plot["png"], why_not)]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", required=True, choices=["ci", "paper"])
    parser.add_argument("--records", required=True)
    parser.add_argument("--inputs", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--ci-records", help="paper: the CI records, for the runs whose paper size is the CI size")
    parser.add_argument("--ci-inputs", help="paper: the build folder, the CI runs' files")
    parser.add_argument("--exact", default=os.path.join(ROOT, "build", "apps", "exact", "exact_solution"))
    parser.add_argument("--problems", default=os.path.join(HERE, "validation_problems.json"))
    parser.add_argument("--require-records", action="store_true")
    parser.add_argument("--figure-width", type=int, default=1000, help="PNGs wider than this are scaled down")
    parser.add_argument("--figures-name", default="figures", help="the folder of the PNGs, beside report.md")
    parser.add_argument("--link-root", help="the folder the report's links to docs/ are relative to (default: OUTPUT)")
    arguments = parser.parse_args()
    arguments.link_root = arguments.link_root or arguments.output
    with open(arguments.problems) as file:
        problems = json.load(file)["problems"]
    records = {}
    load_records(arguments.records, arguments.size, records)
    if arguments.size == "paper":
        load_records(arguments.ci_records, "ci", records)
    figures = os.path.join(arguments.output, arguments.figures_name)
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

    rows = [(p["id"], run, record) for p in problems if available(p) for run, _, record in
            problem_rows(p, arguments.size, records)]
    missing = [(problem, run) for problem, run, record in rows if record is None]
    failed = [(problem, run) for problem, run, record in rows if record is not None and not record["pass"]]
    print("%s: %s/report.md: %d problems, %d runs, %d failing, %d without a record%s%s" %
          (PROGRAM, arguments.output, len(problems), len(rows), len(failed), len(missing),
           "".join("\n  failing: %s / %s" % key for key in failed),
           "".join("\n  no record: %s / %s" % key for key in missing)))
    sys.exit(1 if arguments.require_records and missing else 0)


if __name__ == "__main__":
    main()
