"""Skipping for a missing system program or package, which CI forbids.

Importable by name from any test module (``from skipping import skip_or_fail``): a
unique module name, where ``conftest`` may resolve to a sub-folder's conftest.
"""

from __future__ import annotations

import os

import pytest


def require_all() -> bool:
    """Whether skips are forbidden (``WORKBENCH_REQUIRE_ALL=1``, as ``.ci/run`` sets)."""
    return os.environ.get("WORKBENCH_REQUIRE_ALL", "") not in ("", "0")


def skip_or_fail(reason: str) -> None:
    """Skip with ``reason``; under WORKBENCH_REQUIRE_ALL=1, fail instead."""
    if require_all():
        pytest.fail(f"WORKBENCH_REQUIRE_ALL=1 forbids skipping: {reason}")
    pytest.skip(reason)
