#!/usr/bin/env python3
"""The layer order of the house and its internals rule, checked on every #include "...".

1. Layers. Each folder below includes only itself and the folders before it in its list:
     flecsi_lite/   util < runtime < control < data < execution < topology < io < app
     specialization/  numerics < physics < analytic < sph < fluid
     specialization/sph/   model < step < files < run
   The framework includes nothing of specialization/, apps/, tutorial/ or tests/; the
   specialization nothing of apps/, tutorial/ or tests/; apps/ nothing of tutorial/ or tests/.
   An umbrella header (flecsi_lite/data.hh) belongs to its folder's layer.
2. Internals. A header in a detail/ folder is included only from the folder that holds that
   detail/ (at any depth below it) and from tests/: io/detail/ is the I/O layer's own,
   topology/ntree/search/detail/ the neighbour search's.
3. Public face. Every framework header outside detail/ is reached from an umbrella
   (flecsi_lite/<layer>.hh, flecsi_lite/topology/<topology>.hh): a header is either public, and
   then an umbrella brings it, or internal, and then it lives in a detail/ folder. Apps and the
   tutorial include the specialization through its umbrellas only (specialization/sph.hh,
   physics.hh, analytic.hh, fluid.hh): the rooms under them are its inside.

    python3 check_layers.py ROOT      # exit 0: no violation; 1: each violation listed with its rule
    python3 check_layers.py --self-test   # breaks each rule in a scratch tree: each must be caught
"""
import os
import re
import sys
import tempfile

FRAMEWORK_LAYERS = ["util", "runtime", "control", "data", "execution", "topology", "io", "app"]
SPECIALIZATION_LAYERS = ["numerics", "physics", "analytic", "sph", "fluid"]
SPH_ROOMS = ["model", "step", "files", "run"]
# Top-level folders: each may include only those at or before it (tests, benchmarks and the
# tutorial may include anything below them).
TREES = ["flecsi_lite", "specialization", "apps", "tutorial", "tests", "benchmarks"]
SOURCE_FOLDERS = ["flecsi_lite", "specialization", "apps", "tutorial", "benchmarks", "tests"]
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def layer_rank(path, prefix, layers):
    """The rank in `layers` of the folder of `path` right below `prefix` (an umbrella file
    prefix/<layer>.hh counts as <layer>); None when the path is not under prefix."""
    if not path.startswith(prefix + "/"):
        return None
    head = path[len(prefix) + 1:].split("/")[0]
    head = head[:-3] if head.endswith(".hh") else head
    return layers.index(head) if head in layers else None


def violations(source, target):
    """The rules that `source` including `target` (paths relative to the root) breaks."""
    found = []
    source_tree, target_tree = source.split("/")[0], target.split("/")[0]
    if source_tree in TREES and target_tree in TREES and TREES.index(target_tree) > TREES.index(source_tree):
        found.append(f"{source_tree}/ must not include {target_tree}/ (a higher layer)")
    for prefix, layers in (("flecsi_lite", FRAMEWORK_LAYERS), ("specialization", SPECIALIZATION_LAYERS),
                           ("specialization/sph", SPH_ROOMS)):
        a, b = layer_rank(source, prefix, layers), layer_rank(target, prefix, layers)
        if a is not None and b is not None and b > a:
            found.append(f"{prefix}/{layers[a]} must not include {prefix}/{layers[b]} "
                         f"(order: {' < '.join(layers)})")
    if source_tree in ("apps", "tutorial") and re.match(r"specialization/.+/", target):
        umbrella = "specialization/" + target.split("/")[1] + ".hh"
        found.append(f"{source_tree}/ includes the specialization through its umbrellas: include {umbrella}")
    if "/detail/" in target and source_tree != "tests":
        owner = target[:target.rindex("/detail/")]
        if not source.startswith(owner + "/"):
            found.append(f"{target} is internal to {owner}/ (detail/): include a header of {owner}/ instead")
    return found


def unreached_headers(root):
    """Framework headers outside detail/ that no umbrella reaches, through any chain of includes."""
    umbrellas = [os.path.join("flecsi_lite", name) for name in os.listdir(os.path.join(root, "flecsi_lite"))]
    if os.path.isdir(os.path.join(root, "flecsi_lite/topology")):
        umbrellas += [os.path.join("flecsi_lite/topology", name)
                      for name in os.listdir(os.path.join(root, "flecsi_lite/topology"))]
    reached, pending = set(), [name for name in umbrellas if name.endswith(".hh")]
    while pending:
        header = pending.pop()
        path = os.path.join(root, header)
        if header in reached or not os.path.isfile(path):
            continue
        reached.add(header)
        with open(path, errors="replace") as stream:
            pending += [match.group(1) for match in map(INCLUDE.match, stream) if match]
    headers = set()
    for directory, _, names in os.walk(os.path.join(root, "flecsi_lite")):
        headers |= {os.path.relpath(os.path.join(directory, name), root) for name in names if name.endswith(".hh")}
    return sorted(header for header in headers - reached if "/detail/" not in header)


