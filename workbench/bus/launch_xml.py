"""roslaunch's XML, read as ROS 1's roslaunch reads it.

``<launch>`` holds ``<arg>``, ``<param>``, ``<rosparam>``, ``<node>``, ``<test>``,
``<remap>``, ``<env>``, ``<machine>``, ``<include>`` and ``<group>``, each with
``if``/``unless``. Scoping follows roslaunch (:class:`LaunchContext`): a group's
arguments, remappings and ``<env>`` end with it; an included file sees only the
arguments passed to it (all of the includer's with ``pass_all_args``), and an argument
passed that it does not declare is an error. Elements roslaunch does not know are
skipped with a warning, as roslaunch skips them.

The file is read within bounds and parsed without resolving entities, DTDs or
anything on the network (an XML entity bomb or ``SYSTEM "file:///etc/passwd"``
stays unexpanded text).
"""

from __future__ import annotations

import re
import socket
from pathlib import Path
from typing import Any

from workbench.bus.launch_context import LaunchArg, LaunchContext, LaunchError, LaunchPlan
from workbench.bus.launch_xml_attrs import (
    attr,
    bool_attr,
    elements,
    enabled,
    required,
    scoped,
    where,
)
from workbench.bus.launch_xml_nodes import env_pair, node, remap_pair
from workbench.bus.launch_xml_params import param, rosparam
from workbench.limits import MAX_TEXT_FILE_BYTES, read_bytes_bounded

_LOCATION = re.compile(r", line \d+, column \d+$")
#: Machine addresses that are this computer (``<machine>`` elsewhere is refused).
LOCAL_ADDRESSES = ("localhost", "127.0.0.1", "::1")


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


def load_xml(file: Path, ctx: LaunchContext, plan: LaunchPlan) -> None:
    """Read the XML launch file ``file`` into ``plan`` (its arguments are ``ctx.args``)."""
    root = _parse(file)
    if root.tag != "launch":
        raise ctx.error(f"the root element is <{root.tag}>, not <launch>", root.sourceline)
    deprecated = root.get("deprecated")
    if deprecated:
        plan.warnings.append(f"{file}: deprecated: {deprecated}")
    _children(root, ctx, plan)


def _children(parent: Any, ctx: LaunchContext, plan: LaunchPlan) -> None:
    for element in elements(parent):
        if not enabled(element, ctx):  # lazily: if= may use an <arg> just declared
            continue
        tag = element.tag
        if tag == "arg":
            _arg(element, ctx, ctx, plan)
        elif tag == "param":
            param(element, ctx, plan)
        elif tag == "rosparam":
            rosparam(element, ctx, plan)
        elif tag == "remap":
            source, target = remap_pair(element, ctx)
            ctx.remaps.pop(source, None)
            ctx.remaps[source] = target
        elif tag == "env":
            ctx.env.append(env_pair(element, ctx))
        elif tag in ("node", "test"):
            node(element, ctx, plan)
        elif tag == "group":
            inner = scoped(element, ctx, plan)
            inner.private = list(inner.private)  # ~params set in a group end with it
            _children(element, inner, plan)
        elif tag == "include":
            _include(element, ctx, plan)
        elif tag == "machine":
            _machine(element, ctx, plan)
        elif tag == "master":
            plan.warnings.append(f"{ctx.path}:{element.sourceline}: <master> is ignored")
        else:
            plan.warnings.append(
                f"{ctx.path}:{element.sourceline}: unknown element <{tag}> is ignored"
            )


def _arg(element: Any, reader: LaunchContext, target: LaunchContext, plan: LaunchPlan) -> None:
    """``<arg>`` read in ``reader``'s scope and declared in ``target``'s (they differ for
    the ``<arg>`` of an ``<include>``)."""
    name = required(element, "name", reader)
    value, default, doc = (attr(element, key, reader) for key in ("value", "default", "doc"))
    target.declare_arg(name, value, default, element.sourceline)
    if target is reader and reader.path == reader.shared.top_file and reader.chain == ():
        plan.args.append(LaunchArg(name, doc, default, value is not None))


def _include(element: Any, ctx: LaunchContext, plan: LaunchPlan) -> None:
    line = element.sourceline
    file = required(element, "file", ctx)
    pass_all = bool_attr(element, "pass_all_args", ctx)
    inner = scoped(element, ctx, plan, include=True)
    if pass_all:
        inner.args = dict(ctx.args)
        inner.declared = list(ctx.args)
        inner.pass_all_args = True
    reader = ctx.child()  # the includer's values (roslaunch reads them from a copy)
    reader.env = inner.env  # an <env> in the <include> is for the included file
    for child in elements(element):
        if not enabled(child, reader):
            continue
        if child.tag == "arg":
            _arg(child, reader, inner, plan)
        elif child.tag == "env":
            inner.env.append(env_pair(child, reader))
        else:
            plan.warnings.append(
                f"{ctx.path}:{child.sourceline}: <{child.tag}> inside <include> is ignored"
            )
    unset = [name for name in inner.declared if name not in inner.args]
    if unset:
        raise ctx.error(
            f"{where(element)}: <arg name='{unset[0]}'> passed to {file} has no value",
            line,
            hint="give it value= (or default=)",
        )
    passed = list(inner.args)
    inner.declared = []
    ctx.read_include(file, plan, inner, line)
    unused = [name for name in passed if name not in inner.declared]
    if unused and not pass_all:
        raise ctx.error(
            f"{where(element)}: {file} does not declare the argument '{unused[0]}' passed to it",
            line,
            hint=f"declare <arg name='{unused[0]}'/> there, or stop passing it",
        )


def _machine(element: Any, ctx: LaunchContext, plan: LaunchPlan) -> None:
    """``<machine>``: accepted when it is this computer, refused otherwise."""
    line = element.sourceline
    for old in ("ros-root", "ros-package-path", "ros-ip", "ros-hostname"):
        if element.get(old) is not None:
            raise ctx.error(
                f"{where(element)}: {old} is not supported since ROS Fuerte",
                line,
                hint="use env-loader",
            )
    name, address = required(element, "name", ctx), required(element, "address", ctx)
    default = (attr(element, "default", ctx) or "false").lower()
    if default not in ("true", "false", "never"):
        raise ctx.error(f"{where(element)}: default='{default}' is not true, false or never", line)
    if address not in (*LOCAL_ADDRESSES, socket.gethostname()):
        raise ctx.error(
            f"<machine name='{name}' address='{address}'>: workbench runs every node on this "
            "computer",
            line,
            hint='use address="localhost", or start the remote nodes there with '
            "'workbench launch'",
        )
    plan.machines[name] = address
    if default == "true":
        ctx.shared.default_machine = name
