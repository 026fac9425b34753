"""The commands benchmarks/corpus.py runs on each kind of file, beside ROS's own tools.

One function per kind takes the shared :class:`Context` and an
:class:`~corpus_files.Item` and returns one :class:`Result` per workbench
command run on the file. Every program runs through ``Context.runner`` in the
scratch folder, so nothing is written beside the user's packages.
"""

from __future__ import annotations

import itertools
import json
import os
import sys
import threading
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import launch_compare
from corpus_files import Item
from corpus_oracles import ROSBAG_PROBE, XACRO_PROBE
from corpus_run import (
    NO_ORACLE,
    REFUSAL,
    STOPPED_STATUSES,
    Outcome,
    Runner,
    Verdict,
    classify,
    error_line,
    failure,
    run_process,
    shorten,
    warning_lines,
)

#: Simulated time a world runs for, s.
SIM_SECONDS = 1.0
#: Wall time RViz runs for before it writes its snapshot, s.
RVIZ_SECONDS = 1.0
#: The environment every command gets unless the user's sets it (``--env`` overrides both):
#: the TurtleBot3 model and laser ROBOTIS's launch files read with ``$(env ...)``.
DEFAULT_ENV = {"TURTLEBOT3_MODEL": "burger", "LDS_MODEL": "LDS-01"}
#: Warnings about data a running system would publish, not about the file itself.
RUNTIME_WARNINGS = ("was not found by searchParam",)


@dataclass
class Result:
    """One workbench command on one file, classified.

    Attributes:
        kind: The kind of file (:data:`corpus_files.KINDS`).
        command: The workbench command, e.g. ``launch --dry-run``.
        file: The file.
        cls: One of :data:`corpus_run.CLASSES`, or ``skipped``.
        message: The one line that explains a class other than works.
        ros: ``accepts``, ``refuses: ...`` or ``no oracle``: ROS's own tool's answer.
        seconds: Wall time of the workbench command, s.
    """

    kind: str
    command: str
    file: str
    cls: str
    message: str
    ros: str
    seconds: float

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def ros_text(verdict: Verdict) -> str:
    if verdict.accepts is None:
        return "no oracle" if verdict is NO_ORACLE else f"no oracle ({verdict.message})"
    return "accepts" if verdict.accepts else shorten(f"refuses: {verdict.message}")


