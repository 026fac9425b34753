"""``workbench launch FILE [name:=value ...]``: start the nodes of a launch file (roslaunch)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from workbench.bus.launch import LaunchPlan


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "target",
        nargs="*",
        help="a launch file (.launch/.xml or .yaml), or PACKAGE FILE; then arg:=value pairs",
    )
    parser.add_argument(
        "--which",
        metavar="PACKAGE",
        help="print the folder PACKAGE is found in, where it was found and what it shadows",
    )
    parser.add_argument("--uri", help="the core's address (default $WORKBENCH_MASTER_URI)")
    parser.add_argument(
        "--dry-run",
        action="store_true",
        help="print the plan; start, run and read nothing but the launch files",
    )
    parser.add_argument(
        "--ros-args",
        action="store_true",
        help="list the launch file's arguments (with their doc and default) and exit",
    )


def run(args: argparse.Namespace) -> int:
    if args.which:
        return which(args.which)
    path, values = split_target(args.target)
    if args.ros_args:
        return print_args(path, values)
    return launch(path, values, uri=args.uri, dry_run=args.dry_run)


def which(package: str) -> int:
    """Print where ``package`` is found (``rospack find``, with the origin and what it shadows).

    Raises:
        PackageLookupError: No such package on the search path.
    """
    from workbench.ros_packages import locate_package

    location = locate_package(package)
    print(f"{location.path}  ({location.origin})")
    for shadowed in location.shadows:
        print(f"  shadows {shadowed}")
    return 0


def _shipped_launch_file(name: str) -> Path | None:
    """A launch file of the lab's shipped packages (``start_demo.launch``), when just one has it."""
    from workbench.paths import examples_dir

    found = sorted(examples_dir().glob(f"*/{name}")) + sorted(
        examples_dir().glob(f"packages/*/launch/{name}")
    )
    return found[0] if len(found) == 1 else None


def split_target(target: list[str]) -> tuple[Path, dict[str, str]]:
    """The launch file and the ``arg:=value`` settings of ``FILE`` or ``PACKAGE FILE`` words.

    Raises:
        LaunchError: Not one file or one package and file, or no such file in the package.
    """
    from workbench.bus.launch import LaunchError, find_package

    words = [w for w in target if ":=" not in w]
    values = dict(w.split(":=", 1) for w in target if ":=" in w)
    if len(words) == 1:
        path = Path(words[0])
        if not path.exists() and path.name == words[0]:
            path = _shipped_launch_file(words[0]) or path
        return path, values
    if len(words) == 2:
        package = find_package(words[0])
        for candidate in (package / "launch" / words[1], package / words[1]):
            if candidate.is_file():
                return candidate, values
        raise LaunchError(f"no launch file {words[1]} in package {words[0]} ({package})")
    raise LaunchError(
        "give a launch file, or a package and a launch file name",
        hint="workbench launch PACKAGE FILE [arg:=value ...], or --which PACKAGE",
    )


def run_command(command: str, launch_file: Path) -> str:
    """Run a ``<param command=...>``: xacro in this process, anything else as a program.

    ``xacro FILE [name:=value ...]`` (also ``$(find xacro)/xacro.py``) expands FILE with
    workbench's own xacro, the one ``workbench check``/``show`` use; options such as
    ``--inorder`` are accepted and ignored (their behaviour is the default).

    Raises:
        LaunchError: A command that cannot be split, or a xacro command without a file.
        WorkbenchError: xacro failed (its own one-line message), or the program failed.
    """
    import shlex

    from workbench.bus.launch import LaunchError
    from workbench.bus.launch import run_command as run_program
    from workbench.bus.launch_values import is_xacro_command

    try:
        argv = shlex.split(command)
    except ValueError as error:
        raise LaunchError(f"param command {command!r} cannot be split ({error})") from None
    if not is_xacro_command(argv):
        return run_program(command, launch_file)
    from workbench.model.sources import expand_xacro

    files = [a for a in argv[1:] if ":=" not in a and not a.startswith("-")]
    mappings = dict(a.split(":=", 1) for a in argv[1:] if ":=" in a)
    if len(files) != 1:
        raise LaunchError(
            f"param command '{command}' names {len(files)} files; xacro takes one",
            path=launch_file,
        )
    source = Path(files[0])
    source = source if source.is_absolute() else launch_file.parent / source
    return expand_xacro(source, mappings)


