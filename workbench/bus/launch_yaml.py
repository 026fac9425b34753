"""The YAML form of a launch file::

    args: {turtle: turtle1}
    params: {/background_r: 150}
    nodes:
      - {pkg: turtlesim, type: turtlesim_node, name: sim, output: screen,
         params: {turtle: $(arg turtle)}, remap: {cmd_vel: /turtle1/cmd_vel}}
    include: [{file: other.launch, args: {x: 1}}]

Every key is checked for its shape (a mapping, a list of mappings, a string)
and a wrong one is an error naming the key, e.g. ``nodes[2].remap``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from workbench.bus.launch_context import (
    LaunchContext,
    LaunchError,
    LaunchPlan,
    NodeSpec,
    param_name,
    parse_bool,
    parse_delay,
    split_args,
)
from workbench.limits import load_yaml_file

TOP_LEVEL = ("args", "params", "nodes", "include", "remap")
NODE_KEYS = (
    "pkg",
    "type",
    "name",
    "ns",
    "args",
    "remap",
    "params",
    "output",
    "respawn",
    "respawn_delay",
    "required",
)


def _mapping(value: Any, ctx: LaunchContext, where: str) -> dict[Any, Any]:
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise ctx.error(
            f"'{where}' must be a mapping of names to values, not a {type(value).__name__}",
            hint=f"write it as {where}: {{name: value}}",
        )
    return value


def _list_of_mappings(value: Any, ctx: LaunchContext, where: str) -> list[dict[Any, Any]]:
    if value is None:
        return []
    if not isinstance(value, list):
        raise ctx.error(
            f"'{where}' must be a list of mappings, not a {type(value).__name__}",
            hint=f"write it as {where}: [{{...}}, {{...}}]",
        )
    for index, item in enumerate(value):
        if not isinstance(item, dict):
            raise ctx.error(f"{where}[{index}] must be a mapping, not a {type(item).__name__}")
    return value


def _text(value: Any, ctx: LaunchContext, where: str) -> str:
    if isinstance(value, (dict, list)) or value is None:
        raise ctx.error(f"{where} must be a single value, not a {type(value).__name__}")
    return str(value)


def load_yaml_launch(file: Path, ctx: LaunchContext, plan: LaunchPlan) -> None:
    """Read the YAML launch file ``file`` into ``plan`` (its ``args`` values are ``ctx.args``)."""
    given = dict(ctx.args)
    data = load_yaml_file(file, "launch file", LaunchError)
    if data is None:
        data = {}
    if not isinstance(data, dict):
        raise ctx.error("a YAML launch file is a mapping (args, params, nodes, include)")
    unknown = sorted(str(key) for key in set(data) - set(TOP_LEVEL))
    if unknown:
        raise ctx.error(f"unknown top-level key '{unknown[0]}'", hint="use " + ", ".join(TOP_LEVEL))
    for name, default in _mapping(data.get("args"), ctx, "args").items():
        if str(name) in given:
            ctx.args[str(name)] = given[str(name)]
        elif default is None:
            raise ctx.error(
                f"argument '{name}' has no value", hint=f"pass {name}:=VALUE on the command line"
            )
        else:
            ctx.args[str(name)] = _text(default, ctx, f"args.{name}")
        ctx.declare_arg(str(name), None, None, None)
    missing = sorted(set(given) - set(ctx.declared))
    if missing:
        raise ctx.error(f"argument '{missing[0]}' is not declared in the launch file")

    def sub(value: Any, where: str) -> Any:
        if isinstance(value, str):
            return ctx.substitute(value, where)
        if isinstance(value, list):
            return [sub(v, f"{where}[{i}]") for i, v in enumerate(value)]
        if isinstance(value, dict):
            return {k: sub(v, f"{where}.{k}") for k, v in value.items()}
        return value

    for key, value in _mapping(data.get("remap"), ctx, "remap").items():
        ctx.remaps[str(key)] = _text(sub(value, f"remap.{key}"), ctx, f"remap.{key}")
    for key, value in _mapping(data.get("params"), ctx, "params").items():
        plan.params[param_name(str(key), ctx.namespace)] = sub(value, f"params.{key}")
    for index, entry in enumerate(_list_of_mappings(data.get("nodes"), ctx, "nodes")):
        plan.nodes.append(_node(sub(entry, f"nodes[{index}]"), index, ctx, plan, file))
    for index, include in enumerate(_list_of_mappings(data.get("include"), ctx, "include")):
        where = f"include[{index}]"
        include = sub(include, where)
        if "file" not in include:
            raise ctx.error(f"{where} needs a 'file'", hint="write it as {file: other.launch}")
        args = _mapping(include.get("args"), ctx, f"{where}.args")
        ns = include.get("ns")
        ctx.include(
            _text(include["file"], ctx, f"{where}.file"),
            plan,
            {str(k): _text(v, ctx, f"{where}.args.{k}") for k, v in args.items()},
            _text(ns, ctx, f"{where}.ns") if ns is not None else None,
            None,
        )


def _node(
    entry: dict[Any, Any], index: int, ctx: LaunchContext, plan: LaunchPlan, file: Path
) -> NodeSpec:
    where = f"nodes[{index}]"
    if "pkg" not in entry or "type" not in entry:
        raise ctx.error(f"{where} needs pkg and type")
    unknown = sorted(str(key) for key in set(entry) - set(NODE_KEYS))
    if unknown:
        raise ctx.error(f"{where} has an unknown key '{unknown[0]}'", hint=", ".join(NODE_KEYS))
    node_type = _text(entry["type"], ctx, f"{where}.type")
    args = entry.get("args", [])
    if isinstance(args, str):
        argv = split_args(args, ctx, where)
    elif isinstance(args, list):
        argv = [_text(a, ctx, f"{where}.args[{i}]") for i, a in enumerate(args)]
    else:
        raise ctx.error(f"{where}.args must be a string or a list of words")
    ns = entry.get("ns")
    remaps = _mapping(entry.get("remap"), ctx, f"{where}.remap")
    spec = NodeSpec(
        pkg=_text(entry["pkg"], ctx, f"{where}.pkg"),
        type=node_type,
        name=_text(entry.get("name") or Path(node_type).stem, ctx, f"{where}.name"),
        namespace=ctx.child(_text(ns, ctx, f"{where}.ns")).namespace if ns else ctx.namespace,
        args=argv,
        remaps={
            **ctx.remaps,
            **{str(k): _text(v, ctx, f"{where}.remap.{k}") for k, v in remaps.items()},
        },
        output=_text(entry.get("output", "log"), ctx, f"{where}.output"),
        respawn=parse_bool(entry.get("respawn")),
        respawn_delay=parse_delay(entry.get("respawn_delay"), ctx, where),
        required=parse_bool(entry.get("required")),
        source=f"{file}:{where}",
    )
    for key, value in _mapping(entry.get("params"), ctx, f"{where}.params").items():
        plan.params[param_name(str(key), spec.full_name)] = value
    return spec
