"""What the launch-file readers share: the plan they fill, the reading context, substitutions.

A :class:`LaunchPlan` collects parameters and nodes; a :class:`LaunchContext`
carries what one file sees (its path, ``<arg>`` values, namespace, remappings)
and what the whole launch shares (the include chain, the bounds, whether this
is a dry run, how a ``command=`` runs). Every value taken from a file is
checked here: numbers are numbers, quotes are closed, substitutions stay
within :data:`MAX_VALUE_CHARS`.
"""

from __future__ import annotations

import math
import os
import re
import shlex
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.bus.names import anonymous_name, join
from workbench.errors import BusError

#: Longest value after substitution (an ``<arg>`` defined twice over another doubles), chars.
MAX_VALUE_CHARS = 1024 * 1024
#: Deepest chain of ``<include>`` (a file including a file ...).
MAX_INCLUDE_DEPTH = 32
#: Most files one launch reads (a file may include the same file many times over).
MAX_INCLUDES = 256


class LaunchError(BusError):
    """A launch file cannot be read or names something that does not exist."""


@dataclass
class NodeSpec:
    """One node to start."""

    pkg: str
    type: str
    name: str
    namespace: str = "/"
    args: list[str] = field(default_factory=list)
    remaps: dict[str, str] = field(default_factory=dict)
    output: str = "log"
    respawn: bool = False
    respawn_delay: float = 0.0
    required: bool = False
    source: str = ""

    @property
    def full_name(self) -> str:
        return join(self.namespace, self.name)


@dataclass(frozen=True)
class Deferred:
    """A value a dry run does not compute: a command's output or a file's contents."""

    kind: str  # "output of command", "contents of file"
    source: str

    def __repr__(self) -> str:
        return f"<{self.kind} {self.source!r}, not read in a dry run>"


@dataclass
class LaunchPlan:
    """Parameters to set, then nodes to start.

    Attributes:
        params: Global name -> value (a :class:`Deferred` in a dry run for ``command=``
            and ``textfile=``).
        nodes: In file order.
        deletes: Parameters ``<rosparam command="delete">`` removes.
        rosparam_files: ``(namespace, file)`` of each ``<rosparam file=...>`` a dry run
            did not read.
    """

    params: dict[str, Any] = field(default_factory=dict)
    nodes: list[NodeSpec] = field(default_factory=list)
    deletes: list[str] = field(default_factory=list)
    rosparam_files: list[tuple[str, str]] = field(default_factory=list)


#: ``run(command, launch_file) -> output``: how a ``<param command=...>`` runs.
CommandRunner = Callable[[str, Path], str]
#: ``load(file, context, plan, args)``: reads an included file of either form.
FileLoader = Callable[[Path, "LaunchContext", LaunchPlan, dict[str, str]], None]


@dataclass
class LaunchShared:
    """What every file of one launch shares."""

    dry_run: bool
    run_command: CommandRunner
    load_file: FileLoader
    files_read: int = 0


def find_package(name: str, near: Path | None = None) -> Path:
    """The folder of package ``name``, looked up as :mod:`workbench.ros_packages` does:
    ``WORKBENCH_PACKAGE_PATH`` and ``ROS_PACKAGE_PATH`` first, then the workspace around
    ``near`` (a launch file's folder) and the working directory, then workbench's own.

    Raises:
        LaunchError: Not found.
    """
    from workbench.ros_packages import PackageLookupError
    from workbench.ros_packages import find_package as lookup

    try:
        return lookup(name, near)
    except PackageLookupError as error:
        raise LaunchError(error.message, hint=error.hint) from None


_SUBST = re.compile(r"\$\((\w+)(?:\s+([^)]*))?\)")


