"""ROS 1's roslaunch and workbench's launch loader on the same file: the two plans, compared.

ROS's side is Debian's ``python3-roslaunch``, run by :mod:`roslaunch_oracle` in
``/usr/bin/python3`` (its XML loader, no master); workbench's side is :func:`load_launch`
with the same ``ROS_PACKAGE_PATH``, environment and arguments. Both plans are normalised
(:func:`normalise`: namespaces without a trailing slash, ``args`` split as a shell does,
remappings and ``<env>`` as mappings, ``$(anon)`` names numbered in order of appearance)
and compared field by field (:func:`differences`): nodes and tests (package, type, name,
namespace, args, remaps, env, output, respawn, respawn_delay, required, launch_prefix, cwd,
machine), parameters with their types, cleared namespaces, ``rosparam`` commands and
machines. ``<param command=...>`` runs on neither side: both give the marker
``<command: ...>`` with the substituted command.

Used by ``benchmarks/corpus.py`` (its ``launch`` kind) and by the differential test of the
launch loader. Run as a script, it prints workbench's side for one file as JSON, in
workbench's Python, as a child process of the corpus benchmark::

    python benchmarks/launch_compare.py FILE [NAME:=VALUE ...]

prints ``{"plan": PLAN, "dry_run": null}`` (``PLAN`` in the oracle's shape, or ``{"error":
LINE}`` for workbench's one-line refusal); ``dry_run`` says how ``workbench launch
--dry-run``, which reads no file but the launch files, finds other nodes (null when it
finds the same).
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import re
import shlex
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

ORACLE = Path(__file__).resolve().parent / "roslaunch_oracle.py"
ROS_PYTHON = "/usr/bin/python3"
COMMAND_MARKER = "<command: {}>"
RUN_FIELDS = ("output", "respawn", "respawn_delay", "required")
TEST_FIELDS = ("test_name", "time_limit", "retry")
_ANON = re.compile(r"([A-Za-z_]\w*?)_anon\d+")

# --- the two loaders --------------------------------------------------------------------


def roslaunch_plans(jobs: list[dict[str, Any]], timeout: float = 600) -> list[dict[str, Any]]:
    """roslaunch's plan (or ``{"error": ...}``) for each job, in one system-Python process."""
    done = subprocess.run(
        [ROS_PYTHON, str(ORACLE)],
        input=json.dumps(jobs),
        capture_output=True,
        text=True,
        timeout=timeout,
        env={**os.environ, "PYTHONPATH": ""},
    )
    if done.returncode != 0:
        raise RuntimeError(f"roslaunch_oracle.py failed: {done.stderr.strip()[-2000:]}")
    return json.loads(done.stdout)


@contextlib.contextmanager
def _environment(extra: dict[str, str]) -> Iterator[None]:
    saved = dict(os.environ)
    os.environ.update(extra)
    try:
        yield
    finally:
        os.environ.clear()
        os.environ.update(saved)


@contextlib.contextmanager
def _numbered_anon() -> Iterator[None]:
    """``$(anon id)`` as ``id_anonN`` (N counts the calls), as the oracle numbers them."""
    from workbench.bus import launch_subst

    calls = [0]

    def numbered(base: str) -> str:
        calls[0] += 1
        return f"{base}_anon{calls[0]}"

    saved = launch_subst.anonymous_name
    launch_subst.anonymous_name = numbered  # type: ignore[assignment]
    try:
        yield
    finally:
        launch_subst.anonymous_name = saved  # type: ignore[assignment]


def _values(argv: list[str]) -> dict[str, str]:
    return dict(a.split(":=", 1) for a in argv)


def workbench_plan(job: dict[str, Any], dry_run: bool = False) -> dict[str, Any]:
    """workbench's plan for one job as the oracle prints it (or ``{"error": ...}``); with
    ``dry_run``, as ``workbench launch --dry-run`` reads it (no file but the launch files)."""
    from workbench.bus.launch import load_launch
    from workbench.errors import WorkbenchError
    from workbench.model.launch_eval import evaluate_launch_expression

    def marker(command: str, _file: Path) -> str:
        return COMMAND_MARKER.format(command)

    with _environment(job.get("env", {})), _numbered_anon():
        try:
            plan = load_launch(
                job["file"],
                _values(job.get("argv", [])),
                dry_run=dry_run,
                command_runner=marker,
                evaluate=evaluate_launch_expression,
            )
        except WorkbenchError as error:
            return {"error": error.one_line()}
    return plan_json(plan)


