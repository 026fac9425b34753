"""Resolve ``package://NAME/...`` URIs the way ROS does, without ROS.

A package is a directory with a ``package.xml`` naming it. Packages are found
(first match wins) in:

1. the directory of the model file and its parents (the file's own package),
2. the checkout's ``urdf/`` directory (package ``workbench_urdf``),
3. every directory on ``WORKBENCH_PACKAGE_PATH`` and then ``ROS_PACKAGE_PATH``
   (``os.pathsep``-separated), searched a few levels deep like rospack.
"""

from __future__ import annotations

import os
from functools import lru_cache
from pathlib import Path

from lxml import etree

from workbench.errors import ModelError
from workbench.model.robot_library import library_packages
from workbench.paths import urdf_dir

ENV_VARIABLES = ("WORKBENCH_PACKAGE_PATH", "ROS_PACKAGE_PATH")
_SEARCH_DEPTH = 3


class PackageNotFoundError(ModelError):
    """A ``package://`` URI names a package that is not on the search path."""


def package_name(package_xml: Path) -> str | None:
    """The ``<name>`` of a package.xml, or None when it has none or cannot be read."""
    try:
        root = etree.parse(str(package_xml)).getroot()
    except (OSError, etree.XMLSyntaxError):
        return None
    name = root.findtext("name")
    return name.strip() if name else None


def _own_package(start: Path) -> tuple[str, Path] | None:
    for directory in [start, *start.parents]:
        candidate = directory / "package.xml"
        if candidate.is_file():
            name = package_name(candidate)
            if name:
                return name, directory
            return None
    return None


@lru_cache(maxsize=32)
def _scan(directory: str, depth: int) -> tuple[tuple[str, str], ...]:
    found: list[tuple[str, str]] = []
    root = Path(directory)
    if not root.is_dir():
        return ()
    marker = root / "package.xml"
    if marker.is_file():
        name = package_name(marker)
        return ((name, directory),) if name else ()
    if depth <= 0:
        return ()
    try:
        children = sorted(child for child in root.iterdir() if child.is_dir())
    except OSError:
        return ()
    for child in children:
        if child.name.startswith("."):
            continue
        found.extend(_scan(str(child), depth - 1))
    return tuple(found)


class PackageResolver:
    """Maps package names to directories for one model file.

    Args:
        model_path: The model file; its own package (package.xml upwards) comes first.
    """

    def __init__(self, model_path: Path | None = None) -> None:
        self.packages: dict[str, Path] = {}
        if model_path is not None:
            own = _own_package(model_path.resolve().parent)
            if own:
                self.packages[own[0]] = own[1]
        checkout = urdf_dir()
        marker = checkout / "package.xml"
        if marker.is_file():
            name = package_name(marker)
            if name:
                self.packages.setdefault(name, checkout)
        for variable in ENV_VARIABLES:
            for entry in os.environ.get(variable, "").split(os.pathsep):
                if entry:
                    for name, directory in _scan(str(Path(entry).expanduser()), _SEARCH_DEPTH):
                        self.packages.setdefault(name, Path(directory))
        for library_name, library_dir in library_packages().items():
            self.packages.setdefault(library_name, library_dir)

    def resolve(
        self, uri: str, base_dir: Path | None, *, where: Path | None = None, line: int | None = None
    ) -> Path:
        """Turn a mesh/texture URI into a path (which may not exist).

        Handles ``package://``, ``file://``, absolute and relative paths
        (relative to ``base_dir``, the model file's directory).

        Raises:
            PackageNotFoundError: The package is unknown.
        """
        if uri.startswith("package://"):
            rest = uri[len("package://") :]
            name, _, relative = rest.partition("/")
            directory = self.packages.get(name)
            if directory is None:
                library = library_packages()
                known = ", ".join(sorted(n for n in self.packages if n not in library)) or "none"
                raise PackageNotFoundError(
                    f"unknown package '{name}' in {uri} (known packages: {known})",
                    path=where,
                    line=line,
                    hint="add the directory holding its package.xml to WORKBENCH_PACKAGE_PATH",
                )
            return directory / relative
        if uri.startswith("file://"):
            return Path(uri[len("file://") :])
        path = Path(uri)
        if not path.is_absolute() and base_dir is not None:
            path = base_dir / path
        return path

    def fill_package_map(self, package_map) -> None:
        """Add every known package to a pydrake ``PackageMap`` (names already there are kept)."""
        for name, directory in self.packages.items():
            if not package_map.Contains(name):
                package_map.Add(name, str(directory))
