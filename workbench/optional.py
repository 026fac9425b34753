"""Import optional packages and find system programs, with errors that say what to install."""

from __future__ import annotations

import importlib
import shutil
from types import ModuleType

from workbench.errors import MissingDependencyError

#: The pip extra that provides each optional top-level module.
EXTRA_OF_MODULE = {
    "ompl": "plan",
    "toppra": "plan",
    "numba": "plan",
    "zenoh": "zenoh",
    "serial": "serial",
}

#: Debian package that provides each system program, and the names to try.
SYSTEM_PROGRAMS = {
    "dot": ("graphviz", ("dot",)),
    "chromium": ("chromium", ("chromium", "chromium-browser", "google-chrome", "chrome")),
}


def require(module: str) -> ModuleType:
    """Import an optional module or raise :class:`MissingDependencyError` naming its extra."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        extra = EXTRA_OF_MODULE.get(module.split(".")[0])
        how = f"pip install 'workbench[{extra}]'" if extra else f"pip install {module}"
        raise MissingDependencyError(
            f"the optional package '{module}' is not installed ({exc})", hint=how
        ) from exc


def find_program(name: str) -> str | None:
    """Return the path of a system program (``dot``, ``chromium``) or None."""
    _, candidates = SYSTEM_PROGRAMS.get(name, (name, (name,)))
    for candidate in candidates:
        found = shutil.which(candidate)
        if found:
            return found
    return None


def require_program(name: str) -> str:
    """Return the path of a system program or raise naming the package to install."""
    found = find_program(name)
    if found is None:
        package, _ = SYSTEM_PROGRAMS.get(name, (name, ()))
        raise MissingDependencyError(
            f"the system program '{name}' was not found on PATH",
            hint=f"install it, e.g. 'sudo apt-get install {package}'",
        )
    return found
