"""roslaunch's ``<node>`` and ``<test>``: attributes, nested elements, and the ~params they get.

A node sees the remappings and ``<env>`` of its scope plus its own; its ``<param>`` and
``<rosparam>`` are its private parameters, after the ``~params`` its scope set before it.
A ``<test>`` is read the same way (rostest's ``test-name``, ``time-limit``, ``retry``) and
listed in the plan; ``workbench launch`` does not run it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from workbench.bus.launch_context import (
    LaunchContext,
    LaunchPlan,
    NodeSpec,
    TestSpec,
    canonical_name,
    legal_name,
    parse_delay,
    split_args,
)
from workbench.bus.launch_xml_attrs import (
    attr,
    elements,
    enabled,
    float_attr,
    required,
    scoped,
    to_bool,
    where,
)
from workbench.bus.launch_xml_params import param, rosparam

OUTPUTS = ("log", "screen")
CWDS = ("ROS_HOME", "node")


def remap_pair(element: Any, ctx: LaunchContext) -> tuple[str, str]:
    """``<remap from to>``, canonical, both legal ROS names.

    Raises:
        LaunchError: A missing, empty or illegal name.
    """
    line = element.sourceline
    pair = [canonical_name(required(element, key, ctx)) for key in ("from", "to")]
    for key, name in zip(("from", "to"), pair, strict=True):
        if not name:
            raise ctx.error(f"{where(element)}: {key} is empty", line)
        if not legal_name(name):
            raise ctx.error(f"{where(element)}: {key}='{name}' is not a legal ROS name", line)
    return pair[0], pair[1]


def env_pair(element: Any, ctx: LaunchContext) -> tuple[str, str]:
    """``<env name value>``.

    Raises:
        LaunchError: A missing attribute or an empty name.
    """
    name, value = required(element, "name", ctx), required(element, "value", ctx)
    if not name:
        raise ctx.error(f"{where(element)}: name is empty", element.sourceline)
    return name, value


def node(element: Any, ctx: LaunchContext, plan: LaunchPlan) -> None:
    """``<node>`` or ``<test>`` into the plan (an enabled one; the caller checked if/unless).

    Raises:
        LaunchError: A missing or bad attribute, or a bad nested element.
    """
    test = element.tag == "test"
    line = element.sourceline
    here = where(element)
    extra: dict[str, Any] = {}
    if test:
        for forbidden in ("respawn", "respawn_delay", "output"):
            if element.get(forbidden) is not None:
                raise ctx.error(f"{here}: a <test> has no '{forbidden}'", line)
        name = attr(element, "name", ctx)
        extra = _test_attributes(element, ctx)
        name = name or extra["test_name"]
    else:
        name = attr(element, "name", ctx) or ""
        if not name:
            type_name = element.get("type") or ""
            name = Path(ctx.substitute(type_name, here, line)).stem  # roslaunch requires one
    if "/" in name:
        raise ctx.error(f"{here}: node name '{name}' has a '/'", line, hint="use ns= instead")
    if not legal_name(name):
        plan.warnings.append(f"{ctx.path}:{line}: node name '{name}' is not a legal ROS name")
    scope = scoped(element, ctx, plan, node_name=name)
    pkg, node_type = required(element, "pkg", ctx), required(element, "type", ctx)
    machine, args, output, respawn, delay, cwd, prefix, needed = (
        attr(element, key, ctx)
        for key in ("machine", "args", "output", "respawn", "respawn_delay", "cwd")
        + ("launch-prefix", "required")
    )
    machine = machine or ctx.shared.default_machine
    if not pkg.strip() or not node_type.strip():
        raise ctx.error(f"{here}: pkg and type must not be empty", line)
    if output not in (None, *OUTPUTS):
        raise ctx.error(f"{here}: output='{output}' is not log or screen", line)
    cwd = "ROS_HOME" if cwd == "ros_home" else cwd
    if cwd not in (None, *CWDS):
        raise ctx.error(f"{here}: cwd='{cwd}' is not ROS_HOME or node", line)
    respawning = to_bool(respawn, element, "respawn", ctx) if respawn is not None else False
    is_required = to_bool(needed, element, "required", ctx) if needed is not None else False
    if respawning and is_required:
        raise ctx.error(f"{here}: a node cannot be both respawn and required", line)
    if delay == "":
        raise ctx.error(f"{here}: respawn_delay is empty", line)
    own = scope.child(name, line)
    own.private = []
    remaps, env = dict(ctx.remaps), list(ctx.env)
    for child in elements(element):
        if not enabled(child, ctx if child.tag in ("remap", "env") else own):
            continue
        if child.tag == "remap":
            source, target = remap_pair(child, ctx)
            remaps.pop(source, None)
            remaps[source] = target
        elif child.tag == "param":
            param(child, own, plan, node=True)
        elif child.tag == "rosparam":
            rosparam(child, own, plan)
        elif child.tag == "env":
            env.append(env_pair(child, ctx))
        else:
            plan.warnings.append(
                f"{ctx.path}:{child.sourceline}: <{child.tag}> inside <{element.tag}> is ignored"
            )
    for key, value in [*ctx.private, *own.private]:
        plan.params[canonical_name(f"{own.namespace}/{key.removeprefix('~')}")] = value
    spec_type = TestSpec if test else NodeSpec
    spec = spec_type(
        pkg=pkg,
        type=node_type,
        name=name,
        namespace=scope.namespace,
        args=split_args(args or "", ctx, here, line),
        remaps=remaps,
        output=output or "log",
        respawn=respawning,
        respawn_delay=parse_delay(delay, ctx, here, line),
        required=is_required,
        source=f"{ctx.path}:{line}",
        env=dict(env),
        launch_prefix=prefix or None,
        cwd=cwd,
        machine=machine or None,
        **extra,
    )
    if isinstance(spec, TestSpec):
        plan.tests.append(spec)
    else:
        plan.nodes.append(spec)


def _test_attributes(element: Any, ctx: LaunchContext) -> dict[str, Any]:
    line = element.sourceline
    here = where(element)
    test_name = required(element, "test-name", ctx)
    limit = float_attr(element, "time-limit", ctx) if element.get("time-limit") else None
    if limit is not None and not limit > 0:
        raise ctx.error(f"{here}: time-limit must be a positive number", line)
    retry_text = attr(element, "retry", ctx)
    try:
        retry = int(retry_text) if retry_text else 0
    except ValueError:
        raise ctx.error(f"{here}: retry='{retry_text}' is not a whole number", line) from None
    return {"test_name": test_name, "time_limit": limit or 60.0, "retry": retry}
