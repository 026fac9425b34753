"""How long the model commands take from a cold interpreter, beside their baselines.

Each row runs a fresh process (interpreter start included) several times and
reports the median wall time of workbench and of a baseline doing the least
the same job needs:

* ``workbench --help`` and ``import workbench`` against ``python -c pass``;
  the import row also records whether pydrake was imported (it must not be);
* ``workbench check`` against loading the same URDF with bare Drake (``Parser``
  into a ``MultibodyPlant``) and against ROS's ``check_urdf`` when installed;
* ``workbench check --no-load`` against parsing the file with lxml;
* ``workbench graph`` against graphviz alone (``dot -Tpdf`` on the same .gv)
  and ROS's ``urdf_to_graphviz`` when installed;
* ``workbench run PKG EXE`` until the node's main is called, before (commit
  :data:`BEFORE_REV`, nodes registered by importing every capability) and after
  (entry points), beside ``python -c pass``; with the modules imported by then.
  Run it from an installed checkout (``pip install -e .``): entry points are
  package metadata.

Usage: ``python benchmarks/startup.py [--quick] [--runs N] [--model PATH]``.
Writes ``benchmarks/results/startup.json``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from machine import describe  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
SEED = 0  # nothing here is random; recorded for uniformity with the other benchmarks


def timed(command: list[str], runs: int, cwd: Path) -> tuple[float, str]:
    """Median wall time in seconds of ``runs`` executions, and the last stdout."""
    times, out = [], ""
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    for _ in range(runs):
        start = time.perf_counter()
        result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, env=env)
        times.append(time.perf_counter() - start)
        if result.returncode not in (0, 1):
            raise SystemExit(f"{' '.join(command)} failed:\n{result.stderr}")
        out = result.stdout
    return statistics.median(times), out


# --- `workbench run`: time and modules until the node's main is called ----------------------

#: The last commit that found nodes through import side effects (PROVIDERS imported on
#: every lookup), measured as "before".
BEFORE_REV = "20ef01f"

#: (package, executable, before's module:function, after's module:function).
RUN_NODES = [
    (
        "turtlesim",
        "turtlesim_node",
        "workbench.turtlesim.node:main",
        "workbench.turtlesim.node:main",
    ),
    (
        "tf2_ros",
        "static_transform_publisher",
        "workbench.tf.nodes:static_transform_publisher",
        "workbench.tf.nodes:static_transform_publisher",
    ),
    (
        "robot_state_publisher",
        "robot_state_publisher",
        "workbench.tf.nodes:robot_state_publisher",
        "workbench.robot_state.nodes:robot_state_publisher",
    ),
]

# Runs `workbench run PKG EXE` in-process as `python -m workbench` would, with a meta-path
# hook that swaps the node's function for a probe as soon as its module has executed; the
# probe prints the wall clock and what is imported, and ends the process. Nothing else of
# the lookup is touched, so before and after are measured the same way.
RUN_PROBE = """
import importlib.machinery, json, os, sys, time
package, executable, target = sys.argv[1:4]
module_name, _, function = target.partition(":")

def probe(*args, **kwargs):
    now = time.time()
    names = list(sys.modules)
    print(json.dumps({"t": now, "modules": len(names),
        "workbench": sum(n == "workbench" or n.startswith("workbench.") for n in names),
        "bus": "workbench.bus.bus" in names, "pydrake": "pydrake" in names}), flush=True)
    os._exit(0)

class SwapMain:
    def find_spec(self, name, path=None, target=None):
        if name != module_name:
            return None
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        run = spec.loader.exec_module
        def exec_module(module):
            run(module)
            setattr(module, function, probe)
        spec.loader.exec_module = exec_module
        return spec

