"""Reading roslaunch XML attributes: substituted values, booleans and numbers as roslaunch
checks them, ``if``/``unless``, and ``ns``/``clear_params``."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from workbench.bus.launch_context import LaunchContext, LaunchPlan, canonical_name
from workbench.bus.launch_subst import convert_value


def where(element: Any) -> str:
    return f"<{element.tag}> line {element.sourceline}"


def attr(element: Any, name: str, ctx: LaunchContext, required: bool = False) -> str | None:
    """The attribute ``name`` with its substitutions resolved (None when absent).

    Raises:
        LaunchError: Absent though ``required``, or a substitution fails.
    """
    value = element.get(name)
    if value is None:
        if required:
            raise ctx.error(f"<{element.tag}> needs a '{name}' attribute", element.sourceline)
        return None
    return ctx.substitute(value, where(element), element.sourceline)


def required(element: Any, name: str, ctx: LaunchContext) -> str:
    value = attr(element, name, ctx, required=True)
    assert value is not None
    return value


def bool_attr(element: Any, name: str, ctx: LaunchContext, default: bool = False) -> bool:
    """``true``/``false`` (any case) as roslaunch reads ``respawn``, ``required`` ...

    Raises:
        LaunchError: Empty or anything else.
    """
    value = attr(element, name, ctx)
    return default if value is None else to_bool(value, element, name, ctx)


def to_bool(value: str, element: Any, name: str, ctx: LaunchContext) -> bool:
    """An attribute's resolved ``true``/``false`` (any case).

    Raises:
        LaunchError: Anything else.
    """
    if value.lower() in ("true", "false"):
        return value.lower() == "true"
    raise ctx.error(f"{where(element)}: {name}='{value}' is not true or false", element.sourceline)


def float_attr(element: Any, name: str, ctx: LaunchContext) -> float | None:
    """A number attribute (None when absent).

    Raises:
        LaunchError: Empty or not a number.
    """
    value = attr(element, name, ctx)
    if value is None:
        return None
    try:
        return float(value)
    except ValueError:
        raise ctx.error(
            f"{where(element)}: {name}='{value}' is not a number", element.sourceline
        ) from None


def enabled(element: Any, ctx: LaunchContext) -> bool:
    """Its ``if``/``unless`` (both substituted first, as roslaunch does).

    Raises:
        LaunchError: Both given, or a value that is not true/false/1/0.
    """
    cond_if, cond_unless = attr(element, "if", ctx), attr(element, "unless", ctx)
    if cond_if is not None and cond_unless is not None:
        raise ctx.error(f"{where(element)}: has both 'if' and 'unless'", element.sourceline)
    for name, value in (("if", cond_if), ("unless", cond_unless)):
        if value is None:
            continue
        try:
            truth = convert_value(value, "bool")
        except ValueError:
            raise ctx.error(
                f"{where(element)}: {name}='{value}' is not true, false, 1 or 0",
                element.sourceline,
            ) from None
        return truth if name == "if" else not truth
    return True


def elements(parent: Any) -> Iterator[Any]:
    """The child elements (no comments, entities or processing instructions)."""
    return (e for e in parent if isinstance(e.tag, str))


def text_of(element: Any) -> str:
    """The element's own text (between its children, as roslaunch joins it)."""
    parts = [element.text or ""]
    parts += [child.tail or "" for child in element]
    return "".join(parts)


def scoped(
    element: Any,
    ctx: LaunchContext,
    plan: LaunchPlan,
    node_name: str | None = None,
    include: bool = False,
) -> LaunchContext:
    """The scope of a ``<group>``, ``<node>`` or ``<include>``: its ``ns`` (relative or
    global), and its ``clear_params`` recorded in the plan.

    Raises:
        LaunchError: An empty ``ns``, or ``clear_params`` without ``ns`` (group, include).
    """
    line = element.sourceline
    ns = None
    if element.get("ns") is not None:
        ns = attr(element, "ns", ctx)
        if not ns:
            raise ctx.error(f"{where(element)}: ns is empty", line)
    inner = ctx.include_scope(ns, line) if include else ctx.child(ns, line)
    clear = attr(element, "clear_params", ctx)
    if clear and to_bool(clear, element, "clear_params", ctx):
        if node_name is not None:
            plan.clear_params.append(canonical_name(f"{inner.namespace}/{node_name}"))
        elif not ns:
            raise ctx.error(
                f"{where(element)}: clear_params needs an ns to clear", line, hint="add ns="
            )
        else:
            plan.clear_params.append(inner.namespace)
    return inner
