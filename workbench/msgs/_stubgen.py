"""Write the ``.pyi`` stubs that give the message classes their types.

The classes of ``workbench.msgs.<package>`` are built at run time from the
type store, so an editor or a type checker cannot see their fields. This
module writes one stub per package module (``workbench/msgs/<package>.pyi``)
from the same field definitions, so ``Twist().linear.x`` completes and is a
``float``. What a field holds is what the class really returns:

- ``float64``/``float32`` -> ``float``, integer types -> ``int``, ``bool``,
  ``string`` -> ``str``;
- a nested message -> its class (``time``/``duration`` ->
  ``builtin_interfaces.Time``/``Duration``); assignment also takes a dict;
- a numeric array -> a numpy array of the wire dtype (assignment takes any
  array-like); an array of strings or of messages -> a ``list``;
- constants -> ``Final`` class attributes; a service ``Spawn`` -> the
  message classes ``SpawnRequest``/``SpawnResponse`` and ``Spawn.Request``/
  ``Spawn.Response``.

Regenerate after changing the registered types, and commit the result::

    python -m workbench.msgs._stubgen

``tests/msgs/test_stubs.py`` fails when the committed stubs differ from a fresh run.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from workbench.msgs._classes import Message, ServiceType
from workbench.msgs._fields import DTYPES, FLOATS, INT_RANGES, FieldSpec
from workbench.msgs._store import TypeStore, store

MSGS_DIR = Path(__file__).resolve().parent
_LINE_LENGTH = 100  # the project's formatter's; the stubs are written already formatted

_HEADER = '''"""Types of the {package} messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.
'''

_TIME_TYPES = {
    "builtin_interfaces/msg/Time": "time",
    "builtin_interfaces/msg/Duration": "duration",
}

_TIME_CLASS = '''
class Time(Message):
    """A point in time (ROS 1 ``time``): seconds and nanoseconds since the epoch."""

    sec: int
    nanosec: int
    secs: int
    nsecs: int
    def __init__(
        self,
        secs: float = ...,
        nsecs: int = ...,
        *,
        sec: int | None = ...,
        nanosec: int | None = ...,
    ) -> None: ...
    @classmethod
    def from_sec(cls, seconds: float) -> Self: ...
    @classmethod
    def from_nsec(cls, nanoseconds: int) -> Self: ...
    def to_sec(self) -> float: ...
    def to_nsec(self) -> int: ...
    def is_zero(self) -> bool: ...
    def __bool__(self) -> bool: ...
    def __lt__(self, other: Time) -> bool: ...
    def __le__(self, other: Time) -> bool: ...
    def __gt__(self, other: Time) -> bool: ...
    def __ge__(self, other: Time) -> bool: ...
    def __add__(self, other: Duration) -> Self: ...
    def __radd__(self, other: Duration) -> Self: ...
    @overload
    def __sub__(self, other: Time) -> Duration: ...
    @overload
    def __sub__(self, other: Duration) -> Self: ...
'''

_DURATION_CLASS = '''
class Duration(Message):
    """A signed span of time (ROS 1 ``duration``)."""

    sec: int
    nanosec: int
    secs: int
    nsecs: int
    def __init__(
        self,
        secs: float = ...,
        nsecs: int = ...,
        *,
        sec: int | None = ...,
        nanosec: int | None = ...,
    ) -> None: ...
    @classmethod
    def from_sec(cls, seconds: float) -> Self: ...
    @classmethod
    def from_nsec(cls, nanoseconds: int) -> Self: ...
    def to_sec(self) -> float: ...
    def to_nsec(self) -> int: ...
    def is_zero(self) -> bool: ...
    def __bool__(self) -> bool: ...
    def __lt__(self, other: Duration) -> bool: ...
    def __le__(self, other: Duration) -> bool: ...
    def __gt__(self, other: Duration) -> bool: ...
    def __ge__(self, other: Duration) -> bool: ...
    @overload
    def __add__(self, other: Duration) -> Self: ...
    @overload
    def __add__(self, other: Time) -> Time: ...
    def __sub__(self, other: Duration) -> Self: ...
    def __neg__(self) -> Self: ...
    def __abs__(self) -> Self: ...
    def __mul__(self, factor: float) -> Self: ...
    def __rmul__(self, factor: float) -> Self: ...
    @overload
    def __truediv__(self, other: Duration) -> float: ...
    @overload
    def __truediv__(self, other: float) -> Self: ...