def load(path: Path, values: dict[str, str], dry_run: bool) -> LaunchPlan:
    """The plan of the launch file ``path``, with xacro and ``$(eval)`` as workbench has them.

    Raises:
        LaunchError: The file is missing or malformed.
    """
    from workbench.bus.launch import load_launch

    return load_launch(
        path,
        dict(values),
        dry_run=dry_run,
        command_runner=None if dry_run else run_command,
        evaluate=_evaluate,
    )


def _evaluate(expression: str, variables: dict[str, Any], functions: dict[str, Any]) -> Any:
    """``$(eval)`` in xacro's sandbox, imported on the first expression (most files have none)."""
    from workbench.model.launch_eval import evaluate_launch_expression

    return evaluate_launch_expression(expression, variables, functions)


def print_args(path: Path, values: dict[str, str]) -> int:
    """``--ros-args``: the top-level file's arguments, required ones first (as roslaunch)."""
    plan = load(path, values, dry_run=True)
    free = [a for a in plan.args if not a.fixed]
    for title, group in (
        ("Required Arguments:", [a for a in free if a.default is None]),
        ("Optional Arguments:", [a for a in free if a.default is not None]),
    ):
        if group:
            print(title)
            for arg in group:
                default = "" if arg.default is None else f' (default "{arg.default}")'
                print(f"  {arg.name}{default}: {arg.doc or 'undocumented'}")
    return 0


def describe_plan(plan: LaunchPlan) -> list[str]:
    """The lines ``--dry-run`` prints: parameters, rosparam commands, nodes, tests."""
    from workbench.bus.launch import Deferred

    lines = [f"clear {namespace}/*" for namespace in plan.clear_params]
    for command in plan.rosparam_commands:
        target = f" {command.file}" if command.command == "dump" else ""
        lines.append(f"rosparam {command.command}{target} {command.param} (before the params)")
    for name, value in sorted(plan.params.items()):
        text = repr(value)
        if len(text) >= 60 and not isinstance(value, Deferred):
            text = text[:57] + "..."
        lines.append(f"param {name} = {text}")
    for namespace, file in plan.rosparam_files:
        lines.append(f"rosparam {namespace} <- {file} (not read in a dry run)")
    for spec in plan.nodes:
        extra = " ".join([*spec.args, *(f"{a}:={b}" for a, b in spec.remaps.items())])
        lines.append(f"node {spec.full_name}: {spec.pkg}/{spec.type} {extra}".rstrip())
        notes = [f"env {k}={v}" for k, v in spec.env.items()]
        if spec.launch_prefix:
            notes.append(f"launch-prefix '{spec.launch_prefix}'")
        if spec.cwd:
            notes.append(f"cwd {spec.cwd}")
        if spec.required:
            notes.append("required")
        if spec.respawn:
            notes.append(f"respawn after {spec.respawn_delay:g} s")
        if spec.machine:
            notes.append(f"machine {spec.machine} (this computer)")
        lines += [f"    {note}" for note in notes]
    for test in plan.tests:
        lines.append(
            f"test {test.full_name}: {test.pkg}/{test.type} (test-name {test.test_name}, "
            f"time-limit {test.time_limit:g} s; listed, not run: rostest runs tests)"
        )
    return lines


def launch(
    path: Path,
    values: dict[str, str] | None = None,
    *,
    uri: str | None = None,
    dry_run: bool = False,
) -> int:
    """Start the nodes of the launch file ``path`` and wait for them (or print the plan).

    Args:
        path: A ``.launch``/``.xml`` or ``.yaml`` launch file.
        values: ``arg`` values for the file (``name:=value`` on the command line).
        uri: The core's address (default ``$WORKBENCH_MASTER_URI``).
        dry_run: Print the parameters and nodes instead of starting anything.

    Raises:
        LaunchError: The file is missing or malformed.
    """
    import sys

    plan = load(path, dict(values or {}), dry_run)
    for warning in plan.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    if dry_run:
        for line in describe_plan(plan):
            print(line)
        return 0
    from workbench.bus.launcher import Launcher

    launcher = Launcher(plan, uri=uri, near=path.resolve().parent)
    try:
        launcher.start()
        launcher.wait()
    finally:
        launcher.shutdown()
    return 0
