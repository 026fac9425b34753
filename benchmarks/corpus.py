"""Real ROS packages through workbench: every command on every file, beside ROS's own tools.

Point it at a folder of ROS 1 packages (git clones of turtlebot3, universal_robot,
moveit_resources ...) and, optionally, folders of Gazebo models::

    python benchmarks/corpus.py --root ~/catkin_ws/src --models ~/gazebo_models \\
        [--json OUT] [--timeout S] [--only KIND[,KIND]] [--jobs 1|2] [--sample-models N] \\
        [--env NAME=VALUE ...]

Each file runs the workbench command of its kind (see :mod:`corpus_files`):
``launch --dry-run``, ``check`` and ``graph``, ``sim`` (one simulated second,
headless), ``check`` of a Gazebo model, ``setup --srdf --dry-run``, ``map show``,
``bag info`` and ``rviz -d``, each in a child process with a timeout, with
``ROS_PACKAGE_PATH`` the root, ``GAZEBO_MODEL_PATH`` the model folders,
``TURTLEBOT3_MODEL=burger`` and ``LDS_MODEL=LDS-01`` unless set (``--env`` sets any
variable), from a scratch folder, with a fresh workbench cache (``--cache DIR`` reuses
one). ROS's own tools decide what ROS accepts where they are installed (Debian's
python3-roslaunch, urdfdom's check_urdf and urdf_to_graphviz, libsdformat,
python3-rosbag; see :mod:`corpus_oracles`). A launch file's plan is compared with
roslaunch's by :mod:`launch_compare`. Each command ends in one class:

* works / works with warnings: workbench accepts the file and, where ROS's tool
  accepts it too, gives the same result (launch: the same nodes with every field
  roslaunch resolves, parameters, rosparam commands and machines; URDF: the same tree
  and graph);
* correct refusal: workbench and ROS's tool both refuse it ("needs args": a
  launch file whose required args were not given);
* refusal by design: workbench refuses on purpose what ROS accepts (a ``<machine>``
  on another computer; see the README);
* refusal, no oracle: workbench refuses and no ROS tool here can say otherwise;
* wrong: a different result, a refusal of what ROS accepts ("refused, roslaunch
  accepts"), or accepting what ROS refuses;
* traceback: a Python traceback (or workbench's internal-error guard);
* hang: no answer within the timeout, twice (the second time with twice as long);
* crash: killed by a signal (an abort), or stopped by SIGINT or SIGTERM from outside
  (twice).

Prints one table per kind with the share of the files ROS accepts that run (a
file without an oracle counts as accepted), then every file that does not work
with its one line; writes ``benchmarks/results/corpus.json`` (or ``--json``).
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from corpus_files import KINDS, Item, discover
from corpus_jobs import JOBS, Context, Result
from corpus_oracles import build_sdf_check, have_python_module
from corpus_run import CLASSES, CRASH, HANG, RUNS, TRACEBACK, WRONG
from machine import describe

ROOT = Path(__file__).resolve().parent.parent
SEED = 0  # nothing here is random; recorded for uniformity with the other benchmarks
#: Debian's Python, where python3-roslaunch and python3-rosbag live.
ROS_PYTHON = "/usr/bin/python3"
SKIPPED = "skipped"
#: Classes that make the run fail (exit status 1).
FAILURES = (WRONG, TRACEBACK, HANG, CRASH)


def accepted_by_ros(result: Result) -> bool:
    """ROS's tool accepts the file, or there is no oracle for it."""
    return not result.ros.startswith("refuses")


def summarize(results: Sequence[Result]) -> list[dict[str, object]]:
    """One row per (kind, command): counts per class, what ROS accepts and the share of it
    that runs."""
    rows = []
    for kind in KINDS:
        commands = sorted({r.command for r in results if r.kind == kind})
        for command in commands:
            mine = [r for r in results if r.kind == kind and r.command == command]
            counted = [r for r in mine if r.cls != SKIPPED]
            counts = Counter(r.cls for r in counted)
            accepted = [r for r in counted if accepted_by_ros(r)]
            running = sum(r.cls in RUNS for r in accepted)
            rows.append(
                {
                    "kind": kind,
                    "command": command,
                    "files": len(counted),
                    "skipped": len(mine) - len(counted),
                    **{cls: counts.get(cls, 0) for cls in CLASSES},
                    "ros_accepts": len(accepted),
                    "runs_of_accepted": running,
                    "runs_of_accepted_pct": round(100 * running / len(accepted), 1)
                    if accepted
                    else None,
                }
            )
    return rows