class LaunchContext:
    """What one file sees while it is read."""

    def __init__(
        self,
        path: Path,
        args: dict[str, str],
        shared: LaunchShared,
        namespace: str = "/",
        chain: tuple[Path, ...] = (),
    ) -> None:
        self.path = path
        self.args = dict(args)
        self.namespace = namespace
        self.remaps: dict[str, str] = {}
        self.anon: dict[str, str] = {}
        self.shared = shared
        self.chain = chain  # the files that include this one, outermost first

    def child(self, namespace: str | None = None) -> LaunchContext:
        ctx = LaunchContext(self.path, self.args, self.shared, self.namespace, self.chain)
        ctx.remaps = dict(self.remaps)
        ctx.anon = self.anon
        if namespace:
            ctx.namespace = (
                namespace if namespace.startswith("/") else join(self.namespace, namespace)
            )
        return ctx

    def error(self, message: str, line: int | None = None, hint: str | None = None) -> LaunchError:
        return LaunchError(message, path=self.path, line=line, hint=hint)

    def resolve_file(self, name: str) -> Path:
        """A file named in this launch file: absolute, or relative to the file's folder."""
        target = Path(name)
        return target if target.is_absolute() else self.path.parent / target

    def include(
        self, file: str, plan: LaunchPlan, args: dict[str, str], ns: str | None, line: int | None
    ) -> None:
        """Read the launch file ``file`` into ``plan``, refusing cycles and runaway includes.

        Raises:
            LaunchError: Missing file, a file that includes itself (directly or through
                others), includes deeper than :data:`MAX_INCLUDE_DEPTH` or more files than
                :data:`MAX_INCLUDES`.
        """
        target = self.resolve_file(file)
        if not target.is_file():
            raise self.error(f"<include> file {file} does not exist", line)
        resolved = target.resolve()
        chain = (*self.chain, self.path)
        if resolved in chain:
            cycle = [p.name for p in chain[chain.index(resolved) :]] + [resolved.name]
            what = "includes itself" if len(cycle) == 2 else "is part of an include cycle"
            raise self.error(
                f"{resolved.name} {what} ({' -> '.join(cycle)})",
                line,
                hint="remove the <include> that closes the loop",
            )
        if len(chain) >= MAX_INCLUDE_DEPTH:
            raise self.error(f"includes nest more than {MAX_INCLUDE_DEPTH} files deep", line)
        self.shared.files_read += 1
        if self.shared.files_read > MAX_INCLUDES:
            raise self.error(
                f"the launch reads more than {MAX_INCLUDES} files (includes of includes)", line
            )
        inner = LaunchContext(resolved, {}, self.shared, self.child(ns).namespace, chain)
        inner.remaps = dict(self.remaps)
        self.shared.load_file(resolved, inner, plan, args)

    # --- substitutions and values -----------------------------------------------------------

    def substitute(self, text: str, where: str, line: int | None = None) -> str:
        """``text`` with ``$(arg)``, ``$(find)``, ``$(env)``, ``$(optenv)``, ``$(anon)``,
        ``$(dirname)`` replaced.

        Raises:
            LaunchError: An undefined arg or variable, an unknown substitution, or a
                result longer than :data:`MAX_VALUE_CHARS`.
        """

        def repl(match: re.Match[str]) -> str:
            command, rest = match.group(1), (match.group(2) or "").strip()
            if command == "arg":
                if rest not in self.args:
                    raise self.error(f"{where}: $(arg {rest}) is not defined", line)
                return str(self.args[rest])
            if command == "find":
                try:
                    return str(find_package(rest, self.path.parent))
                except LaunchError as error:
                    message = f"{where}: $(find {rest}): {error.message}"
                    raise self.error(message, line, error.hint) from None
            if command == "env":
                if rest not in os.environ:
                    raise self.error(f"{where}: environment variable {rest} is not set", line)
                return os.environ[rest]
            if command == "optenv":
                key, _, default = rest.partition(" ")
                return os.environ.get(key, default)
            if command == "anon":
                return self.anon.setdefault(rest, anonymous_name(rest))
            if command == "dirname":
                return str(self.path.parent)
            raise self.error(f"{where}: unsupported substitution $({command} ...)", line)

        result = _SUBST.sub(repl, text)
        if len(result) > MAX_VALUE_CHARS:
            raise self.error(
                f"{where}: the value is {len(result):,} characters long after substitution, "
                f"more than {MAX_VALUE_CHARS:,}",
                line,
                hint="are <arg>s defined in terms of each other over and over?",
            )
        return result


def parse_bool(value: str | bool | None, default: bool = False) -> bool:
    if value is None:
        return default
    if isinstance(value, bool):
        return value
    return str(value).strip().lower() in ("true", "1", "yes")


def parse_delay(value: Any, ctx: LaunchContext, where: str, line: int | None = None) -> float:
    """``respawn_delay``: a finite, non-negative number of seconds.

    Raises:
        LaunchError: Anything else (``"abc"``, ``-1``, ``nan``, a list).
    """
    if value is None or value == "":
        return 0.0
    try:
        if isinstance(value, bool) or not isinstance(value, (int, float, str)):
            raise ValueError
        seconds = float(value)
    except ValueError:
        raise ctx.error(
            f"{where}: respawn_delay {value!r} is not a number of seconds", line
        ) from None
    if not (math.isfinite(seconds) and seconds >= 0):
        raise ctx.error(f"{where}: respawn_delay {value!r} must be 0 or more seconds", line)
    return seconds


def split_args(text: str, ctx: LaunchContext, where: str, line: int | None = None) -> list[str]:
    """A node's ``args`` split as a shell would (quotes group words).

    Raises:
        LaunchError: An unterminated quote or escape.
    """
    try:
        return shlex.split(text)
    except ValueError as error:
        raise ctx.error(
            f"{where}: args {text[:60]!r} cannot be split into words ({error})",
            line,
            hint="close the quote, or escape it",
        ) from None


def param_name(name: str, namespace: str) -> str:
    name = name.removeprefix("~")  # inside <node>, the namespace is already the node's
    return name if name.startswith("/") else join(namespace, name)


def typed_value(value: str, type_name: str | None, what: str = "value") -> Any:
    """A ``<param>`` value converted as roslaunch does (auto-typed without ``type``).

    Raises:
        ValueError: Not of the type asked for.
        BusError: ``type="yaml"`` that is not YAML within bounds.
    """
    from workbench.limits import load_yaml

    if type_name in ("str", "string"):
        return value
    if type_name == "int":
        return int(value)
    if type_name == "double":
        return float(value)
    if type_name in ("bool", "boolean"):
        return value.strip().lower() == "true"
    if type_name == "yaml":
        return load_yaml(value, what, error=LaunchError)
    stripped = value.strip()
    if stripped.lower() in ("true", "false"):
        return stripped.lower() == "true"
    for convert in (int, float):
        try:
            return convert(stripped)
        except ValueError:
            pass
    return value
