"""What the launch-file readers share: the reading context, its scopes, and checked values.

A :class:`LaunchContext` carries what one part of a file sees, scoped as roslaunch
scopes it (its ``LoaderContext``): the file's path, ``<arg>`` values and declarations,
namespace, remappings, ``<env>`` settings, private ``~params`` waiting for the next
``<node>``, and ``$(anon)`` names. A ``<group>`` or ``<node>`` works on a copy (what it
adds does not leak out); an ``<include>`` starts with only the arguments passed to it.
What the whole launch shares (the include chain, the bounds, whether this is a dry run,
how a ``command=`` runs, the expression sandbox) is a :class:`LaunchShared`. Every
value taken from a file is checked here: numbers are numbers, quotes are closed,
substitutions stay within :data:`MAX_VALUE_CHARS`.
"""

from __future__ import annotations

import math
import re
import shlex
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.bus.launch_plan import Deferred, LaunchArg, LaunchPlan, NodeSpec, TestSpec
from workbench.bus.launch_subst import (
    ExpressionEvaluator,
    Scope,
    SubstitutionError,
    convert_value,
    resolve,
)
from workbench.errors import BusError

__all__ = ["Deferred", "LaunchArg", "LaunchPlan", "NodeSpec", "TestSpec"]

#: Longest value after substitution (an ``<arg>`` defined twice over another doubles), chars.
MAX_VALUE_CHARS = 1024 * 1024
#: Deepest chain of ``<include>`` (a file including a file ...).
MAX_INCLUDE_DEPTH = 32
#: Most files one launch reads (a file may include the same file many times over).
MAX_INCLUDES = 256


class LaunchError(BusError):
    """A launch file cannot be read or names something that does not exist."""


#: ``run(command, launch_file) -> output``: how a ``<param command=...>`` runs.
CommandRunner = Callable[[str, Path], str]
#: ``load(file, context, plan)``: reads a file of either form (its arguments are in the
#: context).
FileLoader = Callable[[Path, "LaunchContext", LaunchPlan], None]


@dataclass
class LaunchShared:
    """What every file of one launch shares.

    Attributes:
        evaluate: The expression sandbox for ``$(eval)`` and ``!radians`` (None: refused).
        top_file: The launch file given (its arguments are the command line's).
        top_declared: Arguments declared anywhere in the top file.
        default_machine: The last ``<machine default="true">`` read.
    """

    dry_run: bool
    run_command: CommandRunner
    load_file: FileLoader
    evaluate: ExpressionEvaluator | None = None
    top_file: Path | None = None
    top_declared: set[str] = field(default_factory=set)
    default_machine: str | None = None
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


# --- ROS names as roslaunch joins them ------------------------------------------------------


def ns_join(namespace: str, name: str) -> str:
    """rosgraph's ``ns_join``: ``name`` unchanged when private (``~``) or global (``/``)."""
    if name.startswith(("~", "/")):
        return name
    if namespace == "~":
        return "~" + name
    if not namespace:
        return name
    return namespace + name if namespace.endswith("/") else namespace + "/" + name


def canonical_name(name: str) -> str:
    """rosgraph's ``canonicalize_name``: no repeated or trailing slashes."""
    if not name or name == "/":
        return name
    parts = "/".join(p for p in name.split("/") if p)
    return "/" + parts if name.startswith("/") else parts


_LEGAL_NAME = re.compile(r"^[\~\/A-Za-z][\w\/]*$")


def legal_name(name: str) -> bool:
    """rosgraph's ``is_legal_name`` (the empty name is legal: it is the namespace)."""
    return name == "" or (_LEGAL_NAME.match(name) is not None and "//" not in name)