def plan_json(plan: Any) -> dict[str, Any]:
    """A :class:`LaunchPlan` in the oracle's JSON shape."""

    def node(spec: Any, test: bool) -> dict[str, Any]:
        out = {
            "pkg": spec.pkg,
            "type": spec.type,
            "name": spec.name,
            "namespace": spec.namespace,
            "args": spec.args,
            "remaps": [list(pair) for pair in spec.remaps.items()],
            "env": [list(pair) for pair in spec.env.items()],
            "launch_prefix": spec.launch_prefix,
            "cwd": spec.cwd,
            "machine": spec.machine,
        }
        fields = TEST_FIELDS if test else RUN_FIELDS
        out.update({name: getattr(spec, name) for name in fields})
        return out

    return {
        "nodes": [node(spec, False) for spec in plan.nodes],
        "tests": [node(spec, True) for spec in plan.tests],
        "params": {name: _deferred(value) for name, value in plan.params.items()},
        "clear_params": list(plan.clear_params),
        "executables": [
            ["rosparam", [c.command, *([c.file] if c.command == "dump" else []), c.param]]
            for c in plan.rosparam_commands
        ],
        "machines": dict(plan.machines),
    }


def _deferred(value: Any) -> Any:
    """A dry run's :class:`Deferred` value as its text (what ``--dry-run`` prints)."""
    from workbench.bus.launch import Deferred

    return repr(value) if isinstance(value, Deferred) else value


# --- comparing ------------------------------------------------------------------------------


def _namespace(name: str) -> str:
    name = re.sub("//+", "/", name or "/")
    return name.rstrip("/") or "/"


def _canonical(name: str) -> str:
    if not name or name == "/":
        return name
    parts = [p for p in name.split("/") if p]
    return ("/" if name.startswith("/") else "") + "/".join(parts)


def _value(value: Any) -> Any:
    if isinstance(value, tuple | list):
        return [_value(v) for v in value]
    if isinstance(value, dict):
        return {str(k): _value(v) for k, v in value.items()}
    if isinstance(value, float) and not math.isfinite(value):
        return {"float": repr(value)}  # as the oracle spells it in JSON
    return value


def normalise(plan: dict[str, Any]) -> dict[str, Any]:
    """A plan with ROS's equivalent spellings made equal (see the module's note)."""
    if "error" in plan:
        return plan

    def node(raw: dict[str, Any], test: bool) -> dict[str, Any]:
        args = raw["args"]
        if isinstance(args, str):
            try:
                args = shlex.split(args)
            except ValueError:
                args = [args]
        out = {
            "pkg": raw["pkg"],
            "type": raw["type"],
            "name": raw["name"],
            "namespace": _namespace(raw["namespace"]),
            "args": list(args),
            "remaps": {_canonical(a): _canonical(b) for a, b in raw["remaps"]},
            "env": dict(tuple(pair) for pair in raw["env"]),
            "launch_prefix": raw.get("launch_prefix") or None,
            "cwd": raw.get("cwd") or None,
            "machine": raw.get("machine") or None,
        }
        if test:
            out.update({name: raw.get(name) for name in TEST_FIELDS})
        else:
            out.update(
                output=raw.get("output") or "log",
                respawn=bool(raw.get("respawn")),
                respawn_delay=float(raw.get("respawn_delay") or 0.0),
                required=bool(raw.get("required")),
            )
        return out

    normal = {
        "nodes": [node(n, False) for n in plan["nodes"]],
        "tests": [node(t, True) for t in plan["tests"]],
        "params": {_canonical(k): _value(v) for k, v in plan["params"].items()},
        "clear_params": sorted(_namespace(p) for p in plan["clear_params"]),
        "executables": plan["executables"],
        "machines": plan["machines"],
    }
    return _renumber_anon(normal)


