"""Launch files: the roslaunch XML subset the labs use, and a YAML form.

XML: ``<launch>`` with ``<arg name default value>``, ``<param name value type
textfile command>``, ``<rosparam file command ns>`` (or inline YAML),
``<node pkg type name args ns output respawn respawn_delay required>`` with
nested ``<param>``, ``<rosparam>`` and ``<remap>``, ``<remap from to>``,
``<include file>`` with nested ``<arg>``, ``<group ns>``, and ``if``/``unless``
on any element (:mod:`workbench.bus.launch_xml`). Substitutions: ``$(arg x)``,
``$(find pkg)``, ``$(env X)``, ``$(optenv X default)``, ``$(anon name)``,
``$(dirname)``. The YAML form is in :mod:`workbench.bus.launch_yaml`.

Parsing produces a :class:`LaunchPlan`; :mod:`workbench.bus.launcher` runs it.
A dry run reads the launch files and nothing else: ``command=`` does not run
and ``textfile=`` / ``<rosparam file=>`` are not read.

Bounds: files of at most 16 MiB, YAML within :mod:`workbench.limits`, no
include cycles, at most 32 nested and 256 files in all, values of at most a
million characters after substitution.
"""

from __future__ import annotations

import os
from pathlib import Path

from workbench.bus.launch_context import (
    CommandRunner,
    Deferred,
    LaunchContext,
    LaunchError,
    LaunchPlan,
    LaunchShared,
    NodeSpec,
    find_package,
    typed_value,
)
from workbench.bus.launch_values import run_command
from workbench.limits import check_regular_file

__all__ = [
    "CommandRunner",
    "Deferred",
    "LaunchError",
    "LaunchPlan",
    "NodeSpec",
    "find_package",
    "load_launch",
    "run_command",
    "typed_value",
]


def _load_file(file: Path, ctx: LaunchContext, plan: LaunchPlan, args: dict[str, str]) -> None:
    from workbench.bus.launch_xml import load_xml
    from workbench.bus.launch_yaml import load_yaml_launch

    (load_yaml_launch if file.suffix in (".yaml", ".yml") else load_xml)(file, ctx, plan, args)


def load_launch(
    path: str | os.PathLike[str],
    args: dict[str, str] | None = None,
    *,
    dry_run: bool = False,
    command_runner: CommandRunner | None = None,
) -> LaunchPlan:
    """Parse a launch file (``.launch``/``.xml`` or ``.yaml``/``.yml``) into a plan.

    Args:
        path: The file.
        args: Values for its ``<arg>`` (``name:=value`` on the command line).
        dry_run: Run no command and read no file but the launch files.
        command_runner: Runs ``<param command=...>`` (default :func:`run_command`, which
            refuses xacro; ``workbench launch`` passes one that expands it).

    Raises:
        LaunchError: Unreadable file, bad XML/YAML, unknown element, missing arg, a bad
            value, an include cycle, or a bound passed.
    """
    file = Path(path)
    if not file.exists():
        raise LaunchError(f"launch file {file} does not exist")
    check_regular_file(file, "launch file", LaunchError)
    plan = LaunchPlan()
    shared = LaunchShared(dry_run, command_runner or run_command, _load_file)
    _load_file(file.resolve(), LaunchContext(file.resolve(), {}, shared), plan, dict(args or {}))
    names = [spec.full_name for spec in plan.nodes]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise LaunchError(
            f"node name {duplicates[0]} is used twice",
            path=file,
            hint="give each node a unique name",
        )
    return plan
