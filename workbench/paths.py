"""Where workbench finds its data: robot descriptions, planning configs, worlds, maps, examples.

The data directories (``urdf/``, ``planning/``, ``mapping/``, ``examples/``)
live at the top of the project checkout, beside the ``workbench`` package. A
built wheel (``pip install .``) carries a copy of them inside the package, as
``workbench/_data/<dir>`` (``setup.py`` copies them there at build time).
:func:`project_root` picks the first of:

1. ``$WORKBENCH_HOME``, if set: a directory holding those folders (e.g. a
   checkout, or a copy of its data you edit);
2. the checkout the package was imported from (an editable install, or
   ``PYTHONPATH`` pointing at the checkout), recognised by ``pyproject.toml``
   and ``urdf/`` beside the package;
3. the data installed with the package (``workbench/_data``).

Installed data sits in site-packages, which is not the user's to write. So
there, :func:`planning_dir` (where ``workbench setup`` writes and where the
planners read) is a user-writable copy, :func:`user_data_root` ``/planning``
(``$WORKBENCH_DATA_DIR``, else ``$XDG_DATA_HOME/workbench``, else
``~/.local/share/workbench``), filled on first use with the shipped planning
configs and scenes; files already there (written by ``workbench setup``) are
kept. Nothing here imports pydrake.
"""

from __future__ import annotations

import os
import shutil
import threading
from pathlib import Path

from workbench.errors import WorkbenchError

_PACKAGE_DIR = Path(__file__).resolve().parent
#: The data directories, at the top of a checkout and under ``workbench/_data`` in a wheel.
DATA_DIRS = ("urdf", "planning", "mapping", "examples")
#: Where a built wheel carries them.
INSTALLED_DATA = _PACKAGE_DIR / "_data"


def project_root() -> Path:
    """The directory holding ``urdf/``, ``planning/``, ``mapping/`` and ``examples/``.

    Order: ``$WORKBENCH_HOME``, then the checkout the package was imported from,
    then the data installed with the package (see the module docstring).

    Raises:
        WorkbenchError: ``$WORKBENCH_HOME`` is not a directory, or no data is found.
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
    checkout = checkout_root()
    if checkout is not None:
        return checkout
    if INSTALLED_DATA.is_dir():
        return INSTALLED_DATA
    raise WorkbenchError(
        f"workbench's data (urdf/, planning/, mapping/, examples/) is neither beside "
        f"{_PACKAGE_DIR} nor in {INSTALLED_DATA}",
        hint="reinstall workbench from a wheel or a checkout, or set WORKBENCH_HOME to a checkout",
    )


def checkout_root() -> Path | None:
    """The project checkout this package was imported from, or None for an installed wheel."""
    candidate = _PACKAGE_DIR.parent
    if (candidate / "pyproject.toml").is_file() and (candidate / "urdf").is_dir():
        return candidate
    return None


def is_installed_data(root: Path) -> bool:
    """Whether ``root`` is the data shipped inside the installed package (read-only to users)."""
    return root.resolve() == INSTALLED_DATA.resolve()


def urdf_dir() -> Path:
    """The lab robot descriptions (``urdf/``)."""
    return project_root() / "urdf"


def planning_dir() -> Path:
    """Per-robot planning configurations and scenes (``planning/``).

    In a checkout or ``$WORKBENCH_HOME`` it is the ``planning/`` folder there;
    for an installed wheel it is ``<user data>/planning``, seeded from the shipped
    configs (see :func:`user_data_root`).
    """
    root = project_root()
    shipped = root / "planning"
    if not is_installed_data(root):
        return shipped
    target = user_data_root() / "planning"
    seed_copy(shipped, target)
    return target


def mapping_dir() -> Path:
    """Worlds and saved maps (``mapping/``)."""
    return project_root() / "mapping"


def examples_dir() -> Path:
    """The lab's own scripts and launch files (``examples/``)."""
    return project_root() / "examples"


def user_data_root() -> Path:
    """Where an installed workbench writes what the user makes (planning configs).

    ``$WORKBENCH_DATA_DIR``, else ``$XDG_DATA_HOME/workbench``, else
    ``~/.local/share/workbench``.
    """
    explicit = os.environ.get("WORKBENCH_DATA_DIR")
    if explicit:
        return Path(explicit).expanduser()
    xdg = os.environ.get("XDG_DATA_HOME")
    return (Path(xdg) if xdg else Path.home() / ".local" / "share") / "workbench"


def notebook_output(lab: str) -> Path:
    """The folder a lab notebook writes its files into (snapshots, bags, maps, pictures).

    ``$WORKBENCH_OUTPUT_DIR/<lab>``, else ``user_data_root()/output/<lab>``, created on
    use: outside the checkout, so running the notebooks leaves ``notebooks/`` as cloned.

    Raises:
        WorkbenchError: the folder cannot be created.
    """
    explicit = os.environ.get("WORKBENCH_OUTPUT_DIR")
    base = Path(explicit).expanduser() if explicit else user_data_root() / "output"
    folder = base / lab
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise WorkbenchError(
            f"cannot create the notebook output folder {folder}: {error.strerror}",
            hint="set WORKBENCH_OUTPUT_DIR to a writable directory",
        ) from None
    return folder


def seed_copy(source: Path, target: Path) -> None:
    """Copy every file of ``source`` that ``target`` lacks (existing files are kept).

    Each file is written under a temporary name and renamed, so processes seeding
    the same directory at once never see half a file.

    Raises:
        WorkbenchError: ``target`` cannot be written.
    """
    if not source.is_dir():
        return
    try:
        for path in sorted(source.rglob("*")):
            if not path.is_file() or "__pycache__" in path.parts:
                continue
            destination = target / path.relative_to(source)
            if destination.exists():
                continue
            destination.parent.mkdir(parents=True, exist_ok=True)
            unique = f"{os.getpid()}.{threading.get_ident()}"
            temporary = destination.with_name(f".{destination.name}.{unique}.seed")
            shutil.copyfile(path, temporary)
            os.replace(temporary, destination)
    except OSError as error:
        raise WorkbenchError(
            f"cannot copy the shipped planning configs to {target}: {error}",
            hint="set WORKBENCH_DATA_DIR to a writable directory",
        ) from None


def cache_root() -> Path:
    """Where workbench keeps what it can recompute (``$WORKBENCH_CACHE_DIR``, else
    ``$XDG_CACHE_HOME/workbench``, else ``~/.cache/workbench``)."""
    explicit = os.environ.get("WORKBENCH_CACHE_DIR")
    if explicit:
        return Path(explicit)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "workbench"


def is_file(path: str | os.PathLike[str]) -> bool:
    """``Path(path).is_file()``, False (not an error) for a name the system cannot look up.

    A path from a model or a scene may be longer than the system allows (``File name too
    long``) or loop through links; ``pathlib`` raises for those, where "no such file" is the
    answer the caller can report.
    """
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


def is_dir(path: str | os.PathLike[str]) -> bool:
    """``Path(path).is_dir()``, False for a name the system cannot look up (see :func:`is_file`)."""
    try:
        return Path(path).is_dir()
    except (OSError, ValueError):
        return False


def exists(path: str | os.PathLike[str]) -> bool:
    """``Path(path).exists()``, False for a name the system cannot look up (see :func:`is_file`)."""
    try:
        return Path(path).exists()
    except (OSError, ValueError):
        return False
