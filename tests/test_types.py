"""The type checker on the public API: ``python -m mypy`` with the ``[tool.mypy]`` configuration."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent


def require_mypy() -> None:
    """Skip (fail under WORKBENCH_REQUIRE_ALL=1) when mypy, a test extra, is not installed."""
    if importlib.util.find_spec("mypy") is None:
        from skipping import skip_or_fail

        skip_or_fail("mypy is not installed (it is in the test extra: pip install -e '.[test]')")


def test_mypy_passes_on_the_configured_modules():
    require_mypy()
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--config-file", str(REPO_ROOT / "pyproject.toml")],
        cwd=REPO_ROOT,
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, f"mypy found type errors:\n{result.stdout}{result.stderr}"
    assert "Success" in result.stdout
