"""Values a launch file takes from outside itself: ``textfile=``, ``command=``, rosparam files.

Each is read within bounds (regular files of at most 16 MiB, YAML within the
limits of :mod:`workbench.limits`, a command's output of at most
:data:`MAX_COMMAND_OUTPUT` bytes within :data:`COMMAND_TIMEOUT` seconds). In
a dry run none of them is read or run: the plan holds a
:class:`~workbench.bus.launch_context.Deferred` that says what would be.

``xacro`` commands do not run here: the bus sits below the model layer that
expands xacro, so :func:`run_command` refuses them and ``workbench launch``
passes a runner that expands them in-process (see ``workbench.cli.launch``).
"""

from __future__ import annotations

import selectors
import shlex
import subprocess
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from workbench.bus.launch_context import Deferred, LaunchContext, LaunchError
from workbench.bus.launch_rosparam_yaml import load_rosparam_yaml
from workbench.errors import WorkbenchError
from workbench.limits import MAX_TEXT_FILE_BYTES, read_text_bounded

#: Seconds a ``<param command=...>`` may run.
COMMAND_TIMEOUT = 120.0
#: Most bytes of output a ``<param command=...>`` may print.
MAX_COMMAND_OUTPUT = MAX_TEXT_FILE_BYTES

#: Command names that mean xacro (``$(find xacro)/xacro.py`` in older launch files).
XACRO_NAMES = ("xacro", "xacro.py")


def is_xacro_command(argv: list[str]) -> bool:
    return bool(argv) and Path(argv[0]).name in XACRO_NAMES


def _bounded_output(argv: list[str], command: str, path: Path) -> tuple[int, str, str]:
    """Run ``argv``; its exit status, stdout and stderr, within the time and size bounds."""
    try:
        process = subprocess.Popen(
            argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL
        )
    except OSError as error:
        raise LaunchError(
            f"param command '{command}' failed: {error.strerror or error}", path=path
        ) from None
    chunks: dict[str, list[bytes]] = {"out": [], "err": []}
    size = 0
    deadline = time.monotonic() + COMMAND_TIMEOUT
    problem = None
    with selectors.DefaultSelector() as selector:
        assert process.stdout is not None and process.stderr is not None
        selector.register(process.stdout, selectors.EVENT_READ, "out")
        selector.register(process.stderr, selectors.EVENT_READ, "err")
        while selector.get_map() and problem is None:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                problem = f"did not finish within {COMMAND_TIMEOUT:g} s"
                break
            for key, _ in selector.select(timeout=min(remaining, 1.0)):
                data = key.fileobj.read1(65536)  # type: ignore[union-attr]
                if not data:
                    selector.unregister(key.fileobj)
                    continue
                chunks[key.data].append(data)
                size += len(data)
                if size > MAX_COMMAND_OUTPUT:
                    problem = f"printed more than {MAX_COMMAND_OUTPUT // (1024 * 1024)} MiB"
                    break
    if problem is not None:
        process.kill()
        process.wait()
        raise LaunchError(f"param command '{command}' {problem}", path=path)
    status = process.wait()
    out = b"".join(chunks["out"]).decode("utf-8", "replace")
    return status, out, b"".join(chunks["err"]).decode("utf-8", "replace")


def run_command(command: str, path: Path) -> str:
    """Run a ``<param command=...>`` and return its output.

    Raises:
        LaunchError: The command is xacro (see the module's note), cannot start,
            fails, runs too long or prints too much.
    """
    try:
        argv = shlex.split(command)
    except ValueError as error:
        raise LaunchError(
            f"param command {command!r} cannot be split ({error})", path=path
        ) from None
    if not argv:
        raise LaunchError("param command is empty", path=path)
    if is_xacro_command(argv):
        raise LaunchError(
            f"param command '{command}' needs workbench's xacro",
            path=path,
            hint="start the launch file with 'workbench launch', which expands xacro itself",
        )
    status, out, err = _bounded_output(argv, command, path)
    if status != 0:
        last = err.strip().splitlines()[-1] if err.strip() else ""
        raise LaunchError(f"param command '{command}' exited with {status}: {last}", path=path)
    return out


def command_value(command: str, ctx: LaunchContext, where: str, line: int | None) -> Any:
    """The output of ``command`` (a :class:`Deferred` in a dry run)."""
    if ctx.shared.dry_run:
        return Deferred("output of command", command)
    try:
        return ctx.shared.run_command(command, ctx.path)
    except LaunchError:
        raise
    except WorkbenchError as error:  # xacro's own error, with its file and line
        raise ctx.error(f"{where}: {error.one_line()}", line) from None


def _outside_file(
    name: str, ctx: LaunchContext, where: str, line: int | None, read: Callable[[Path], Any]
) -> Any:
    """``read(file)`` of a file the launch file names (a :class:`Deferred` in a dry run)."""
    target = ctx.resolve_file(name)
    if ctx.shared.dry_run:
        return Deferred("contents of file", str(target))
    try:
        return read(target)
    except LaunchError as error:
        raise ctx.error(f"{where}: {error.one_line()}", line) from None


def textfile_value(name: str, ctx: LaunchContext, where: str, line: int | None) -> Any:
    """The contents of ``textfile=`` (a :class:`Deferred` in a dry run)."""
    return _outside_file(
        name, ctx, where, line, lambda path: read_text_bounded(path, "textfile", LaunchError)
    )


def binfile_value(name: str, ctx: LaunchContext, where: str, line: int | None) -> Any:
    """``binfile=``: refused outside a dry run, as workbench's parameters hold no bytes.

    Raises:
        LaunchError: Always, outside a dry run.
    """
    if ctx.shared.dry_run:
        return Deferred("contents of binary file", str(ctx.resolve_file(name)))
    raise ctx.error(
        f"{where}: binfile={name} makes a binary parameter, which workbench's parameter "
        "server does not hold",
        line,
        hint="use textfile= for text, or a YAML list of numbers",
    )


def rosparam_text(file: str, ctx: LaunchContext, where: str, line: int | None) -> Any:
    """The text of a ``<rosparam file=...>`` (a :class:`Deferred` in a dry run).

    Raises:
        LaunchError: Not a readable regular file within the size bound.
    """
    return _outside_file(
        file, ctx, where, line, lambda path: read_text_bounded(path, "rosparam file", LaunchError)
    )


def rosparam_data(
    text: str, file: str | None, ctx: LaunchContext, where: str, line: int | None
) -> Any:
    """The YAML of a ``<rosparam>`` (its file's text, or its own), with rosparam's angle tags.

    Raises:
        LaunchError: Invalid YAML or YAML past the bounds (the line counts from the file,
            or from the element for inline YAML).
    """
    what = "rosparam file" if file is not None else f"{where}: the YAML"
    try:
        return load_rosparam_yaml(
            text,
            what,
            LaunchError,
            ctx.shared.evaluate,
            str(ctx.resolve_file(file)) if file is not None else None,
        )
    except LaunchError as error:
        if file is not None:
            raise ctx.error(f"{where}: {error.one_line()}", line) from None
        at = line + error.line - 1 if line is not None and error.line is not None else line
        raise ctx.error(error.message, at, error.hint) from None