def _renumber_anon(plan: dict[str, Any]) -> dict[str, Any]:
    """``id_anonN`` renumbered by first appearance, so the two loaders' call orders do not
    matter, only which names are the same."""
    text = json.dumps(plan, sort_keys=True)
    numbers: dict[str, int] = {}

    def renumber(match: re.Match[str]) -> str:
        number = numbers.setdefault(match.group(0), len(numbers) + 1)
        return f"{match.group(1)}_anon#{number}"

    return json.loads(_ANON.sub(renumber, text))


def differences(ours: dict[str, Any], theirs: dict[str, Any], limit: int = 5) -> list[str]:
    """What differs between two normalised plans (at most ``limit`` lines)."""
    found: list[str] = []
    if len(ours["nodes"]) != len(theirs["nodes"]) or [n["name"] for n in ours["nodes"]] != [
        n["name"] for n in theirs["nodes"]
    ]:
        found.append(
            f"nodes: ours {[n['name'] for n in ours['nodes']]}, "
            f"roslaunch {[n['name'] for n in theirs['nodes']]}"
        )
    else:
        for a, b in zip(ours["nodes"], theirs["nodes"], strict=True):
            for key in a:
                if a[key] != b.get(key):
                    found.append(f"node {b['name']} {key}: ours {a[key]!r}, roslaunch {b[key]!r}")
    if ours["tests"] != theirs["tests"]:
        found.append(f"tests: ours {ours['tests']!r}, roslaunch {theirs['tests']!r}")
    for key in sorted(set(ours["params"]) | set(theirs["params"])):
        a, b = ours["params"].get(key, "<unset>"), theirs["params"].get(key, "<unset>")
        if a != b or type(a) is not type(b) and not (_number(a) and _number(b)):
            found.append(f"param {key}: ours {_short(a)}, roslaunch {_short(b)}")
    for key in ("clear_params", "executables", "machines"):
        if ours[key] != theirs[key]:
            found.append(f"{key}: ours {ours[key]!r}, roslaunch {theirs[key]!r}")
    return found[:limit] + ([f"... {len(found) - limit} more"] if len(found) > limit else [])


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def classify(ours: dict[str, Any], theirs: dict[str, Any]) -> tuple[str, list[str]]:
    """``agree``, ``differ``, ``ours only``, ``roslaunch only`` or ``both refuse``, and why."""
    if "error" in theirs and "error" in ours:
        return "both refuse", [f"ours: {ours['error']}", f"roslaunch: {theirs['error']}"]
    if "error" in theirs:
        return "ours only", [f"roslaunch: {theirs['error']}"]
    if "error" in ours:
        return "roslaunch only", [f"ours: {ours['error']}"]
    found = differences(normalise(ours), normalise(theirs))
    return ("differ", found) if found else ("agree", [])


# --- arguments and the command line --------------------------------------------------------


def required_args(path: Path) -> list[str]:
    """``NAME:=value`` for each top-level ``<arg>`` without value or default: roslaunch asks
    for one, and any text resolves the file."""
    from lxml import etree

    try:
        root = etree.parse(str(path), etree.XMLParser(resolve_entities=False)).getroot()
    except (etree.XMLSyntaxError, OSError):
        return []
    return [
        f"{e.get('name')}:=value"
        for e in root
        if e.tag == "arg" and e.get("name") and e.get("value") is None and e.get("default") is None
    ]


def dry_run_difference(job: dict[str, Any], plan: dict[str, Any]) -> str | None:
    """How the dry run's nodes differ from ``plan``'s (workbench's full read), or None."""
    dry = workbench_plan(job, dry_run=True)
    if "error" in dry:
        return f"the dry run refuses: {dry['error']}"
    ours, theirs = normalise(dry)["nodes"], normalise(plan)["nodes"]
    if ours == theirs:
        return None
    return f"the dry run finds nodes {[n['name'] for n in ours]}, not {[n['name'] for n in theirs]}"


def main(argv: list[str]) -> int:
    if not argv or argv[0].startswith("-"):
        print("usage: python benchmarks/launch_compare.py FILE [NAME:=VALUE ...]", file=sys.stderr)
        return 2
    job = {"file": argv[0], "argv": argv[1:]}
    with contextlib.redirect_stdout(sys.stderr):  # stdout carries the JSON alone
        plan = workbench_plan(job)
        dry = None if "error" in plan else dry_run_difference(job, plan)
    json.dump({"plan": plan, "dry_run": dry}, sys.stdout)
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