@dataclass
class Context:
    """What every job shares.

    Attributes:
        root: The folder of ROS packages (``ROS_PACKAGE_PATH``).
        models: Gazebo model folders (``GAZEBO_MODEL_PATH``).
        work: Scratch folder: every command runs there and writes its outputs there.
        timeout: Seconds a command may take before it counts as hung.
        workbench: The argv that runs workbench (``python -m workbench``).
        python: workbench's Python, for the probes that use its API.
        runner: Runs a program (:func:`corpus_run.run_process`; tests pass their own).
        ros_python: Debian's Python with ``roslaunch``, or None.
        check_urdf: urdfdom's ``check_urdf``, or None.
        urdf_to_graphviz: urdfdom's ``urdf_to_graphviz``, or None.
        sdf_check: The compiled libsdformat checker, or None.
        rosbag: ``ros_python`` also imports ``rosbag``.
        oracle_packages: Extra ``ROS_PACKAGE_PATH`` entries for roslaunch, after the root:
            the packages workbench ships, which stand in for ones installed with ROS
            (gazebo_ros, xacro), where workbench finds them.
        retry_hangs: Run a command that timed out once more with twice the time
            before calling it hung (a loaded machine is slow, not stuck).
        cache: workbench's cache folder (``WORKBENCH_CACHE_DIR``); None keeps the user's.
            A fresh one shows what a new user sees: meshes converted on first use.
        environment: Variables every command gets (``--env NAME=VALUE``), over
            :data:`DEFAULT_ENV` and the user's own.
    """

    root: Path
    models: list[Path]
    work: Path
    timeout: float
    workbench: list[str] = field(default_factory=lambda: [sys.executable, "-m", "workbench"])
    python: str = sys.executable
    runner: Runner = run_process
    ros_python: str | None = None
    check_urdf: str | None = None
    urdf_to_graphviz: str | None = None
    sdf_check: Path | None = None
    rosbag: bool = False
    oracle_packages: list[Path] = field(default_factory=list)
    retry_hangs: bool = True
    cache: Path | None = None
    environment: dict[str, str] = field(default_factory=dict)
    _counter: itertools.count = field(default_factory=itertools.count, repr=False)
    _lock: threading.Lock = field(default_factory=threading.Lock, repr=False)

    def scratch(self, name: str) -> Path:
        """A fresh path in the scratch folder, unique across jobs."""
        with self._lock:
            number = next(self._counter)
        return self.work / f"{number:05d}-{name}"

    def env(self, *, oracle: bool = False) -> dict[str, str]:
        """The environment of a command: the packages, the models, :data:`DEFAULT_ENV`,
        ``environment``."""
        env = {k: v for k, v in os.environ.items() if k != "WORKBENCH_DEBUG"}
        packages = [self.root, *(self.oracle_packages if oracle else [])]
        env["ROS_PACKAGE_PATH"] = os.pathsep.join(map(str, packages))
        env["GAZEBO_MODEL_PATH"] = os.pathsep.join(map(str, self.models))
        for name, value in DEFAULT_ENV.items():
            env.setdefault(name, value)
        env.update(self.environment)
        env["WORKBENCH_MASTER_URI"] = "inproc"  # never join a core another program runs
        if self.cache is not None:
            env["WORKBENCH_CACHE_DIR"] = str(self.cache)
        if oracle:  # Debian's Python must not see workbench's checkout or virtual env
            env.pop("PYTHONPATH", None)
            env.pop("VIRTUAL_ENV", None)
        return env

    def relative(self, text: str) -> str:
        """``text`` with the root's and the model folders' parents cut from its paths."""
        for folder in (self.root, *self.models):
            text = text.replace(f"{folder.parent}{os.sep}", "")
        return text

    def ours(self, argv: list[str]) -> Outcome:
        """Run a workbench command (once more with twice the time if it timed out, and once
        more if a signal from outside stopped it)."""
        outcome = self.runner(argv, self.env(), self.work, self.timeout)
        if outcome.timed_out and self.retry_hangs:
            outcome = self.runner(argv, self.env(), self.work, 2 * self.timeout)
        elif outcome.returncode in STOPPED_STATUSES:
            outcome = self.runner(argv, self.env(), self.work, self.timeout)
        return outcome

    def tool(self, argv: list[str], env: dict[str, str] | None = None) -> Outcome:
        """Run one of ROS's tools."""
        return self.runner(argv, env or self.env(oracle=True), self.work, self.timeout)


def _result(
    ctx: Context, item: Item, command: str, verdict: Verdict, outcome: Outcome
) -> Callable[..., Result]:
    def make(cls: str, message: str) -> Result:
        return Result(
            item.kind,
            command,
            str(item.path),
            cls,
            ctx.relative(message),
            ctx.relative(ros_text(verdict)),
            outcome.seconds,
        )

    return make


def _oracle_outcome(outcome: Outcome, tool: str) -> Verdict | None:
    """A broken oracle run (hang, crash, traceback) as a verdict of no oracle, else None."""
    broken = failure(outcome)
    return None if broken is None else Verdict(None, f"{tool} {broken[0]}: {broken[1]}")


# --- launch files ----------------------------------------------------------------------


#: workbench's own script for its side of the comparison (see :mod:`launch_compare`).
LAUNCH_COMPARE = Path(launch_compare.__file__).resolve()
#: What workbench refuses on purpose where roslaunch accepts (README, "Choices where a
#: launch file meets a machine that is not ROS"): a ``<machine>`` on another computer, a
#: ``binfile=`` parameter outside a dry run, a negative or NaN ``respawn_delay``.
LAUNCH_BY_DESIGN = (
    "workbench runs every node on this computer",
    "which workbench's parameter server does not hold",
    "must be 0 or more seconds",
)