sys.meta_path.insert(0, SwapMain())
from workbench.cli import main
sys.exit(main(["run", package, executable]))
"""

CLOCK_PROBE = "import json, time; print(json.dumps({'t': time.time()}))"


def to_main(command: list[str], runs: int, cwd: Path, pythonpath: str | None) -> dict:
    """Median seconds from spawning ``command`` to its probe, and what the probe saw."""
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    if pythonpath is not None:
        env["PYTHONPATH"] = pythonpath
    delays, seen = [], {}
    for _ in range(runs):
        start = time.time()
        result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, env=env)
        lines = [line for line in result.stdout.splitlines() if line.startswith("{")]
        if not lines:
            raise SystemExit(f"{' '.join(command)} never reached main:\n{result.stderr}")
        seen = json.loads(lines[-1])
        delays.append(seen["t"] - start)
    return {"seconds": statistics.median(delays), **{k: v for k, v in seen.items() if k != "t"}}


def checkout_of(rev: str, into: Path) -> Path | None:
    """``workbench/`` of commit ``rev`` unpacked under ``into`` (None without git or the commit)."""
    archive = subprocess.run(
        ["git", "-C", str(ROOT), "archive", rev, "workbench"], capture_output=True
    )
    if archive.returncode != 0:
        return None
    into.mkdir(parents=True, exist_ok=True)
    subprocess.run(["tar", "-x", "-C", str(into)], input=archive.stdout, check=True)
    return into


def run_rows(runs: int, work: Path) -> tuple[list[dict], float]:
    """Before/after rows for ``workbench run`` and the interpreter's own start time."""
    py = sys.executable
    base = to_main([py, "-c", CLOCK_PROBE], runs, work, None)["seconds"]
    before_tree = checkout_of(BEFORE_REV, work / "before")
    rows = []
    for package, executable, before_target, after_target in RUN_NODES:
        after = to_main(
            [py, "-c", RUN_PROBE, package, executable, after_target], runs, work, str(ROOT)
        )
        before = None
        if before_tree is not None:
            before = to_main(
                [py, "-c", RUN_PROBE, package, executable, before_target],
                runs,
                work,
                str(before_tree),
            )
        rows.append(
            {
                "task": f"workbench run {package} {executable}",
                "before_s": None if before is None else round(before["seconds"], 4),
                "before_modules": None if before is None else before["modules"],
                "before_workbench_modules": None if before is None else before["workbench"],
                "after_s": round(after["seconds"], 4),
                "after_modules": after["modules"],
                "after_workbench_modules": after["workbench"],
                "after_bus_before_main": after["bus"],
                "after_pydrake_before_main": after["pydrake"],
                "baseline": "python -c pass",
                "baseline_s": round(base, 4),
                "after_beyond_start_s": round(after["seconds"] - base, 4),
                "before_beyond_start_s": None
                if before is None
                else round(before["seconds"] - base, 4),
            }
        )
    return rows, base