_SHORT = {
    "works": "works",
    "works with warnings": "warn",
    "correct refusal": "refuse ok",
    "refusal by design": "by design",
    "refusal, no oracle": "refuse ?",
    "wrong": "wrong",
    "traceback": "traceback",
    "hang": "hang",
    "crash": "crash",
}


def print_table(rows: Sequence[dict[str, object]]) -> None:
    heads = ["kind", "command", "files", *(_SHORT[c] for c in CLASSES), "ROS accepts", "runs %"]
    widths = [11, 17, 5, *(max(len(_SHORT[c]), 5) for c in CLASSES), 11, 6]
    line = "| " + " | ".join(h.ljust(w) for h, w in zip(heads, widths, strict=True)) + " |"
    print(line)
    print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    for row in rows:
        pct = row["runs_of_accepted_pct"]
        cells = [
            row["kind"],
            row["command"],
            row["files"],
            *(row[c] for c in CLASSES),
            row["ros_accepts"],
            "-" if pct is None else f"{pct:.1f}",
        ]
        print(
            "| "
            + " | ".join(
                str(c).ljust(w) if i < 2 else str(c).rjust(w)
                for i, (c, w) in enumerate(zip(cells, widths, strict=True))
            )
            + " |"
        )


def print_failures(results: Sequence[Result], root: Path, models: Sequence[Path]) -> None:
    order = {cls: i for i, cls in enumerate((*CLASSES, SKIPPED))}
    rest = sorted(
        (r for r in results if r.cls not in RUNS),
        key=lambda r: (order[r.cls], r.kind, r.command, r.file),
    )
    if not rest:
        return
    print("\nFiles that do not run (class, kind, command, file: workbench's line | ROS):")
    for r in rest:
        ros = "" if r.ros in ("accepts", "no oracle", "") else f" | ROS {r.ros}"
        print(
            f"- {r.cls}: {r.kind} {r.command} {_relative(r.file, root, models)}: {r.message}{ros}"
        )


def _relative(file: str, root: Path, models: Sequence[Path]) -> str:
    path = Path(file)
    for base in (root, *models):
        try:
            return str(path.relative_to(base.parent))
        except ValueError:
            continue
    return file


def sample(items: list[Item], kind: str, count: int | None) -> list[Item]:
    """``items`` with at most ``count`` of ``kind``, evenly spaced in sorted order."""
    if count is None:
        return items
    chosen = [i for i in items if i.kind == kind]
    if len(chosen) <= count:
        return items
    step = len(chosen) / count
    keep = {id(chosen[int(k * step)]) for k in range(count)}
    return [i for i in items if i.kind != kind or id(i) in keep]


def oracle_packages() -> list[Path]:
    """The folders of the packages workbench ships (its stand-ins for gazebo_ros, xacro
    ...), where workbench itself finds them, for roslaunch's ``ROS_PACKAGE_PATH`` after the
    root: both then find them at the same path, and both let the root's own package of the
    same name win (the first one found does, in rospkg and in workbench)."""
    from workbench.ros_packages import shipped_packages

    return list(dict.fromkeys(folder for folder, _origin in shipped_packages().values()))


def run_all(
    ctx: Context,
    items: Sequence[Item],
    jobs: int = 2,
    progress: Callable[[int, int, Item], None] | None = None,
) -> list[Result]:
    """Run every item's job on at most ``jobs`` (1 or 2) workers; results in item order."""
    done = 0

    def one(item: Item) -> list[Result]:
        nonlocal done
        results = JOBS[item.kind](ctx, item)
        done += 1
        if progress:
            progress(done, len(items), item)
        return results

    with ThreadPoolExecutor(max_workers=max(1, min(jobs, 2))) as pool:
        return [r for results in pool.map(one, items) for r in results]