def self_test():
    """A scratch tree that breaks each rule once: every break must be reported, and nothing else."""
    files = {
        "flecsi_lite/data.hh": '#include "flecsi_lite/data/field.hh"\n',
        "flecsi_lite/data/field.hh": '#include "flecsi_lite/io/h5part_writer.hh"\n',  # data includes io
        "flecsi_lite/io.hh": '#include "flecsi_lite/io/h5part_writer.hh"\n',
        "flecsi_lite/io/h5part_writer.hh": '#include "flecsi_lite/io/detail/handle.hh"\n',  # allowed
        "flecsi_lite/io/detail/handle.hh": "",
        "flecsi_lite/runtime/orphan.hh": "",  # in no umbrella, not in detail/
        "flecsi_lite/runtime.hh": '#include "specialization/sph/model/fields.hh"\n',  # framework -> specialization
        "specialization/sph/model/fields.hh": '#include "specialization/sph/run/app.hh"\n',  # model -> run
        "specialization/sph/run/app.hh": '#include "flecsi_lite/io/detail/handle.hh"\n',  # io's internal
        "specialization/physics/eos.hh": '#include "specialization/fluid/tait.hh"\n',  # physics -> fluid
        "apps/sod/sod.cc": '#include "tests/support/collective_checks.hh"\n',  # apps -> tests
        "apps/sod/sod_problem.hh": '#include "specialization/sph/run/app.hh"\n',  # past the umbrella
        "tests/io/handle.cc": '#include "flecsi_lite/io/detail/handle.hh"\n',  # tests may
    }
    expected = ["flecsi_lite/data/field.hh:1", "flecsi_lite/runtime/orphan.hh:", "flecsi_lite/runtime.hh:1",
                "specialization/sph/model/fields.hh:1", "specialization/sph/run/app.hh:1",
                "specialization/physics/eos.hh:1", "apps/sod/sod.cc:1", "apps/sod/sod_problem.hh:1"]
    with tempfile.TemporaryDirectory() as root:
        for name, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(name)), exist_ok=True)
            with open(os.path.join(root, name), "w") as stream:
                stream.write(text)
        problems = find_problems(root)
    reported = [line.strip() for line in problems]
    missed = [where for where in expected if not any(line.startswith(where) for line in reported)]
    extra = [line for line in reported if not any(line.startswith(where) for where in expected)]
    for line in reported:
        print("  caught:", line)
    if missed or extra or len(reported) != len(expected):
        print(f"check_layers --self-test: missed {missed}, unexpected {extra}")
        return 1
    print(f"check_layers --self-test: each of the {len(expected)} broken rules was caught, nothing else")
    return 0


def find_problems(root):
    """Every violation under root, one line each."""
    problems = []
    for folder in SOURCE_FOLDERS:
        for directory, _, names in os.walk(os.path.join(root, folder)):
            for name in sorted(names):
                if not name.endswith((".hh", ".cc")):
                    continue
                path = os.path.join(directory, name)
                source = os.path.relpath(path, root)
                with open(path, errors="replace") as stream:
                    for number, line in enumerate(stream, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        for problem in violations(source, match.group(1)):
                            problems.append(f"  {source}:{number}: #include \"{match.group(1)}\": {problem}")
    for header in unreached_headers(root):
        problems.append(f"  {header}: no umbrella includes it and it is not in a detail/ folder "
                        "(public: include it from its layer's umbrella; internal: move it into detail/)")
    return problems


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__.split("\n\n")[-1].strip(), file=sys.stderr)
        return 2
    root = sys.argv[1]
    checked = sum(name.endswith((".hh", ".cc")) for folder in SOURCE_FOLDERS
                  for _, _, names in os.walk(os.path.join(root, folder)) for name in names)
    if checked == 0:
        print(f"check_layers: no sources under {root}", file=sys.stderr)
        return 2
    problems = find_problems(root)
    if problems:
        print(f"check_layers: {len(problems)} problems with the layer order, the internals rule or the public face:")
        print("\n".join(problems))
        return 1
    print(f"check_layers: the includes of {checked} files keep the layer order and the internals rule; every public framework header is in an umbrella")
    return 0


if __name__ == "__main__":
    sys.exit(main())
