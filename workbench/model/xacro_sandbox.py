"""Run xacro on a model file so that the file can compute and nothing else.

ROS's xacro (the ``xacro`` package from PyPI) does the macro work: properties,
macros, blocks, conditionals, includes, ``load_yaml``. While it runs for one
file, workbench replaces the pieces of it that touch the world:

* ``${...}`` is evaluated by :mod:`workbench.model.xacro_eval` (no attribute walks
  to globals; bounded integers, sizes, work and time, :mod:`workbench.model.xacro_meter`);
* ``<xacro:include>``, ``xacro.load_yaml()`` and the file itself may read only
  regular files of at most :data:`~workbench.model.limits.MAX_MODEL_BYTES` inside
  the model's package (the directory of the nearest ``package.xml`` above the
  file, else the file's directory) or a package on the package path
  (``$(find NAME)``), symbolic links resolved;
* ``$(arg)``, ``$(find)``, ``$(dirname)``, ``$(cwd)`` and ``$(eval)`` work (the last
  through the same evaluator); ``$(env NAME)`` is refused and ``$(optenv NAME
  DEFAULT)`` gives its default: a model does not read the environment;
* at most :data:`~workbench.model.limits.MAX_XACRO_ELEMENTS` elements are processed,
  macro bodies counted each time they are copied.

The replacements are undone when the file is expanded; one expansion runs at a time.
"""

from __future__ import annotations

import contextlib
import os
import re
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from workbench.errors import ModelError
from workbench.model.limits import MAX_MODEL_BYTES, MAX_XACRO_ELEMENTS, check_input_file
from workbench.model.packages import PackageResolver
from workbench.model.xacro_eval import evaluate
from workbench.model.xacro_guards import REMOVED_PYTHON, SafeFunction
from workbench.model.xacro_meter import ExpressionLimitError, Meter, metered
from workbench.model.xacro_namespaces import math_functions, python_functions

_LOCK = threading.RLock()
_PATCHED = (
    "replace_node",
    "safe_eval",
    "_global_symbols",
    "eval_extension",
    "get_include_files",
    "parse",
    "eval_all",
    "resolve_macro",
)


class XacroAccessError(ModelError):
    """A xacro file reaches for a file, the environment or a process it may not use."""


def package_root(path: Path) -> Path:
    """The model's package: the directory of the nearest ``package.xml`` above ``path``.

    Without one, the directory of ``path`` itself.
    """
    start = path.resolve().parent
    for directory in [start, *start.parents]:
        if (directory / "package.xml").is_file():
            return directory
    return start


def replace_node(node: Any, by: Any, content_only: bool = False) -> None:
    """xacro's ``replace_node`` in one splice instead of one ``insertBefore`` per child.

    minidom's ``insertBefore`` looks its reference node up in the parent's child list, so
    xacro's expansion grew with the square of a parent's children (a 3000-link chain took
    seconds in that lookup alone). Same result: the nodes of ``by`` (their children, with
    ``content_only``) take the place of ``node``.
    """
    parent = node.parentNode
    moved: list[Any] = []
    for doc in [] if by is None else by if isinstance(by, list) else [by]:
        if content_only:
            moved.extend(doc.childNodes)
            del doc.childNodes[:]
        else:
            if doc.parentNode is not None and doc is not node:
                doc.parentNode.removeChild(doc)
            moved.append(doc)
    siblings = parent.childNodes
    index = siblings.index(node)
    siblings[index : index + 1] = moved
    for child in moved:
        child.parentNode = parent
    for position in range(max(0, index - 1), min(len(siblings), index + len(moved) + 1)):
        current = siblings[position]
        current.previousSibling = siblings[position - 1] if position > 0 else None
        current.nextSibling = siblings[position + 1] if position + 1 < len(siblings) else None
    node.parentNode = node.previousSibling = node.nextSibling = None


def _count_elements(node: Any) -> int:
    count, stack = 0, [node]
    while stack:
        current = stack.pop()
        if current.nodeType == current.ELEMENT_NODE:
            count += 1
        stack.extend(current.childNodes)
    return count