def parse_args(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", required=True, type=Path, help="a folder of ROS packages")
    parser.add_argument(
        "--models", action="append", type=Path, default=[], help="a Gazebo model folder (repeat)"
    )
    parser.add_argument("--json", type=Path, help="write the results here")
    parser.add_argument(
        "--env",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="an environment variable for every command, workbench's and ROS's (repeat)",
    )
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per command")
    parser.add_argument(
        "--only", help=f"comma-separated kinds to run, of: {', '.join(KINDS)}", default=None
    )
    parser.add_argument("--jobs", type=int, default=2, help="parallel files (1 or 2)")
    parser.add_argument("--sample-models", type=int, help="check at most N Gazebo models")
    parser.add_argument(
        "--cache",
        type=Path,
        help="workbench's cache folder (default: a fresh one, as a new user has)",
    )
    args = parser.parse_args(argv)
    if args.only:
        args.only = [k.strip() for k in args.only.split(",") if k.strip()]
        unknown = sorted(set(args.only) - set(KINDS))
        if unknown:
            parser.error(f"unknown kind {unknown[0]} (kinds: {', '.join(KINDS)})")
    if not args.root.is_dir():
        parser.error(f"--root {args.root} is not a folder")
    for folder in args.models:
        if not folder.is_dir():
            parser.error(f"--models {folder} is not a folder")
    bad = [pair for pair in args.env if "=" not in pair or pair.startswith("=")]
    if bad:
        parser.error(f"--env {bad[0]} is not NAME=VALUE")
    args.env = dict(pair.split("=", 1) for pair in args.env)
    return args


def main(argv: Sequence[str] | None = None) -> int:
    args = parse_args(argv)
    root = args.root.resolve()
    models = [m.resolve() for m in args.models]
    kinds = set(args.only or KINDS)
    work = Path(tempfile.mkdtemp(prefix="workbench-corpus-"))
    try:
        needs_ros = bool(kinds & {"launch", "bag"})
        ros_python = (
            ROS_PYTHON if needs_ros and have_python_module(ROS_PYTHON, "roslaunch") else None
        )
        ctx = Context(
            root=root,
            models=models,
            work=work,
            timeout=args.timeout,
            ros_python=ros_python,
            check_urdf=shutil.which("check_urdf"),
            urdf_to_graphviz=shutil.which("urdf_to_graphviz"),
            sdf_check=build_sdf_check(work) if kinds & {"world", "model"} else None,
            rosbag=ros_python is not None and have_python_module(ROS_PYTHON, "rosbag"),
            oracle_packages=oracle_packages(),
            cache=args.cache or work / "cache",
            environment=args.env,
        )
        items = sample(discover(root, models, args.only), "model", args.sample_models)
        start = time.perf_counter()

        def progress(done: int, total: int, item: Item) -> None:
            print(f"[{done}/{total}] {item.kind} {item.path}", file=sys.stderr, flush=True)

        results = run_all(ctx, items, args.jobs, progress)
        wall = time.perf_counter() - start
    finally:
        shutil.rmtree(work, ignore_errors=True)

    oracles = {
        "roslaunch": ros_python or "not used or not installed",
        "check_urdf": ctx.check_urdf or "not installed",
        "urdf_to_graphviz": ctx.urdf_to_graphviz or "not installed",
        "libsdformat": "compiled checker" if ctx.sdf_check else "not used or not available",
        "rosbag": "python3-rosbag" if ctx.rosbag else "not used or not installed",
        "xacro for check_urdf": "workbench's xacro",
    }
    machine = describe(("drake", "lxml", "xacro"), seed=SEED, jobs=args.jobs)
    print(
        f"machine: {machine['cpu']}, {machine['cores']} cores (load {machine['load_average']}), "
        f"Python {machine['python']}, drake {machine['drake']}"
    )
    print(f"root: {root}; models: {', '.join(map(str, models)) or 'none'}")
    print(f"oracles: {'; '.join(f'{k}: {v}' for k, v in oracles.items())}")
    print(
        f"{len(items)} files, {len(results)} commands in {wall:.0f} s on {args.jobs} workers; "
        f"timeout {args.timeout:.0f} s (a hang is retried once with twice as long); "
        f"workbench cache: {args.cache or 'fresh'}\n"
    )
    rows = summarize(results)
    print_table(rows)
    print_failures(results, root, models)
    out = args.json or ROOT / "benchmarks" / "results" / "corpus.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    payload = {
        "benchmark": "corpus",
        "machine": machine,
        "root": str(root),
        "models": [str(m) for m in models],
        "timeout_s": args.timeout,
        "sample_models": args.sample_models,
        "cache": str(args.cache) if args.cache else "fresh",
        "oracles": oracles,
        "wall_s": round(wall, 1),
        "rows": rows,
        "results": [r.as_dict() for r in results],
    }
    out.write_text(json.dumps(payload, indent=2) + "\n")
    print(f"\nwrote {out}")
    return 1 if any(r.cls in FAILURES for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