def roslaunch_verdict(
    ctx: Context, path: Path, args: list[str]
) -> tuple[Verdict, dict[str, Any] | None]:
    """roslaunch's answer (:mod:`roslaunch_oracle`) and, when it accepts, its plan."""
    if ctx.ros_python is None:
        return NO_ORACLE, None
    outcome = ctx.tool([ctx.ros_python, str(launch_compare.ORACLE), str(path), *args])
    broken = _oracle_outcome(outcome, "roslaunch")
    if broken:
        return broken, None
    try:
        plan = json.loads(outcome.stdout)
    except ValueError:
        return Verdict(None, f"roslaunch oracle: {error_line(outcome)}"), None
    if "error" in plan:
        return Verdict(False, plan["error"]), None
    return Verdict(True), plan


def run_launch(ctx: Context, item: Item) -> list[Result]:
    """``workbench launch --dry-run FILE``; where roslaunch accepts the file, also the plan
    workbench resolves when it reads the parameter files too, compared with roslaunch's
    (:func:`launch_compare.differences`), and the dry run's nodes with that plan's.

    Each top-level ``<arg>`` without a value or default is given ``NAME:=value`` on both
    sides (:func:`launch_compare.required_args`)."""
    args = launch_compare.required_args(item.path)
    verdict, ros = roslaunch_verdict(ctx, item.path, args)
    cli = ctx.ours([*ctx.workbench, "launch", "--dry-run", str(item.path), *args])
    make = _result(ctx, item, "launch --dry-run", verdict, cli)
    broken = failure(cli)
    if broken:
        return [make(*broken)]
    ok, message, mismatch = cli.returncode == 0, error_line(cli), None
    if ok and verdict.accepts is not None:
        probe = ctx.ours([ctx.python, str(LAUNCH_COMPARE), str(item.path), *args])
        broken = failure(probe)
        if broken:
            return [make(broken[0], f"reading its parameter files: {broken[1]}")]
        try:
            data = json.loads(probe.stdout)
        except ValueError:
            data = {"plan": {"error": error_line(probe)}, "dry_run": None}
        if "error" in data["plan"]:
            ok, message = False, f"reading its parameter files: {data['plan']['error']}"
        elif ros is not None:
            problems = launch_compare.differences(
                launch_compare.normalise(data["plan"]), launch_compare.normalise(ros), limit=2
            )
            problems += [data["dry_run"]] if data["dry_run"] else []
            mismatch = "; ".join(problems) or None
    cls, line = classify(
        ok,
        message,
        verdict,
        warnings=warning_lines(cli.stderr),
        mismatch=mismatch,
        tool="roslaunch",
        by_design=any(part in message for part in LAUNCH_BY_DESIGN),
    )
    if cls == REFUSAL and "requires the" in verdict.message and "arg to be set" in verdict.message:
        line = f"needs args: {line}"
    return [make(cls, line)]


# --- robot descriptions ----------------------------------------------------------------


def _urdf_of(ctx: Context, item: Item) -> tuple[Path | None, str]:
    """The URDF ROS's tools read: the file, or the xacro expanded by workbench's xacro."""
    if item.path.suffix == ".urdf":
        return item.path, ""
    out = ctx.scratch(item.path.name + ".urdf")
    expanded = ctx.runner(
        [ctx.python, "-c", XACRO_PROBE, str(item.path), str(out)], ctx.env(), ctx.work, ctx.timeout
    )
    if expanded.returncode == 0 and out.is_file():
        return out, ""
    return None, f"xacro expansion failed: {failure(expanded) or error_line(expanded)}"


