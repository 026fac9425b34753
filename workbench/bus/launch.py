"""Launch files: roslaunch's XML, read as ROS 1's roslaunch reads it, and a YAML form.

XML (:mod:`workbench.bus.launch_xml`): ``<launch>`` with ``<arg name value default
doc>``, ``<param name value|textfile|binfile|command type>``, ``<rosparam command="load|
dump|delete" file ns param subst_value>`` (rosparam's ``!degrees``/``!radians``),
``<node pkg type name args ns output respawn respawn_delay required cwd launch-prefix
machine clear_params>`` with nested ``<param>``, ``<rosparam>``, ``<remap>`` and
``<env>``, ``<test>`` (listed, not run), ``<remap>``, ``<env>``, ``<machine>`` (this
computer only), ``<include file ns clear_params pass_all_args>`` with nested ``<arg>``
and ``<env>``, ``<group ns clear_params>``, and ``if``/``unless`` on any element.
Substitutions (:mod:`workbench.bus.launch_subst`): ``$(arg)``, ``$(find)``, ``$(env)``,
``$(optenv)``, ``$(anon)``, ``$(dirname)`` and ``$(eval)``. The YAML form is in
:mod:`workbench.bus.launch_yaml`.

Parsing produces a :class:`LaunchPlan`; :mod:`workbench.bus.launcher` runs it.
A dry run reads the launch files and nothing else: ``command=`` does not run
and ``textfile=`` / ``<rosparam file=>`` are not read.

Bounds: files of at most 16 MiB, YAML within :mod:`workbench.limits`, no
include cycles, at most 32 nested and 256 files in all, values of at most a
million characters after substitution, expressions within the sandbox's bounds.
"""

from __future__ import annotations

import os
from pathlib import Path

from workbench.bus.launch_context import (
    CommandRunner,
    LaunchContext,
    LaunchError,
    LaunchShared,
    find_package,
    typed_value,
)
from workbench.bus.launch_plan import (
    Deferred,
    LaunchArg,
    LaunchPlan,
    NodeSpec,
    RosparamCommand,
    TestSpec,
)
from workbench.bus.launch_subst import ExpressionEvaluator
from workbench.bus.launch_values import run_command
from workbench.limits import check_regular_file

__all__ = [
    "CommandRunner",
    "Deferred",
    "ExpressionEvaluator",
    "LaunchArg",
    "LaunchError",
    "LaunchPlan",
    "NodeSpec",
    "RosparamCommand",
    "TestSpec",
    "find_package",
    "load_launch",
    "run_command",
    "typed_value",
]


def _load_file(file: Path, ctx: LaunchContext, plan: LaunchPlan) -> None:
    from workbench.bus.launch_xml import load_xml
    from workbench.bus.launch_yaml import load_yaml_launch

    (load_yaml_launch if file.suffix in (".yaml", ".yml") else load_xml)(file, ctx, plan)


def load_launch(
    path: str | os.PathLike[str],
    args: dict[str, str] | None = None,
    *,
    dry_run: bool = False,
    command_runner: CommandRunner | None = None,
    evaluate: ExpressionEvaluator | None = None,
) -> LaunchPlan:
    """Parse a launch file (``.launch``/``.xml`` or ``.yaml``/``.yml``) into a plan.

    Args:
        path: The file.
        args: Values for its ``<arg>`` (``name:=value`` on the command line).
        dry_run: Run no command and read no file but the launch files.
        command_runner: Runs ``<param command=...>`` (default :func:`run_command`, which
            refuses xacro; ``workbench launch`` passes one that expands it).
        evaluate: The expression sandbox for ``$(eval)`` and rosparam's ``!radians``
            (``workbench.model.launch_eval.evaluate_launch_expression``, which
            ``workbench launch`` passes; without it they are refused).

    Raises:
        LaunchError: Unreadable file, bad XML/YAML, a missing arg, a bad
            value, an include cycle, a remote machine, or a bound passed.
    """
    file = Path(path)
    if not file.exists():
        raise LaunchError(f"launch file {file} does not exist")
    check_regular_file(file, "launch file", LaunchError)
    plan = LaunchPlan()
    top = file.resolve()
    given = dict(args or {})
    shared = LaunchShared(dry_run, command_runner or run_command, _load_file, evaluate, top)
    _load_file(top, LaunchContext(top, given, shared), plan)
    for name in sorted(set(given) - shared.top_declared):
        # roslaunch ignores a command-line value no <arg> declares (gui:=false to a file
        # without a gui arg); a warning still catches a misspelt name.
        plan.warnings.append(f"{file}: argument '{name}' is not declared; ignored")
    names = [spec.full_name for spec in plan.nodes]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise LaunchError(
            f"node name {duplicates[0]} is used twice",
            path=file,
            hint="give each node a unique name",
        )
    for spec in [*plan.nodes, *plan.tests]:
        if spec.machine is not None and spec.machine not in plan.machines:
            raise LaunchError(
                f"node {spec.full_name} names machine '{spec.machine}', which no <machine> "
                "declares",
                path=spec.source,
            )
    return plan
