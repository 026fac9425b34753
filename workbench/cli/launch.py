"""``workbench launch FILE [name:=value ...]``: start the nodes of a launch file (roslaunch)."""

from __future__ import annotations

import argparse
from pathlib import Path


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "target",
        nargs="+",
        help="a launch file (.launch/.xml or .yaml), or PACKAGE FILE; then arg:=value pairs",
    )
    parser.add_argument("--uri", help="the core's address (default $WORKBENCH_MASTER_URI)")
    parser.add_argument("--dry-run", action="store_true", help="print the plan, start nothing")


def run(args: argparse.Namespace) -> int:
    path, values = split_target(args.target)
    return launch(path, values, uri=args.uri, dry_run=args.dry_run)


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
    raise LaunchError("give a launch file, or a package and a launch file name")


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
    from workbench.bus.launch import load_launch

    plan = load_launch(path, dict(values or {}))
    if dry_run:
        for name, value in sorted(plan.params.items()):
            text = repr(value)
            print(f"param {name} = {text if len(text) < 60 else text[:57] + '...'}")
        for spec in plan.nodes:
            extra = " ".join([*spec.args, *(f"{a}:={b}" for a, b in spec.remaps.items())])
            print(f"node {spec.full_name}: {spec.pkg}/{spec.type} {extra}".rstrip())
        return 0
    from workbench.bus.launcher import Launcher

    launcher = Launcher(plan, uri=uri, near=path.resolve().parent)
    try:
        launcher.start()
        launcher.wait()
    finally:
        launcher.shutdown()
    return 0
