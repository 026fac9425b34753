"""urdfdom's command-line tools and workbench's command line, run side by side."""

from __future__ import annotations

import contextlib
import io
from dataclasses import dataclass

from workbench.cli import main


@dataclass(frozen=True)
class Tools:
    """Paths of Debian's ``check_urdf`` and ``urdf_to_graphviz``."""

    check_urdf: str
    urdf_to_graphviz: str


def run_cli(*args: str) -> tuple[int, str, str]:
    """``workbench ARGS`` in this process: (exit status, stdout, stderr)."""
    stdout, stderr = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
        status = main(list(args))
    return status, stdout.getvalue(), stderr.getvalue()