def run_description(ctx: Context, item: Item) -> list[Result]:
    """``workbench check`` and ``workbench graph`` against ``check_urdf`` and
    ``urdf_to_graphviz`` (the tree they print and the .gv they write must match)."""
    urdf, why = _urdf_of(ctx, item) if ctx.check_urdf else (None, "")
    verdict, ros_tree, ros_gv = NO_ORACLE, None, None
    if urdf is None and why:
        verdict = Verdict(None, why)
    elif urdf is not None and ctx.check_urdf:
        done = ctx.tool([ctx.check_urdf, str(urdf)])
        verdict = _oracle_outcome(done, "check_urdf") or Verdict(
            done.returncode == 0, error_line(done)
        )
        ros_tree = done.stdout.splitlines() if done.returncode == 0 else None
        if ctx.urdf_to_graphviz:
            base = ctx.scratch("ros")
            no_dot = dict(ctx.env(oracle=True), PATH=str(ctx.work / "no-programs"))
            ctx.tool([ctx.urdf_to_graphviz, str(urdf), str(base)], env=no_dot)
            gv = Path(f"{base}.gv")
            ros_gv = gv.read_text() if gv.is_file() else None
    results = []

    check = ctx.ours([*ctx.workbench, "check", "--json", str(item.path)])
    make = _result(ctx, item, "check", verdict, check)
    broken = failure(check)
    if broken:
        results.append(make(*broken))
    else:
        report, warnings = _check_report(check)
        mismatch = None
        tree = report.get("tree")
        if check.returncode == 0 and ros_tree is not None and tree is not None and tree != ros_tree:
            mismatch = "the tree it prints is not check_urdf's"
        results.append(
            make(
                *classify(
                    check.returncode == 0,
                    _check_error(report) or error_line(check),
                    verdict,
                    warnings=warnings,
                    mismatch=mismatch,
                    tool="check_urdf",
                )
            )
        )

    out = ctx.scratch(item.path.name + ".gv")
    graph = ctx.ours([*ctx.workbench, "graph", str(item.path), "-o", str(out)])
    graph_verdict = verdict
    if verdict.accepts is not None and ctx.urdf_to_graphviz:
        graph_verdict = Verdict(ros_gv is not None, verdict.message)
    make = _result(ctx, item, "graph", graph_verdict, graph)
    broken = failure(graph)
    if broken:
        results.append(make(*broken))
    else:
        ok = graph.returncode == 0 and out.is_file()
        mismatch = None
        if ok and ros_gv is not None and out.read_text() != ros_gv:
            mismatch = "its .gv is not urdf_to_graphviz's"
        results.append(
            make(
                *classify(
                    ok,
                    error_line(graph),
                    graph_verdict,
                    warnings=warning_lines(graph.stderr),
                    mismatch=mismatch,
                    tool="urdf_to_graphviz",
                )
            )
        )
    return results


def _check_report(check: Outcome) -> tuple[dict[str, Any], list[str]]:
    """``workbench check --json``'s report (empty when it printed none) and its warnings."""
    try:
        report = json.loads(check.stdout)
    except ValueError:
        report = {}
    warnings = [
        f"{f.get('element', '')}: {f.get('message', '')}"
        for f in report.get("findings", [])
        if f.get("severity") == "warning"
    ]
    return report, warnings + warning_lines(check.stderr)


def _check_error(report: dict[str, Any]) -> str:
    for finding in report.get("findings", []):
        if finding.get("severity") == "error":
            where = f" (line {finding['line']})" if finding.get("line") else ""
            return shorten(f"{finding.get('element', '')}{where}: {finding.get('message', '')}")
    return ""


# --- worlds and models -----------------------------------------------------------------


def sdformat_verdict(ctx: Context, path: Path) -> Verdict:
    """libsdformat's answer on a world or model."""
    if ctx.sdf_check is None:
        return NO_ORACLE
    done = ctx.tool([str(ctx.sdf_check), str(path)])
    broken = _oracle_outcome(done, "libsdformat")
    if broken:
        return broken
    errors = [
        line[len("error: ") :] for line in done.stdout.splitlines() if line.startswith("error: ")
    ]
    return Verdict(done.returncode == 0, shorten("; ".join(errors[:2])))


