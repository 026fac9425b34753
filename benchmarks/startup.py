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
  and ROS's ``urdf_to_graphviz`` when installed.

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

    results = ROOT / "benchmarks" / "results"
    results.mkdir(parents=True, exist_ok=True)
    payload = {
        "benchmark": "startup",
        "machine": machine,
        "pydrake_on_import": pydrake_imported,
        "rows": rows,
    }
    (results / "startup.json").write_text(json.dumps(payload, indent=2) + "\n")
    print(f"wrote {results / 'startup.json'}")
    return 0 if not pydrake_imported else 1


if __name__ == "__main__":
    sys.exit(main())