class XacroRun:
    """The world one xacro expansion may see: its files, arguments and budget.

    Args:
        path: The top-level xacro file.
        packages: The packages ``$(find NAME)`` resolves (and whose files it may read).
    """

    def __init__(self, path: Path, packages: PackageResolver) -> None:
        self.path = path.resolve()
        self.packages = packages
        self.roots = [package_root(self.path)] + [
            directory.resolve() for directory in packages.packages.values()
        ]
        self.meter = Meter()
        self.elements = 0

    # --- files -------------------------------------------------------------------------

    def readable(self, filename: str, what: str) -> str:
        """``filename`` when it is a small regular file inside an allowed package.

        Raises:
            XacroAccessError: Outside every allowed package.
            ModelError: Not a regular file, or too big.
        """
        real = Path(filename).resolve()
        if not any(real == root or root in real.parents for root in self.roots):
            raise XacroAccessError(
                f"{what} {filename} is outside the model's package ({self.roots[0]})",
                hint="a model may read only files of its own package, or of a package on "
                "WORKBENCH_PACKAGE_PATH through $(find NAME); see 'Limits on input' in the README",
            )
        check_input_file(real, what, MAX_MODEL_BYTES)
        return str(real)

    def load_yaml(self, filename: Any) -> Any:
        """xacro's ``load_yaml``, reading only files of the allowed packages."""
        import xacro
        import yaml

        for unit in xacro.ConstructUnits:
            yaml.SafeLoader.add_constructor(unit.value.tag, unit.constructor)
        path = self.readable(xacro.abs_filename_spec(str(filename)), "YAML file")
        xacro.filestack.append(path)
        try:
            with open(path, encoding="utf-8") as handle:
                data = yaml.safe_load(handle)
        except RecursionError:
            raise ExpressionLimitError(f"YAML file {path} is nested too deeply") from None
        except (UnicodeDecodeError, yaml.YAMLError) as error:
            reason = " ".join(str(error).split())
            raise xacro.XacroException(f"cannot read YAML file {path}: {reason}") from None
        finally:
            xacro.filestack.pop()
        return xacro.YamlListWrapper.wrap(data)

    def include_files(self, original: Any, filename_spec: str, symbols: Any) -> Iterator[str]:
        """xacro's include file list, each file checked."""
        for filename in original(filename_spec, symbols):
            yield self.readable(filename, "included file")

    def parse(self, original: Any, inp: Any, filename: str | None = None) -> Any:
        """xacro's ``parse``: a file is checked (regular, small) before it is opened."""
        if inp is None and filename is not None:
            check_input_file(filename, "xacro file", MAX_MODEL_BYTES)
        return original(inp, filename)

    # --- budget ------------------------------------------------------------------------

    def count(self, elements: int) -> None:
        self.elements += elements
        self.meter.charge(elements)
        if self.elements > MAX_XACRO_ELEMENTS:
            raise ExpressionLimitError(
                f"the expansion processes more than {MAX_XACRO_ELEMENTS:,} XML elements",
                hint="a model's macros may not multiply without end; see 'Limits on input' "
                "in the README",
            )

    def eval_all(self, original: Any, node: Any, macros: Any, symbols: Any) -> Any:
        self.count(1)
        if self.elements % 1000 == 0:
            self.meter.check_time()
        return original(node, macros, symbols)

    def resolve_macro(self, original: Any, fullname: str, macros: Any, symbols: Any) -> Any:
        found = original(fullname, macros, symbols)
        macro = found[2]
        size = getattr(macro, "workbench_elements", None)
        if size is None:
            size = _count_elements(macro.body)
            macro.workbench_elements = size
        self.count(size)
        return found

    # --- expressions and substitutions ---------------------------------------------

    def safe_eval(self, expression: str, symbols: Any, locals: Any = None) -> Any:
        return evaluate(expression, symbols)

    def symbols(self) -> dict[str, Any]:
        """xacro's global symbols, re-made (see :func:`xacro.create_global_symbols`)."""
        import xacro

        python = python_functions()
        maths = math_functions()
        result: dict[str, Any] = {}
        direct: tuple[str, ...] = (
            "list",
            "dict",
            "map",
            "len",
            "str",
            "float",
            "int",
            "bool",
            "True",
            "False",
        )
        direct += ("min", "max", "round", "sorted", "range")
        for name in direct:
            result[name] = python[name]
        result.update(maths)
        namespaces = {"python": python, "math": maths, "xacro": self._xacro_functions()}
        for name, functions in namespaces.items():
            space = xacro.NameSpace()
            space.update(functions)
            result[name] = space
        vars(result["python"])["removed_names"] = REMOVED_PYTHON
        for name in ("load_yaml", "abs_filename", "dotify"):
            result[name] = result["xacro"][name]
        return result

    def _xacro_functions(self) -> dict[str, Any]:
        import xacro

        def arg(name: str) -> Any:
            return xacro.substitution_args_context["arg"][name]

        def fatal(*args: Any) -> None:
            raise xacro.XacroException(" ".join(map(str, args)))

        def tokenize(text: str, sep: str = ",; ", skip_empty: bool = True) -> list[str]:
            parts = re.split("[" + re.escape(sep) + "]", text)
            return [part for part in parts if part] if skip_empty else parts

        def report(function: Any) -> Any:
            def wrapper(*args: Any, **kwargs: Any) -> str:
                location = kwargs.pop("print_location", function.__name__ in ("warning", "error"))
                kwargs.pop("file", None)
                function(*args, **kwargs)
                if location:
                    xacro.print_location()
                return ""

            return wrapper

        functions: dict[str, Any] = {
            "load_yaml": self.load_yaml,
            "abs_filename": xacro.abs_filename_spec,
            "dotify": xacro.YamlDictWrapper,
            "arg": arg,
            "fatal": fatal,
            "tokenize": tokenize,
        }
        for function in (xacro.message, xacro.warning, xacro.error, xacro.print_location):
            functions[function.__name__] = report(function)
        return {
            name: SafeFunction(function, f"xacro.{name}") for name, function in functions.items()
        }

    def extension(self, text: str) -> Any:
        """xacro's ``$(...)`` substitutions, without the environment or processes."""
        import xacro

        body = text[2:-1].strip()
        if body == "cwd":
            return os.getcwd()
        command, _, rest = body.partition(" ")
        words = rest.split()
        if command == "eval":
            return str(evaluate(rest, self._eval_names()))
        if command == "arg" and len(words) == 1:
            arguments = xacro.substitution_args_context.get("arg", {})
            if words[0] not in arguments:
                raise xacro.XacroException(f"Undefined substitution argument {words[0]}")
            return arguments[words[0]]
        if command == "find" and len(words) == 1:
            return str(self._find(words[0]))
        if command == "dirname" and not words:
            return os.path.dirname(os.path.abspath(xacro.filestack[-1] or self.path))
        if command == "optenv" and words:
            return " ".join(words[1:])
        if command == "env":
            raise XacroAccessError(
                f"$({body}) reads the environment, which a model file may not do in workbench",
                hint=f"pass the value as a xacro argument, {words[0] if words else 'NAME'}:=VALUE",
            )
        raise xacro.XacroException(f"unknown or malformed substitution $({body})")

    def _find(self, name: str) -> Path:
        directory = self.packages.packages.get(name)
        if directory is None:
            known = ", ".join(sorted(self.packages.packages)) or "none"
            raise XacroAccessError(
                f"$(find {name}): unknown package (known packages: {known})",
                hint="add the directory holding its package.xml to WORKBENCH_PACKAGE_PATH",
            )
        return directory

    def _eval_names(self) -> dict[str, Any]:
        import xacro
        from xacro.substitution_args import convert_value

        arguments = dict(xacro.substitution_args_context.get("arg", {}))
        safe = SafeFunction
        names: dict[str, Any] = dict(math_functions())
        names.update({"true": True, "false": False, "True": True, "False": False})
        names["arg"] = safe(lambda name: convert_value(arguments[name], "auto"), "arg")
        names["dirname"] = safe(lambda: os.path.dirname(str(self.path)), "dirname")
        names["find"] = safe(lambda name: str(self._find(name)), "find")
        names["optenv"] = safe(lambda name, default="": default, "optenv")
        for name, value in arguments.items():
            if name.isidentifier() and not name.startswith("__"):
                names[name] = convert_value(value, "auto")
        return names

    # --- installing it ------------------------------------------------------------------

    @contextlib.contextmanager
    def installed(self) -> Iterator[Any]:
        """xacro with this run's replacements, for as long as the block runs."""
        import xacro

        with _LOCK:
            saved = {name: getattr(xacro, name) for name in _PATCHED}
            xacro.replace_node = replace_node
            xacro.safe_eval = self.safe_eval
            xacro._global_symbols = self.symbols()
            xacro.eval_extension = self.extension
            xacro.get_include_files = lambda spec, symbols: self.include_files(
                saved["get_include_files"], spec, symbols
            )
            xacro.parse = lambda inp, filename=None: self.parse(saved["parse"], inp, filename)
            xacro.eval_all = lambda node, macros, symbols: self.eval_all(
                saved["eval_all"], node, macros, symbols
            )
            xacro.resolve_macro = lambda fullname, macros, symbols: self.resolve_macro(
                saved["resolve_macro"], fullname, macros, symbols
            )
            xacro.all_includes = []
            try:
                with metered(self.meter):
                    yield xacro
            finally:
                for name, value in saved.items():
                    setattr(xacro, name, value)
                xacro.all_includes = []


def expand(path: Path, mappings: dict[str, str] | None = None) -> str:
    """The URDF text of the xacro file ``path``, expanded in the sandbox.

    Raises:
        Exception: Whatever xacro raises (:class:`XacroAccessError`, the evaluator's
            errors, ``XacroException``, XML errors); :func:`workbench.model.sources.expand_xacro`
            turns them into one line.
    """
    run = XacroRun(path, PackageResolver(path))
    check_input_file(path, "xacro file", MAX_MODEL_BYTES)
    with run.installed() as xacro:
        try:
            document = xacro.process_file(str(path), mappings=dict(mappings or {}))
        except Exception as error:
            # The file it happened in: an included one, or the top file.
            error.workbench_file = xacro.filestack[-1] if xacro.filestack else None  # type: ignore[attr-defined]
            raise
        text = document.toprettyxml(indent="  ")
    if len(text) > MAX_MODEL_BYTES:
        raise ExpressionLimitError(
            f"the expanded model has {len(text):,} characters; at most {MAX_MODEL_BYTES:,}"
        )
    return text