def run_world(ctx: Context, item: Item) -> list[Result]:
    """``workbench sim WORLD`` for :data:`SIM_SECONDS` of simulated time, headless, against
    libsdformat loading the world."""
    verdict = sdformat_verdict(ctx, item.path)
    argv = [*ctx.workbench, "sim", "--headless", "--fast", "--until", str(SIM_SECONDS)]
    sim = ctx.ours([*argv, str(item.path)])
    make = _result(ctx, item, "sim", verdict, sim)
    broken = failure(sim)
    if broken:
        return [make(*broken)]
    return [
        make(
            *classify(
                sim.returncode == 0,
                error_line(sim),
                verdict,
                warnings=warning_lines(sim.stderr),
                tool="libsdformat",
            )
        )
    ]


def run_model(ctx: Context, item: Item) -> list[Result]:
    """``workbench check MODEL.sdf`` against libsdformat loading the model."""
    verdict = sdformat_verdict(ctx, item.path)
    check = ctx.ours([*ctx.workbench, "check", "--json", str(item.path)])
    make = _result(ctx, item, "check", verdict, check)
    broken = failure(check)
    if broken:
        return [make(*broken)]
    report, warnings = _check_report(check)
    message = _check_error(report) or error_line(check)
    return [
        make(
            *classify(
                check.returncode == 0, message, verdict, warnings=warnings, tool="libsdformat"
            )
        )
    ]


# --- the rest --------------------------------------------------------------------------


def _plain(ctx: Context, item: Item, command: str, argv: list[str], verdict: Verdict) -> Result:
    outcome = ctx.ours(argv)
    make = _result(ctx, item, command, verdict, outcome)
    broken = failure(outcome)
    if broken:
        return make(*broken)
    warnings = warning_lines(outcome.stderr, RUNTIME_WARNINGS)
    return make(*classify(outcome.returncode == 0, error_line(outcome), verdict, warnings=warnings))


def run_srdf(ctx: Context, item: Item) -> list[Result]:
    """``workbench setup DESCRIPTION --srdf FILE --dry-run`` (no oracle: MoveIt is not here)."""
    if item.extra is None:
        reason = "no robot description found (launch/planning_context.launch)"
        return [Result(item.kind, "setup --srdf", str(item.path), "skipped", reason, "", 0.0)]
    out = ctx.scratch("setup")
    argv = [*ctx.workbench, "setup", str(item.extra), "--srdf", str(item.path), "--dry-run"]
    return [_plain(ctx, item, "setup --srdf", [*argv, "-o", str(out)], NO_ORACLE)]


def run_map(ctx: Context, item: Item) -> list[Result]:
    """``workbench map show MAP.yaml`` (no oracle: map_server is not here)."""
    argv = [*ctx.workbench, "map", "show", str(item.path)]
    return [_plain(ctx, item, "map show", argv, NO_ORACLE)]


def run_bag(ctx: Context, item: Item) -> list[Result]:
    """``workbench bag info BAG`` against rosbag opening it."""
    verdict = NO_ORACLE
    if ctx.rosbag and ctx.ros_python:
        done = ctx.tool([ctx.ros_python, "-c", ROSBAG_PROBE, str(item.path)])
        verdict = _oracle_outcome(done, "rosbag") or Verdict(done.returncode == 0, error_line(done))
    argv = [*ctx.workbench, "bag", "info", str(item.path)]
    return [_plain(ctx, item, "bag info", argv, verdict)]


def run_rviz(ctx: Context, item: Item) -> list[Result]:
    """``workbench rviz -d CONFIG`` for :data:`RVIZ_SECONDS`, writing a snapshot (no oracle:
    RViz is not here)."""
    out = ctx.scratch(item.path.stem + ".html")
    argv = [*ctx.workbench, "rviz", "-d", str(item.path), "--after", str(RVIZ_SECONDS)]
    return [_plain(ctx, item, "rviz -d", [*argv, "--html", str(out)], NO_ORACLE)]


JOBS: dict[str, Callable[[Context, Item], list[Result]]] = {
    "launch": run_launch,
    "description": run_description,
    "world": run_world,
    "model": run_model,
    "srdf": run_srdf,
    "map": run_map,
    "bag": run_bag,
    "rviz": run_rviz,
}