def print_run_rows(rows: list[dict]) -> None:
    print(
        f"\n`workbench run PKG EXE` until the node's main is called (before = {BEFORE_REV}, "
        "import-side-effect registry; after = entry points); seconds from spawn, "
        "modules in sys.modules at main"
    )
    header = (
        f"| {'node':58} | {'before s':>8} | {'modules':>7} | {'after s':>7} | {'modules':>7} "
        f"| {'python -c pass':>14} | {'after beyond start':>18} |"
    )
    print(header)
    print("|" + "|".join("-" * len(part) for part in header.split("|")[1:-1]) + "|")
    for item in rows:
        before = "-" if item["before_s"] is None else f"{item['before_s']:.3f}"
        before_modules = "-" if item["before_modules"] is None else str(item["before_modules"])
        print(
            f"| {item['task']:58} | {before:>8} | {before_modules:>7} | {item['after_s']:7.3f} "
            f"| {item['after_modules']:7d} | {item['baseline_s']:14.3f} "
            f"| {item['after_beyond_start_s']:18.3f} |"
        )
    worst = max(item["after_beyond_start_s"] for item in rows)
    print(
        f"\n`workbench run` reaches the node's main {worst:.3f} s beyond interpreter start at "
        f"worst (target < 0.3 s): {'met' if worst < 0.3 else 'NOT met'}"
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="2 runs per row instead of 7")
    parser.add_argument("--runs", type=int, default=None, help="runs per row")
    parser.add_argument("--model", default=str(ROOT / "urdf" / "robot_arm.urdf"))
    args = parser.parse_args()
    runs = args.runs or (2 if args.quick else 7)
    model = str(Path(args.model).resolve())
    py = sys.executable
    work = Path(tempfile.mkdtemp(prefix="workbench-bench-"))
    wb = [py, "-m", "workbench"]

    drake_load = (
        "import sys; from pydrake.multibody.parsing import Parser; "
        "from pydrake.multibody.plant import MultibodyPlant; "
        "p = MultibodyPlant(0.0); Parser(p).AddModels(sys.argv[1]); p.Finalize()"
    )
    lxml_parse = "import sys; from lxml import etree; etree.parse(sys.argv[1])"
    import_probe = "import sys, workbench; print('pydrake' in sys.modules)"

    rows = []

    def row(task, command, baseline_name, baseline_command):
        ours, out = timed(command, runs, work)
        base, _ = timed(baseline_command, runs, work) if baseline_command else (None, "")
        rows.append(
            {
                "task": task,
                "workbench_s": round(ours, 4),
                "baseline": baseline_name,
                "baseline_s": None if base is None else round(base, 4),
                "ratio": None if not base else round(ours / base, 2),
            }
        )
        return out

    row("workbench --help", [*wb, "--help"], "python -c pass", [py, "-c", "pass"])
    out = row("import workbench", [py, "-c", import_probe], "python -c pass", [py, "-c", "pass"])
    pydrake_imported = out.strip() == "True"
    row(
        "workbench check (with Drake load)",
        [*wb, "check", model],
        "bare Drake Parser load",
        [py, "-c", drake_load, model],
    )
    row(
        "workbench check --no-load",
        [*wb, "check", "--no-load", model],
        "lxml parse",
        [py, "-c", lxml_parse, model],
    )
    check_urdf = shutil.which("check_urdf")
    if check_urdf:
        row(
            "workbench check (with Drake load)",
            [*wb, "check", model],
            "ROS check_urdf",
            [check_urdf, model],
        )
    dot = shutil.which("dot")
    if dot:
        subprocess.run(
            [*wb, "graph", model, "-o", str(work / "g.gv")], check=True, capture_output=True
        )
        row(
            "workbench graph (gv + pdf)",
            [*wb, "graph", model],
            "dot -Tpdf alone",
            [dot, "-Tpdf", str(work / "g.gv"), "-o", str(work / "g.pdf")],
        )
        urdf_to_graphviz = shutil.which("urdf_to_graphviz")
        if urdf_to_graphviz:
            row(
                "workbench graph (gv + pdf)",
                [*wb, "graph", model],
                "ROS urdf_to_graphviz",
                [urdf_to_graphviz, model],
            )
    run_nodes, interpreter_s = run_rows(runs, work)
    shutil.rmtree(work, ignore_errors=True)

    machine = describe(
        ("drake", "lxml", "pydot"),
        platform=platform.platform(),
        graphviz_dot=dot or "not installed",
        seed=SEED,
        runs_per_row=runs,
        model=os.path.relpath(model, ROOT),
    )
    print(
        f"machine: {machine['cpu']}, {machine['cores']} cores, Python {machine['python']}, "
        f"drake {machine['drake']}, lxml {machine['lxml']}, pydot {machine['pydot']}"
    )
    print(f"model: {machine['model']}; median of {runs} cold runs; seed {SEED}")
    print(f"`import workbench` imports pydrake: {'yes' if pydrake_imported else 'no'}")
    print()
    header = f"| {'task':34} | {'workbench s':>11} | {'baseline':24} | {'baseline s':>10} | {'ratio':>6} |"
    print(header)
    print("|" + "|".join("-" * (len(part)) for part in header.split("|")[1:-1]) + "|")
    for item in rows:
        base = "-" if item["baseline_s"] is None else f"{item['baseline_s']:.3f}"
        ratio = "-" if item["ratio"] is None else f"{item['ratio']:.2f}"
        print(
            f"| {item['task']:34} | {item['workbench_s']:11.3f} | {item['baseline']:24} | "
            f"{base:>10} | {ratio:>6} |"
        )
    help_time = rows[0]["workbench_s"]
    print(
        f"\n`workbench --help` {help_time:.3f} s (target < 0.3 s): "
        f"{'met' if help_time < 0.3 else 'NOT met'}"
    )
    print_run_rows(run_nodes)

    results = ROOT / "benchmarks" / "results"
    results.mkdir(parents=True, exist_ok=True)
    payload = {
        "benchmark": "startup",
        "machine": machine,
        "pydrake_on_import": pydrake_imported,
        "rows": rows,
        "workbench_run": {
            "before_rev": BEFORE_REV,
            "interpreter_start_s": round(interpreter_s, 4),
            "rows": run_nodes,
        },
    }
    (results / "startup.json").write_text(json.dumps(payload, indent=2) + "\n")
    print(f"wrote {results / 'startup.json'}")
    return 0 if not pydrake_imported else 1


if __name__ == "__main__":
    sys.exit(main())
