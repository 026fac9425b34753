"""Build hook: put the data directories at the top of the repository into the wheel.

``urdf/``, ``planning/``, ``mapping/`` and ``examples/`` stay at the top of the
repository (see ARCHITECTURE.md); a built wheel carries them as
``workbench/_data/<dir>``, where :mod:`workbench.paths` finds them when no
checkout is around. An editable install needs no copy: it uses the checkout's
folders in place. Everything else is configured in ``pyproject.toml``.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

DATA_DIRS = ("urdf", "planning", "mapping", "examples")
HERE = Path(__file__).resolve().parent


class BuildPyWithData(build_py):
    """``build_py`` that also copies the data directories into ``workbench/_data``."""

    def run(self) -> None:
        super().run()
        if getattr(self, "editable_mode", False):
            return
        target = Path(self.build_lib) / "workbench" / "_data"
        for name in DATA_DIRS:
            source = HERE / name
            if not source.is_dir():
                raise SystemExit(f"setup.py: the data directory {source} is missing")
            destination = target / name
            if destination.exists():
                shutil.rmtree(destination)
            shutil.copytree(
                source, destination, ignore=shutil.ignore_patterns("__pycache__", "*.py[co]")
            )


setup(cmdclass={"build_py": BuildPyWithData})
