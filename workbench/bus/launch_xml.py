"""roslaunch's XML: ``<launch>`` with ``arg``, ``param``, ``rosparam``, ``node``, ``remap``,
``include``, ``group`` and ``if``/``unless`` on any element.

The file is read within bounds and parsed without resolving entities, DTDs or
anything on the network (an XML entity bomb or ``SYSTEM "file:///etc/passwd"``
stays unexpanded text).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
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
    typed_value,
)
from workbench.bus.launch_values import command_value, rosparam_data, textfile_value
from workbench.errors import WorkbenchError
from workbench.limits import MAX_TEXT_FILE_BYTES, read_bytes_bounded

_LOCATION = re.compile(r", line \d+, column \d+$")


def _parse(file: Path) -> Any:
    from lxml import etree

    data = read_bytes_bounded(file, "launch file", MAX_TEXT_FILE_BYTES, LaunchError)
    parser = etree.XMLParser(
        resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False
    )
    try:
        return etree.fromstring(data, parser)
    except etree.XMLSyntaxError as error:
        message = _LOCATION.sub("", " ".join((error.msg or str(error)).split()))
        if "amplification" in message:  # libxml2's guard against entity bombs
            message = "its entities expand to too much text (an XML entity bomb?)"
        raise LaunchError(
            f"cannot parse launch file: {message}", path=file, line=error.lineno or None
        ) from None


def load_xml(file: Path, ctx: LaunchContext, plan: LaunchPlan, given: dict[str, str]) -> None:
    """Read the XML launch file ``file`` into ``plan``; ``given`` are its ``<arg>`` values."""
    root = _parse(file)
    if root.tag != "launch":
        raise ctx.error(f"the root element is <{root.tag}>, not <launch>", root.sourceline)
    _children(root, ctx, plan, given)
    unknown = sorted(set(given) - set(ctx.args))
    if unknown:
        raise ctx.error(f"argument '{unknown[0]}' is not declared in the launch file")


def _attr(element: Any, name: str, ctx: LaunchContext, required: bool = False) -> str | None:
    value = element.get(name)
    if value is None:
        if required:
            raise ctx.error(f"<{element.tag}> needs a '{name}' attribute", element.sourceline)
        return None
    return ctx.substitute(value, f"<{element.tag}> line {element.sourceline}", element.sourceline)


def _required(element: Any, name: str, ctx: LaunchContext) -> str:
    value = _attr(element, name, ctx, required=True)
    assert value is not None
    return value


def _enabled(element: Any, ctx: LaunchContext) -> bool:
    cond_if, cond_unless = _attr(element, "if", ctx), _attr(element, "unless", ctx)
    if cond_if is not None and not parse_bool(cond_if):
        return False
    return not (cond_unless is not None and parse_bool(cond_unless))


def _elements(parent: Any, ctx: LaunchContext) -> Iterator[Any]:
    """The enabled child elements (no comments, entities or processing instructions).

    Lazily: an element's ``if=`` may use an ``<arg>`` defined just before it.
    """
    return (e for e in parent if isinstance(e.tag, str) and _enabled(e, ctx))


def _children(parent: Any, ctx: LaunchContext, plan: LaunchPlan, given: dict[str, str]) -> None:
    for element in _elements(parent, ctx):
        tag = element.tag
        if tag == "arg":
            _arg(element, ctx, given)
        elif tag == "param":
            name = _required(element, "name", ctx)
            plan.params[param_name(name, ctx.namespace)] = _param_value(element, ctx)
        elif tag == "rosparam":
            _rosparam(element, ctx, plan, ctx.namespace)
        elif tag == "remap":
            ctx.remaps[_required(element, "from", ctx)] = _required(element, "to", ctx)
        elif tag == "node":
            plan.nodes.append(_node(element, ctx, plan))
        elif tag == "group":
            _children(element, ctx.child(_attr(element, "ns", ctx)), plan, given)
        elif tag == "include":
            _include(element, ctx, plan)
        elif tag in ("machine", "env", "test"):
            continue
        else:
            raise ctx.error(f"unsupported launch element <{tag}>", element.sourceline)


def _arg(element: Any, ctx: LaunchContext, given: dict[str, str]) -> None:
    name = _required(element, "name", ctx)
    value, default = _attr(element, "value", ctx), _attr(element, "default", ctx)
    if value is not None:
        ctx.args[name] = value
    elif name in given:
        ctx.args[name] = given[name]
    elif default is not None:
        ctx.args[name] = default
    else:
        raise ctx.error(
            f"argument '{name}' has no value",
            element.sourceline,
            hint=f"pass {name}:=VALUE on the command line",
        )


def _param_value(element: Any, ctx: LaunchContext) -> Any:
    line = element.sourceline
    where = f"<param> line {line}"
    value, textfile = _attr(element, "value", ctx), _attr(element, "textfile", ctx)
    command = _attr(element, "command", ctx)
    if value is not None:
        try:
            return typed_value(value, _attr(element, "type", ctx), f"{where}: the YAML value")
        except ValueError as error:
            raise ctx.error(f"{where}: {error}", line) from None
        except WorkbenchError as error:
            raise ctx.error(error.message, line, error.hint) from None
    if textfile is not None:
        return textfile_value(textfile, ctx, where, line)
    if command is not None:
        return command_value(command, ctx, where, line)
    raise ctx.error(f"{where}: needs value=, textfile= or command=", line)


def _rosparam(element: Any, ctx: LaunchContext, plan: LaunchPlan, namespace: str) -> None:
    line = element.sourceline
    where = f"<rosparam> line {line}"
    command = _attr(element, "command", ctx) or "load"
    ns = _attr(element, "ns", ctx)
    base = param_name(ns, namespace) if ns else namespace
    if command == "delete":
        plan.deletes.append(param_name(_required(element, "param", ctx), base))
        return
    if command == "dump":
        return
    if command != "load":
        raise ctx.error(
            f"<rosparam command='{command}'> is not supported (load, delete, dump)", line
        )
    file = _attr(element, "file", ctx)
    inline = "" if file is not None else ctx.substitute(element.text or "", where, line)
    data = rosparam_data(file, inline, ctx, where, line)
    target = _attr(element, "param", ctx)
    if target is not None:
        _unrolled(plan, param_name(target, base), data)
    elif file is not None and ctx.shared.dry_run:
        plan.rosparam_files.append((base, file))
    elif isinstance(data, dict):
        _unrolled(plan, base, data)
    elif data is not None:
        raise ctx.error("<rosparam> without param= needs a YAML dictionary", line)


def _unrolled(plan: LaunchPlan, name: str, value: Any) -> None:
    """Set ``value`` leaf by leaf, as roslaunch's loader does (``add_param`` unrolls a dict):
    a file loaded into a namespace adds to what is there instead of replacing it (move_base's
    ``global_costmap:`` block after costmap_common_params.yaml loaded with ns="global_costmap")."""
    if isinstance(value, dict):
        for key, item in value.items():
            _unrolled(plan, param_name(str(key), name), item)
    else:
        plan.params[name] = value


def _node(element: Any, ctx: LaunchContext, plan: LaunchPlan) -> NodeSpec:
    line = element.sourceline
    where = f"<node> line {line}"
    pkg = _required(element, "pkg", ctx)
    node_type = _required(element, "type", ctx)
    name = _attr(element, "name", ctx) or Path(node_type).stem
    ns = _attr(element, "ns", ctx)
    spec = NodeSpec(
        pkg=pkg,
        type=node_type,
        name=name,
        namespace=ctx.child(ns).namespace if ns else ctx.namespace,
        args=split_args(_attr(element, "args", ctx) or "", ctx, where, line),
        remaps=dict(ctx.remaps),
        output=_attr(element, "output", ctx) or "log",
        respawn=parse_bool(_attr(element, "respawn", ctx)),
        respawn_delay=parse_delay(_attr(element, "respawn_delay", ctx), ctx, where, line),
        required=parse_bool(_attr(element, "required", ctx)),
        source=f"{ctx.path}:{line}",
    )
    private = spec.full_name
    for child in _elements(element, ctx):
        if child.tag == "param":
            name = _required(child, "name", ctx)
            plan.params[param_name(name, private)] = _param_value(child, ctx)
        elif child.tag == "rosparam":
            _rosparam(child, ctx, plan, private)
        elif child.tag == "remap":
            spec.remaps[_required(child, "from", ctx)] = _required(child, "to", ctx)
        elif child.tag != "env":
            raise ctx.error(f"unsupported element <{child.tag}> inside <node>", child.sourceline)
    return spec


def _include(element: Any, ctx: LaunchContext, plan: LaunchPlan) -> None:
    file = _required(element, "file", ctx)
    args = {
        _required(child, "name", ctx): _required(child, "value", ctx)
        for child in _elements(element, ctx)
        if child.tag == "arg"
    }
    ctx.include(file, plan, args, _attr(element, "ns", ctx), element.sourceline)
