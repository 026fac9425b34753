"""Launch files: the roslaunch XML subset the labs use, and a YAML form.

XML: ``<launch>`` with ``<arg name default value>``, ``<param name value type
textfile command>``, ``<rosparam file command ns>`` (or inline YAML),
``<node pkg type name args ns output respawn respawn_delay required>`` with
nested ``<param>``, ``<rosparam>`` and ``<remap>``, ``<remap from to>``,
``<include file>`` with nested ``<arg>``, ``<group ns>``, and ``if``/``unless``
on any element. Substitutions: ``$(arg x)``, ``$(find pkg)``, ``$(env X)``,
``$(optenv X default)``, ``$(anon name)``, ``$(dirname)``.

YAML::

    args: {turtle: turtle1}
    params: {/background_r: 150}
    nodes:
      - {pkg: turtlesim, type: turtlesim_node, name: sim, output: screen,
         params: {turtle: $(arg turtle)}, remap: {cmd_vel: /turtle1/cmd_vel}}
    include: [{file: other.launch, args: {x: 1}}]

Parsing produces a :class:`LaunchPlan`; :mod:`workbench.bus.launcher` runs it.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.bus.names import anonymous_name, join
from workbench.errors import BusError


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


@dataclass
class LaunchPlan:
    """Parameters to set, then nodes to start."""

    params: dict[str, Any] = field(default_factory=dict)
    nodes: list[NodeSpec] = field(default_factory=list)
    deletes: list[str] = field(default_factory=list)


_SUBST = re.compile(r"\$\((\w+)(?:\s+([^)]*))?\)")


class _Context:
    def __init__(self, path: Path, args: dict[str, str], namespace: str = "/"):
        self.path = path
        self.args = dict(args)
        self.namespace = namespace
        self.remaps: dict[str, str] = {}
        self.anon: dict[str, str] = {}

    def child(self, namespace: str | None = None) -> _Context:
        ctx = _Context(self.path, self.args, self.namespace)
        ctx.remaps = dict(self.remaps)
        ctx.anon = self.anon
        if namespace:
            ctx.namespace = (
                namespace if namespace.startswith("/") else join(self.namespace, namespace)
            )
        return ctx


def find_package(name: str, near: Path | None = None) -> Path:
    """The directory of package ``name``: a folder with a package.xml naming it.

    Looks beside and above ``near``, in the working directory, in the checkout and in
    workbench's ``examples/packages``.

    Raises:
        LaunchError: Not found.
    """
    from workbench.paths import examples_dir, project_root

    roots: list[Path] = []
    if near is not None:
        roots += [near, *near.parents][:4]
    # examples/packages holds the ROS packages the labs' launch files name (gazebo_ros ...).
    roots += [Path.cwd(), project_root(), examples_dir(), examples_dir() / "packages"]
    seen: set[Path] = set()
    for root in roots:
        if root in seen or not root.is_dir():
            continue
        seen.add(root)
        if root.name == name:
            return root
        for candidate in (root / name, root / "src" / name):
            if candidate.is_dir():
                return candidate
        for xml in list(root.glob("package.xml")) + list(root.glob("*/package.xml")):
            try:
                text = xml.read_text(errors="replace")
            except OSError:
                continue
            if re.search(rf"<name>\s*{re.escape(name)}\s*</name>", text):
                return xml.parent
    raise LaunchError(
        f"package '{name}' not found",
        hint="run from the package's folder, or use a path instead of $(find ...)",
    )


def substitute(text: str, ctx: _Context, where: str) -> str:
    def repl(match: re.Match[str]) -> str:
        command, rest = match.group(1), (match.group(2) or "").strip()
        if command == "arg":
            if rest not in ctx.args:
                raise LaunchError(f"{where}: $(arg {rest}) is not defined", path=ctx.path)
            return str(ctx.args[rest])
        if command == "find":
            return str(find_package(rest, ctx.path.parent))
        if command == "env":
            if rest not in os.environ:
                raise LaunchError(f"{where}: environment variable {rest} is not set", path=ctx.path)
            return os.environ[rest]
        if command == "optenv":
            key, _, default = rest.partition(" ")
            return os.environ.get(key, default)
        if command == "anon":
            return ctx.anon.setdefault(rest, anonymous_name(rest))
        if command == "dirname":
            return str(ctx.path.parent)
        raise LaunchError(f"{where}: unsupported substitution $({command} ...)", path=ctx.path)

    return _SUBST.sub(repl, text)


def _bool(value: str | bool | None, default: bool = False) -> bool:
    if value is None:
        return default
    if isinstance(value, bool):
        return value
    return str(value).strip().lower() in ("true", "1", "yes")


def typed_value(value: str, type_name: str | None) -> Any:
    """A ``<param>`` value converted as roslaunch does (auto-typed without ``type``)."""
    import yaml

    if type_name in ("str", "string"):
        return value
    if type_name == "int":
        return int(value)
    if type_name == "double":
        return float(value)
    if type_name in ("bool", "boolean"):
        return value.strip().lower() == "true"
    if type_name == "yaml":
        return yaml.safe_load(value)
    stripped = value.strip()
    if stripped.lower() in ("true", "false"):
        return stripped.lower() == "true"
    for convert in (int, float):
        try:
            return convert(stripped)
        except ValueError:
            pass
    return value


def run_command(command: str, path: Path) -> str:
    """Run a ``<param command=...>`` and return its output (xacro runs in-process Python)."""
    argv = shlex.split(command)
    if argv and Path(argv[0]).name in ("xacro", "xacro.py"):
        # The xacro distribution on PyPI has no __main__: call its main() as its script does.
        argv = [sys.executable, "-c", "import sys, xacro; sys.argv[0] = 'xacro'; xacro.main()"]
        argv += shlex.split(command)[1:]
    try:
        done = subprocess.run(argv, capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise LaunchError(f"param command '{command}' failed: {error}", path=path) from None
    if done.returncode != 0:
        raise LaunchError(
            f"param command '{command}' exited with {done.returncode}: "
            f"{done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ''}",
            path=path,
        )
    return done.stdout


def load_launch(path: str | os.PathLike[str], args: dict[str, str] | None = None) -> LaunchPlan:
    """Parse a launch file (``.launch``/``.xml`` or ``.yaml``/``.yml``) into a plan.

    Args:
        path: The file.
        args: Values for its ``<arg>`` (``name:=value`` on the command line).

    Raises:
        LaunchError: Unreadable file, bad XML/YAML, unknown element or missing arg.
    """
    file = Path(path)
    if not file.is_file():
        raise LaunchError(f"launch file {file} does not exist")
    plan = LaunchPlan()
    ctx = _Context(file.resolve(), {})
    if file.suffix in (".yaml", ".yml"):
        _load_yaml(file, ctx, plan, args or {})
    else:
        _load_xml(file, ctx, plan, args or {})
    names = [spec.full_name for spec in plan.nodes]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise LaunchError(
            f"node name {duplicates[0]} is used twice",
            path=file,
            hint="give each node a unique name",
        )
    return plan


# --- XML --------------------------------------------------------------------------------


def _load_xml(file: Path, ctx: _Context, plan: LaunchPlan, given: dict[str, str]) -> None:
    from lxml import etree

    try:
        root = etree.parse(str(file)).getroot()
    except (etree.XMLSyntaxError, OSError) as error:
        raise LaunchError(f"cannot parse launch file: {error}", path=file) from None
    if root.tag != "launch":
        raise LaunchError(
            f"the root element is <{root.tag}>, not <launch>", path=file, line=root.sourceline
        )
    ctx.path = file.resolve()
    _xml_children(root, ctx, plan, given)
    unknown = sorted(set(given) - set(ctx.args))
    if unknown and ctx.path == file.resolve():
        raise LaunchError(f"argument '{unknown[0]}' is not declared in the launch file", path=file)


def _attr(element: Any, name: str, ctx: _Context, required: bool = False) -> str | None:
    value = element.get(name)
    if value is None:
        if required:
            raise LaunchError(
                f"<{element.tag}> needs a '{name}' attribute",
                path=ctx.path,
                line=element.sourceline,
            )
        return None
    return substitute(value, ctx, f"<{element.tag}> line {element.sourceline}")


def _enabled(element: Any, ctx: _Context) -> bool:
    cond_if, cond_unless = _attr(element, "if", ctx), _attr(element, "unless", ctx)
    if cond_if is not None and not _bool(cond_if):
        return False
    return not (cond_unless is not None and _bool(cond_unless))


def _xml_children(parent: Any, ctx: _Context, plan: LaunchPlan, given: dict[str, str]) -> None:
    for element in parent:
        if not isinstance(element.tag, str):
            continue  # comments
        if not _enabled(element, ctx):
            continue
        tag = element.tag
        if tag == "arg":
            name = _attr(element, "name", ctx, required=True)
            assert name is not None
            value, default = _attr(element, "value", ctx), _attr(element, "default", ctx)
            if value is not None:
                ctx.args[name] = value
            elif name in given:
                ctx.args[name] = given[name]
            elif default is not None:
                ctx.args[name] = default
            else:
                raise LaunchError(
                    f"argument '{name}' has no value",
                    path=ctx.path,
                    line=element.sourceline,
                    hint=f"pass {name}:=VALUE on the command line",
                )
        elif tag == "param":
            name = _attr(element, "name", ctx, required=True)
            assert name is not None
            plan.params[_param_name(name, ctx.namespace)] = _xml_param_value(element, ctx)
        elif tag == "rosparam":
            _xml_rosparam(element, ctx, plan, ctx.namespace)
        elif tag == "remap":
            ctx.remaps[_attr(element, "from", ctx, True) or ""] = (
                _attr(element, "to", ctx, True) or ""
            )
        elif tag == "node":
            plan.nodes.append(_xml_node(element, ctx, plan))
        elif tag == "group":
            _xml_children(element, ctx.child(_attr(element, "ns", ctx)), plan, given)
        elif tag == "include":
            _xml_include(element, ctx, plan)
        elif tag in ("machine", "env", "test"):
            continue
        else:
            raise LaunchError(
                f"unsupported launch element <{tag}>", path=ctx.path, line=element.sourceline
            )


def _param_name(name: str, namespace: str) -> str:
    name = name.removeprefix("~")  # inside <node>, the namespace is already the node's
    return name if name.startswith("/") else join(namespace, name)


def _xml_param_value(element: Any, ctx: _Context) -> Any:
    where = f"<param> line {element.sourceline}"
    value, textfile = _attr(element, "value", ctx), _attr(element, "textfile", ctx)
    command = _attr(element, "command", ctx)
    try:
        if value is not None:
            return typed_value(value, _attr(element, "type", ctx))
        if textfile is not None:
            target = Path(textfile)
            if not target.is_absolute():
                target = ctx.path.parent / target
            try:
                return target.read_text()
            except OSError as error:
                raise LaunchError(
                    f"{where}: cannot read textfile {textfile}: {error.strerror}", path=ctx.path
                ) from None
        if command is not None:
            return run_command(command, ctx.path)
    except ValueError as error:
        raise LaunchError(f"{where}: {error}", path=ctx.path, line=element.sourceline) from None
    raise LaunchError(
        f"{where}: needs value=, textfile= or command=", path=ctx.path, line=element.sourceline
    )


def _xml_rosparam(element: Any, ctx: _Context, plan: LaunchPlan, namespace: str) -> None:
    import yaml

    command = _attr(element, "command", ctx) or "load"
    ns = _attr(element, "ns", ctx)
    base = _param_name(ns, namespace) if ns else namespace
    if command == "delete":
        param = _attr(element, "param", ctx, required=True) or ""
        plan.deletes.append(_param_name(param, base))
        return
    if command == "dump":
        return
    if command != "load":
        raise LaunchError(
            f"<rosparam command='{command}'> is not supported (load, delete, dump)",
            path=ctx.path,
            line=element.sourceline,
        )
    file = _attr(element, "file", ctx)
    if file is not None:
        target = Path(file) if Path(file).is_absolute() else ctx.path.parent / file
        try:
            text = target.read_text()
        except OSError as error:
            raise LaunchError(
                f"<rosparam> cannot read {file}: {error.strerror}",
                path=ctx.path,
                line=element.sourceline,
            ) from None
    else:
        text = substitute(element.text or "", ctx, f"<rosparam> line {element.sourceline}")
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise LaunchError(
            f"<rosparam> YAML is invalid: {error}", path=ctx.path, line=element.sourceline
        ) from None
    target_param = _attr(element, "param", ctx)
    if target_param is not None:
        plan.params[_param_name(target_param, base)] = data
    elif isinstance(data, dict):
        for key, value in data.items():
            plan.params[_param_name(str(key), base)] = value
    elif data is not None:
        raise LaunchError(
            "<rosparam> without param= needs a YAML dictionary",
            path=ctx.path,
            line=element.sourceline,
        )


def _xml_node(element: Any, ctx: _Context, plan: LaunchPlan) -> NodeSpec:
    pkg = _attr(element, "pkg", ctx, required=True) or ""
    node_type = _attr(element, "type", ctx, required=True) or ""
    name = _attr(element, "name", ctx) or Path(node_type).stem
    ns = _attr(element, "ns", ctx)
    namespace = ctx.child(ns).namespace if ns else ctx.namespace
    spec = NodeSpec(
        pkg=pkg,
        type=node_type,
        name=name,
        namespace=namespace,
        args=shlex.split(_attr(element, "args", ctx) or ""),
        remaps=dict(ctx.remaps),
        output=_attr(element, "output", ctx) or "log",
        respawn=_bool(_attr(element, "respawn", ctx)),
        respawn_delay=float(_attr(element, "respawn_delay", ctx) or 0.0),
        required=_bool(_attr(element, "required", ctx)),
        source=f"{ctx.path}:{element.sourceline}",
    )
    private = spec.full_name
    for child in element:
        if not isinstance(child.tag, str) or not _enabled(child, ctx):
            continue
        if child.tag == "param":
            pname = _attr(child, "name", ctx, required=True) or ""
            plan.params[_param_name(pname, private)] = _xml_param_value(child, ctx)
        elif child.tag == "rosparam":
            _xml_rosparam(child, ctx, plan, private)
        elif child.tag == "remap":
            spec.remaps[_attr(child, "from", ctx, True) or ""] = _attr(child, "to", ctx, True) or ""
        elif child.tag == "env":
            continue
        else:
            raise LaunchError(
                f"unsupported element <{child.tag}> inside <node>",
                path=ctx.path,
                line=child.sourceline,
            )
    return spec


def _xml_include(element: Any, ctx: _Context, plan: LaunchPlan) -> None:
    file = _attr(element, "file", ctx, required=True) or ""
    target = Path(file) if Path(file).is_absolute() else ctx.path.parent / file
    child_args: dict[str, str] = {}
    for child in element:
        if isinstance(child.tag, str) and child.tag == "arg" and _enabled(child, ctx):
            child_args[_attr(child, "name", ctx, True) or ""] = (
                _attr(child, "value", ctx, True) or ""
            )
    if not target.is_file():
        raise LaunchError(
            f"<include> file {file} does not exist", path=ctx.path, line=element.sourceline
        )
    inner = _Context(target.resolve(), {}, ctx.child(_attr(element, "ns", ctx)).namespace)
    inner.remaps = dict(ctx.remaps)
    if target.suffix in (".yaml", ".yml"):
        _load_yaml(target, inner, plan, child_args)
    else:
        _load_xml(target, inner, plan, child_args)


# --- YAML -------------------------------------------------------------------------------


def _load_yaml(file: Path, ctx: _Context, plan: LaunchPlan, given: dict[str, str]) -> None:
    import yaml

    try:
        data = yaml.safe_load(file.read_text()) or {}
    except (yaml.YAMLError, OSError) as error:
        raise LaunchError(f"cannot read launch file: {error}", path=file) from None
    if not isinstance(data, dict):
        raise LaunchError(
            "a YAML launch file is a mapping (args, params, nodes, include)", path=file
        )
    unknown = set(data) - {"args", "params", "nodes", "include", "remap"}
    if unknown:
        raise LaunchError(
            f"unknown top-level key '{sorted(unknown)[0]}'",
            path=file,
            hint="use args, params, nodes, include, remap",
        )
    for name, default in (data.get("args") or {}).items():
        ctx.args[str(name)] = str(given.get(name, default))
    missing = sorted(set(given) - set(ctx.args))
    if missing:
        raise LaunchError(f"argument '{missing[0]}' is not declared in the launch file", path=file)

    def sub(value: Any) -> Any:
        if isinstance(value, str):
            return substitute(value, ctx, str(file.name))
        if isinstance(value, list):
            return [sub(v) for v in value]
        if isinstance(value, dict):
            return {k: sub(v) for k, v in value.items()}
        return value

    for key, value in (data.get("remap") or {}).items():
        ctx.remaps[str(key)] = str(sub(value))
    for key, value in (data.get("params") or {}).items():
        plan.params[_param_name(str(key), ctx.namespace)] = sub(value)
    for index, entry in enumerate(data.get("nodes") or []):
        if not isinstance(entry, dict) or "pkg" not in entry or "type" not in entry:
            raise LaunchError(f"nodes[{index}] needs pkg and type", path=file)
        entry = sub(entry)
        args = entry.get("args", [])
        spec = NodeSpec(
            pkg=str(entry["pkg"]),
            type=str(entry["type"]),
            name=str(entry.get("name") or Path(str(entry["type"])).stem),
            namespace=ctx.child(entry.get("ns")).namespace if entry.get("ns") else ctx.namespace,
            args=shlex.split(args) if isinstance(args, str) else [str(a) for a in args],
            remaps={
                **ctx.remaps,
                **{str(k): str(v) for k, v in (entry.get("remap") or {}).items()},
            },
            output=str(entry.get("output", "log")),
            respawn=_bool(entry.get("respawn")),
            respawn_delay=float(entry.get("respawn_delay", 0.0)),
            required=_bool(entry.get("required")),
            source=f"{file}:nodes[{index}]",
        )
        for key, value in (entry.get("params") or {}).items():
            plan.params[_param_name(str(key), spec.full_name)] = value
        plan.nodes.append(spec)
    for include in data.get("include") or []:
        include = sub(include)
        target = Path(include["file"])
        target = target if target.is_absolute() else file.parent / target
        if not target.is_file():
            raise LaunchError(f"include file {include['file']} does not exist", path=file)
        inner = _Context(target.resolve(), {}, ctx.child(include.get("ns")).namespace)
        inner.remaps = dict(ctx.remaps)
        args = {str(k): str(v) for k, v in (include.get("args") or {}).items()}
        (_load_yaml if target.suffix in (".yaml", ".yml") else _load_xml)(target, inner, plan, args)