'''


class StubError(Exception):
    """A type cannot be written as a stub (a field name hides a name the stub uses)."""


def package_modules() -> list[str]:
    """The packages with a module ``workbench/msgs/<package>.py``."""
    return sorted(p.stem for p in MSGS_DIR.glob("*.py") if not p.stem.startswith("_"))


def render_all(types: TypeStore | None = None) -> dict[str, str]:
    """Stub file name (``geometry_msgs.pyi``) -> its text, for every package module."""
    types = types or store()
    packages = package_modules()
    return {f"{package}.pyi": render_package(package, packages, types) for package in packages}


def render_package(package: str, packages: list[str], types: TypeStore) -> str:
    """The stub text of ``workbench.msgs.<package>``.

    Args:
        package: The ROS package (``geometry_msgs``).
        packages: Every package that has a module (other packages' types are ``Message``).
        types: The type store holding the classes.
    """
    classes = sorted(
        (cls for name, cls in types.classes.items() if name.split("/")[0] == package),
        key=lambda cls: cls.__name__,
    )
    services = sorted(
        (svc for name, svc in types.services.items() if name.split("/")[0] == package),
        key=lambda svc: svc.__name__,
    )
    writer = _PackageWriter(package, packages, types)
    writer.exported = sorted([cls.__name__ for cls in classes] + [svc.__name__ for svc in services])
    bodies = [writer.message(cls) for cls in classes]
    bodies += [writer.service(svc) for svc in services]
    return _HEADER.format(package=package) + writer.imports() + "".join(bodies)


class _PackageWriter:
    """Writes the classes of one package and collects the imports they need."""

    def __init__(self, package: str, packages: list[str], types: TypeStore) -> None:
        self.package = package
        self.types = types
        self.packages = packages
        self.typing: set[str] = set()
        self.modules: set[str] = set()
        self.uses_numpy = False
        self.uses_service = False
        self.exported: list[str] = []

    def imports(self) -> str:
        lines = ["\n"]
        collections = sorted({"Iterable", "Mapping"} & self.typing)
        if collections:
            lines.append(f"from collections.abc import {', '.join(collections)}\n")
        typing = sorted(self.typing - {"Iterable", "Mapping", "Self"})
        if typing:
            lines.append(f"from typing import {', '.join(typing)}\n")
        if self.uses_numpy:
            lines.append("\nimport numpy as np\nfrom numpy.typing import ArrayLike, NDArray\n")
        lines.append("\n")
        if "Self" in self.typing:
            lines.append("from typing_extensions import Self\n\n")
        # `geometry_msgs.msg.Twist` / `turtlesim.srv.Spawn`, as the lab's rospy scripts write them;
        # the import statements in the order the project's import sorter keeps them.
        names = [f"{self.package} as msg", f"{self.package} as srv"]
        if self.modules:
            names.append(", ".join(sorted(self.modules)))
        for imported in sorted(names):
            lines.append(f"from workbench.msgs import {imported}\n")
        bases = ["Message"] + (["ServiceType"] if self.uses_service else [])
        lines.append(f"from workbench.msgs._classes import {', '.join(bases)}\n")
        lines.append("\n__all__ = [\n")
        lines += [f'    "{name}",\n' for name in [*self.exported, "msg", "srv"]]
        lines.append("]\n")
        return "".join(lines)

    def message(self, cls: type[Message]) -> str:
        special = _TIME_TYPES.get(cls.__msgtype__)
        if special == "time":
            self.typing |= {"Self", "overload"}
            return _TIME_CLASS
        if special == "duration":
            self.typing |= {"Self", "overload"}
            return _DURATION_CLASS
        lines = ["\n", f"class {cls.__name__}(Message):\n", f'    """``{cls._type}``."""\n\n']
        constants, _fields = self.types.ts.fielddefs[cls.__msgtype__]
        for name, _ros_type, value in constants:
            self.typing.add("Final")
            lines.append(f"    {name}: Final = {value!r}\n")
        if constants:
            lines.append("\n")
        params = []
        for spec in cls._specs:
            self._check_name(cls, spec.name)
            getter, setter = self._field_types(spec)
            params.append(f"        {spec.name}: {setter} = ...,\n")
            if getter == setter:
                lines.append(f"    {spec.name}: {getter}\n")
            else:
                lines.append(f"    @property\n    def {spec.name}(self) -> {getter}: ...\n")
                lines.append(f"    @{spec.name}.setter\n")
                lines.append(_def_line(spec.name, f"self, value: {setter}", "None"))
        if params:
            lines.append("    def __init__(\n        self,\n")
            lines += params
            lines.append("    ) -> None: ...\n")
        else:
            lines.append("    def __init__(self) -> None: ...\n")
        return "".join(lines)

    def service(self, service: type[ServiceType]) -> str:
        self.uses_service = True
        self.typing.add("ClassVar")
        request, response = service.Request.__name__, service.Response.__name__
        return (
            f"\nclass {service.__name__}(ServiceType):\n"
            f'    """``{service._type}``: ``{service.__name__}.Request(...)``, '
            f'``{service.__name__}.Response(...)``."""\n\n'
            f"    Request: ClassVar[type[{request}]]\n"
            f"    Response: ClassVar[type[{response}]]\n"
        )

    def _field_types(self, spec: FieldSpec) -> tuple[str, str]:
        """The getter and setter types of one field."""
        if spec.elem_is_msg:
            element = self._class_ref(spec.elem)
            self.typing |= {"Any", "Mapping"}
            accepted = f"{element} | Mapping[str, Any]"
            if spec.kind == "msg":
                return element, accepted
            self.typing.add("Iterable")
            return f"list[{element}]", f"Iterable[{accepted}]"
        python = _python_type(spec.elem)
        if spec.kind == "base":
            return python, python
        if spec.elem == "string":
            self.typing.add("Iterable")
            return "list[str]", "Iterable[str]"
        self.uses_numpy = True
        return f"NDArray[np.{DTYPES[spec.elem].__name__}]", "ArrayLike"

    def _class_ref(self, store_name: str) -> str:
        package, _, name = store_name.split("/")
        if package == self.package:
            return name
        if package in self.packages:
            self.modules.add(package)
            return f"{package}.{name}"
        return "Message"

    def _check_name(self, cls: type[Message], field: str) -> None:
        hidden = {"float", "int", "bool", "str", "list", "np", "Any", "Mapping", "Iterable"}
        hidden |= {"NDArray", "ArrayLike", "Final", "ClassVar", "Message", "ServiceType"}
        if field in hidden or field in self.packages:
            raise StubError(f"field '{field}' of {cls._type} hides a name the stub uses")


def _def_line(name: str, params: str, returns: str) -> str:
    """A stub method on one line, or wrapped as the formatter wraps it when too long."""
    line = f"    def {name}({params}) -> {returns}: ...\n"
    if len(line) - 1 <= _LINE_LENGTH:
        return line
    return f"    def {name}(\n        {params}\n    ) -> {returns}: ...\n"


def _python_type(prim: str) -> str:
    if prim == "string":
        return "str"
    if prim == "bool":
        return "bool"
    if prim in FLOATS:
        return "float"
    if prim in INT_RANGES:
        return "int"
    raise StubError(f"no Python type for the primitive '{prim}'")


def write_stubs(directory: Path = MSGS_DIR) -> list[Path]:
    """Write every stub into ``directory``; returns the files written."""
    written = []
    for name, text in render_all().items():
        path = directory / name
        path.write_text(text, encoding="utf-8")
        written.append(path)
    return written


def main(argv: list[str] | None = None) -> int:
    """``python -m workbench.msgs._stubgen [--check]``."""
    parser = argparse.ArgumentParser(prog="python -m workbench.msgs._stubgen", description=__doc__)
    parser.add_argument(
        "--check", action="store_true", help="exit 1 if a committed stub differs, write nothing"
    )
    options = parser.parse_args(argv)
    if options.check:
        stale = [
            name
            for name, text in render_all().items()
            if not (MSGS_DIR / name).is_file()
            or (MSGS_DIR / name).read_text(encoding="utf-8") != text
        ]
        for name in stale:
            print(f"stale: workbench/msgs/{name}", file=sys.stderr)
        return 1 if stale else 0
    for path in write_stubs():
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
