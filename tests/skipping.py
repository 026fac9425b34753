"""Skipping for a missing system program or package, which CI forbids.

Importable by name from any test module (``from skipping import skip_or_fail``): a
unique module name, where ``conftest`` may resolve to a sub-folder's conftest.
"""

from __future__ import annotations

import os
import subprocess
from functools import cache

import pytest


def require_all() -> bool:
    """Whether skips are forbidden (``WORKBENCH_REQUIRE_ALL=1``, as ``.ci/run`` sets)."""
    return os.environ.get("WORKBENCH_REQUIRE_ALL", "") not in ("", "0")


def skip_or_fail(reason: str) -> None:
    """Skip with ``reason``; under WORKBENCH_REQUIRE_ALL=1, fail instead."""
    if require_all():
        pytest.fail(f"WORKBENCH_REQUIRE_ALL=1 forbids skipping: {reason}")
    pytest.skip(reason)


#: The system Python, where Debian's ROS 1 packages are installed.
ROS_PYTHON = "/usr/bin/python3"


@cache
def _imports(module: str) -> bool:
    try:
        done = subprocess.run(
            [ROS_PYTHON, "-c", f"import {module}"], capture_output=True, timeout=60
        )
    except (OSError, subprocess.TimeoutExpired):
        return False
    return done.returncode == 0


def ros_python(module: str, package: str) -> str:
    """The system Python if it imports ROS 1's ``module``; else skip (fail under
    WORKBENCH_REQUIRE_ALL=1) saying which Debian ``package`` to install."""
    if not _imports(module):
        skip_or_fail(f"ROS 1's {module} is not installed (apt-get install {package})")
    return ROS_PYTHON
