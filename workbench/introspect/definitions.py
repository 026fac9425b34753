"""``rosmsg show`` / ``rossrv show`` text: fields with nested types expanded and indented."""

from __future__ import annotations

from workbench.errors import MessageError

_PRIMITIVES = {
    "bool", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64",
    "float32", "float64", "string", "time", "duration", "byte", "char",
}  # fmt: skip


def _sections(full: str, typename: str) -> dict[str, list[str]]:
    """Split a full definition (main text + ``MSG: pkg/Type`` parts) into type -> lines."""
    sections: dict[str, list[str]] = {typename: []}
    current = typename
    for line in full.splitlines():
        if line.startswith("=" * 10):
            continue
        if line.startswith("MSG: "):
            current = line[5:].strip()
            sections[current] = []
            continue
        text = line.split("#", 1)[0].strip() if "=" not in line else line.strip()
        if text:
            sections[current].append(text)
    return sections


def _resolve(base: str, package: str, sections: dict[str, list[str]]) -> str | None:
    if base in _PRIMITIVES:
        return None
    if base == "Header":
        return "std_msgs/Header"
    if "/" not in base:
        base = f"{package}/{base}"
    return base if base in sections else None


def _expand(typename: str, sections: dict[str, list[str]], indent: int) -> list[str]:
    package = typename.split("/")[0]
    out = []
    for line in sections.get(typename, []):
        out.append("  " * indent + line)
        if "=" in line:  # a constant
            continue
        field_type = line.split()[0]
        base = field_type.split("[")[0]
        nested = _resolve(base, package, sections)
        if nested is not None:
            out += _expand(nested, sections, indent + 1)
    return out


def show_message(typename: str) -> str:
    """``rosmsg show TYPE``.

    Raises:
        MessageError: unknown type (with close names).
    """
    from workbench.msgs import definition, get_type

    name = get_type(typename)._type
    return "\n".join(_expand(name, _sections(definition(name), name), 0))


def show_service(typename: str) -> str:
    """``rossrv show TYPE``: request fields, ``---``, response fields."""
    from workbench.msgs import get_service

    service = get_service(typename)
    parts = [show_message(service.Request._type), "---", show_message(service.Response._type)]
    return "\n".join(p for p in parts if p)


def show_any(typename: str) -> str:
    """A message's or a service's definition, whichever ``typename`` is."""
    try:
        return show_message(typename)
    except MessageError:
        return show_service(typename)
