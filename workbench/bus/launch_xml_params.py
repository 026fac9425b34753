"""roslaunch's ``<param>`` and ``<rosparam>``: names, values and commands as roslaunch reads them.

``<param name value|textfile|binfile|command type>``: exactly one source; the value is
typed (``auto`` without ``type``; the ``type`` attribute itself is not substituted, as in
roslaunch), a ``textfile``'s contents and a ``command``'s output too. A ``~name`` outside
a ``<node>`` waits for the nodes that follow in its scope; inside a node every name is the
node's own (roslaunch puts even ``/name`` under the node).

``<rosparam command="load|dump|delete" file ns param subst_value>``: ``load`` sets a
YAML dictionary key by key (or any value at ``param``), ``subst_value`` resolves
substitutions in the YAML text first; ``dump`` and ``delete`` run before the parameters
are set, in file order.
"""

from __future__ import annotations

from typing import Any

from workbench.bus.launch_context import (
    Deferred,
    LaunchContext,
    LaunchPlan,
    canonical_name,
    ns_join,
    typed_value,
)
from workbench.bus.launch_plan import RosparamCommand
from workbench.bus.launch_values import (
    binfile_value,
    command_value,
    rosparam_data,
    rosparam_text,
    textfile_value,
)
from workbench.bus.launch_xml_attrs import attr, text_of, to_bool, where
from workbench.errors import WorkbenchError

SOURCES = ("value", "textfile", "binfile", "command")


def add_private(private: list[tuple[str, Any]], name: str, value: Any) -> None:
    """A ``~param`` waiting for nodes (a later one of the same name replaces it)."""
    key = canonical_name(name)
    private[:] = [(k, v) for k, v in private if k != key]
    private.append((key, value))


def param(element: Any, ctx: LaunchContext, plan: LaunchPlan, node: bool = False) -> None:
    """``<param>``: set in the plan, or kept for nodes (``~name``, or inside a ``<node>``).

    Raises:
        LaunchError: Not exactly one source, no name, or a value of the wrong type.
    """
    line = element.sourceline
    kind = (element.get("type") or "auto").lower().strip()
    values = {source: attr(element, source, ctx) for source in SOURCES}
    given = [source for source, value in values.items() if value is not None]
    if len(given) != 1:
        raise ctx.error(
            f"{where(element)}: needs exactly one of value=, textfile=, binfile=, command=",
            line,
        )
    raw = element.get("name")
    if raw is None:
        raise ctx.error(f"{where(element)}: needs a 'name' attribute", line)
    name = ctx.substitute(raw.strip(), where(element), line)
    value = _value(given[0], values[given[0]] or "", kind, element, ctx)
    if node or name.startswith("~"):
        add_private(ctx.private, name, value)
    else:
        plan.params[canonical_name(ns_join(ctx.namespace, name))] = value


def _value(source: str, text: str, kind: str, element: Any, ctx: LaunchContext) -> Any:
    line = element.sourceline
    here = where(element)
    if source == "binfile":
        return binfile_value(text, ctx, here, line)
    if source == "textfile":
        raw = textfile_value(text, ctx, here, line)
    elif source == "command":
        raw = command_value(text, ctx, here, line)
    else:
        raw = text.strip()
    if isinstance(raw, Deferred):
        return raw
    try:
        return typed_value(raw, kind, f"{here}: the YAML value", ctx.shared.evaluate)
    except ValueError as error:
        raise ctx.error(f"{here}: {error}", line) from None
    except WorkbenchError as error:
        raise ctx.error(error.message, line, error.hint) from None


def rosparam(element: Any, ctx: LaunchContext, plan: LaunchPlan) -> None:
    """``<rosparam>`` in the scope ``ctx`` (a node's own scope inside a ``<node>``).

    Raises:
        LaunchError: An unknown command, ``file=`` with delete, YAML that is invalid or
            not a dictionary without ``param=``, a non-dictionary at ``/``.
    """
    line = element.sourceline
    here = where(element)
    command, ns, file, target, subst = (
        attr(element, name, ctx) for name in ("command", "ns", "file", "param", "subst_value")
    )
    substitute = to_bool(subst, element, "subst_value", ctx) if subst is not None else False
    named = target is not None
    target = ns_join(ns or "", target or "")
    command = command or "load"
    if command not in ("load", "dump", "delete"):
        raise ctx.error(f"{here}: command='{command}' is not load, dump or delete", line)
    if file is not None and command == "delete":
        raise ctx.error(f"{here}: file= does not go with command='delete'", line)
    full = canonical_name(ns_join(ctx.namespace, target) if target else ctx.namespace)
    if command != "load":
        plan.rosparam_commands.append(RosparamCommand(command, full, file))
        return
    text: Any = text_of(element)
    if file is not None:
        text = rosparam_text(file, ctx, here, line)
        if isinstance(text, Deferred):
            if named:
                plan.params[full] = text
            else:
                plan.rosparam_files.append((full, file))
            return
    if substitute:
        text = ctx.substitute(text, here, line)
    data = rosparam_data(text, file, ctx, here, line)
    if data is None:
        data = {}
    if not target and not isinstance(data, dict):
        raise ctx.error(f"{here}: without param=, the YAML must be a dictionary", line)
    if full == "/" and not isinstance(data, dict):
        raise ctx.error(f"{here}: only a dictionary can be loaded into '/'", line)
    unrolled(plan, full, data)


def unrolled(plan: LaunchPlan, name: str, value: Any) -> None:
    """Set ``value`` leaf by leaf, as roslaunch's loader does (``add_param`` unrolls a dict):
    a file loaded into a namespace adds to what is there instead of replacing it (move_base's
    ``global_costmap:`` block after costmap_common_params.yaml loaded with ns="global_costmap")."""
    if isinstance(value, dict):
        for key, item in value.items():
            unrolled(plan, canonical_name(ns_join(name, str(key))), item)
    else:
        plan.params[name] = value