class LaunchContext:
    """What one part of a launch file sees while it is read (roslaunch's ``LoaderContext``).

    Attributes:
        args: Argument values in scope (``$(arg)``).
        declared: Arguments declared in this scope (a second declaration is an error).
        remaps: ``from`` -> ``to`` for nodes declared in this scope.
        env: ``(name, value)`` of ``<env>`` settings for nodes in this scope.
        private: ``(~name, value)`` set outside a node: every later node in the scope gets them.
        pass_all_args: The file was included with ``pass_all_args`` (it may re-set them).
    """

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
        self.declared: list[str] = []
        self.namespace = namespace
        self.remaps: dict[str, str] = {}
        self.env: list[tuple[str, str]] = []
        self.private: list[tuple[str, Any]] = []
        self.anon: dict[str, str] = {}
        self.pass_all_args = False
        self.for_include = False  # reading the <arg>s of an <include> into this scope
        self.shared = shared
        self.chain = chain  # the files that include this one, outermost first

    def child(self, namespace: str | None = None, line: int | None = None) -> LaunchContext:
        """A scope inside this one (``<group>``, ``<node>``), in ``namespace`` if given.

        Raises:
            LaunchError: A private namespace (``~name``).
        """
        ctx = LaunchContext(self.path, self.args, self.shared, self.namespace, self.chain)
        ctx.declared = list(self.declared)
        ctx.remaps = dict(self.remaps)
        ctx.env = list(self.env)
        # roslaunch passes its list of ~params on when it holds some, else starts a new one
        ctx.private = self.private if self.private else []
        ctx.anon = dict(self.anon)
        if namespace:
            if namespace.startswith("~"):
                raise self.error(
                    f"namespace '{namespace}' is private; a namespace is relative or global",
                    line,
                )
            joined = namespace if namespace.startswith("/") else ns_join(self.namespace, namespace)
            ctx.namespace = canonical_name(joined) or "/"
        return ctx

    def error(self, message: str, line: int | None = None, hint: str | None = None) -> LaunchError:
        return LaunchError(message, path=self.path, line=line, hint=hint)

    def resolve_file(self, name: str) -> Path:
        """A file named in this launch file: absolute, or relative to the file's folder."""
        target = Path(name)
        return target if target.is_absolute() else self.path.parent / target

    # --- arguments ----------------------------------------------------------------------

    def declare_arg(
        self, name: str, value: str | None, default: str | None, line: int | None
    ) -> None:
        """``<arg name value default>`` as roslaunch's ``add_arg`` takes it.

        Raises:
            LaunchError: Declared twice in one scope, a ``value`` for an argument already
                set (from the command line or an ``<include>``), or both value and default.
        """
        if value is not None and default is not None:
            raise self.error(f"<arg name='{name}'> has both value and default", line)
        if name in self.declared:
            if not self.pass_all_args:
                raise self.error(f"argument '{name}' is declared twice", line)
        else:
            self.declared.append(name)
        if self.path == self.shared.top_file and not self.for_include:
            self.shared.top_declared.add(name)
        if value is not None:
            if name in self.args and not self.pass_all_args:
                raise self.error(
                    f"argument '{name}' has a fixed value='{value}' and cannot be set",
                    line,
                    hint="only an <arg> with default= can be given a value",
                )
            self.args[name] = value
        elif default is not None and name not in self.args:
            self.args[name] = default

    # --- includes -----------------------------------------------------------------------

    def include_scope(self, namespace: str | None, line: int | None = None) -> LaunchContext:
        """The scope an ``<include>``d file starts in: this one's namespace, remappings, env
        and ~params, but no arguments (they are passed one by one)."""
        inner = self.child(namespace, line)
        inner.args = {}
        inner.declared = []
        inner.anon = {}
        inner.for_include = True
        return inner

    def include(
        self, file: str, plan: LaunchPlan, args: dict[str, str], ns: str | None, line: int | None
    ) -> None:
        """Read ``file`` with ``args`` in namespace ``ns`` (the YAML form's ``include:``)."""
        inner = self.include_scope(ns, line)
        inner.args = dict(args)
        self.read_include(file, plan, inner, line)
        unused = sorted(set(args) - set(inner.declared))
        if unused:
            raise self.error(
                f"{file} does not declare the argument '{unused[0]}' passed to it", line
            )

    def read_include(
        self, file: str, plan: LaunchPlan, inner: LaunchContext, line: int | None
    ) -> None:
        """Read the launch file ``file`` into ``plan`` in the scope ``inner``, refusing cycles
        and runaway includes.

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
        inner.path, inner.chain, inner.for_include = resolved, chain, False
        self.shared.load_file(resolved, inner, plan)

    # --- substitutions and values -----------------------------------------------------------

    def scope(self) -> Scope:
        """What substitutions see here."""
        return Scope(
            self.args,
            self.anon,
            self.path,
            lambda name: find_package(name, self.path.parent),
            self.shared.evaluate,
        )

    def substitute(self, text: str, where: str, line: int | None = None) -> str:
        """``text`` with its substitutions resolved as roslaunch resolves them
        (:mod:`workbench.bus.launch_subst`).

        Raises:
            LaunchError: An unset arg or variable, an unknown substitution, a failing
                ``$(eval)``, or a result longer than :data:`MAX_VALUE_CHARS`.
        """
        try:
            return resolve(text, self.scope(), MAX_VALUE_CHARS)
        except SubstitutionError as error:
            raise self.error(f"{where}: {error.message}", line, error.hint) from None
        except LaunchError as error:  # $(find) of a package that is not there
            raise self.error(f"{where}: {error.message}", line, error.hint) from None


def parse_bool(value: str | bool | None, default: bool = False) -> bool:
    """A loose boolean (the YAML form): ``true``, ``1`` or ``yes`` in any case."""
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
    if value is None:
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
    return name if name.startswith("/") else ns_join(namespace, name)


def typed_value(
    value: str,
    type_name: str | None,
    what: str = "value",
    evaluate: ExpressionEvaluator | None = None,
) -> Any:
    """A ``<param>`` value converted as roslaunch converts it (``auto`` without ``type``):
    :func:`~workbench.bus.launch_subst.convert_value`, and ``yaml`` as rosparam YAML.

    Raises:
        ValueError: Not of the type asked for, or an unknown type.
        BusError: ``type="yaml"`` that is not YAML within bounds.
    """
    from workbench.bus.launch_rosparam_yaml import load_rosparam_yaml

    kind = (type_name or "auto").lower().strip()
    if kind == "yaml":
        return load_rosparam_yaml(value, what, LaunchError, evaluate)
    return convert_value(value, kind)
