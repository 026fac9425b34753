"""Where workbench finds its data: robot descriptions, planning configs, worlds and maps.

The data directories (``urdf/``, ``planning/``, ``mapping/``) live at the top
of the project checkout, beside the ``workbench`` package, and are used in
place by an editable install (``pip install -e .``, as the README does).
``WORKBENCH_HOME`` points elsewhere, e.g. at a copy of the checkout's data
for a non-editable install. Nothing here imports pydrake.
"""

from __future__ import annotations

import os
from pathlib import Path

from workbench.errors import WorkbenchError

_PACKAGE_DIR = Path(__file__).resolve().parent


def project_root() -> Path:
    """The directory holding ``urdf/``, ``planning/`` and ``mapping/``.

    Order: ``$WORKBENCH_HOME``, then the checkout the package was imported
    from, then the current directory.
    """
    env = os.environ.get("WORKBENCH_HOME")
    if env:
        root = Path(env).expanduser()
        if not root.is_dir():
            raise WorkbenchError(
                f"WORKBENCH_HOME={env} is not a directory",
                hint="point it at a workbench checkout or unset it",
            )
        return root
    checkout = _PACKAGE_DIR.parent
    if (checkout / "urdf").is_dir():
        return checkout
    return Path.cwd()


def urdf_dir() -> Path:
    """The lab robot descriptions (``urdf/``)."""
    return project_root() / "urdf"


def planning_dir() -> Path:
    """Per-robot planning configurations and scenes (``planning/``)."""
    return project_root() / "planning"


def mapping_dir() -> Path:
    """Worlds and saved maps (``mapping/``)."""
    return project_root() / "mapping"


def cache_root() -> Path:
    """Where workbench keeps what it can recompute (``$WORKBENCH_CACHE_DIR``, else
    ``$XDG_CACHE_HOME/workbench``, else ``~/.cache/workbench``)."""
    explicit = os.environ.get("WORKBENCH_CACHE_DIR")
    if explicit:
        return Path(explicit)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "workbench"
