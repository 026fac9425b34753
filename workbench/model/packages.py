"""Resolve ``package://NAME/...`` URIs the way ROS does, without ROS.

Package names are looked up as :mod:`workbench.ros_packages` does (the same
order as ``$(find NAME)`` in launch files): ``WORKBENCH_PACKAGE_PATH`` and
``ROS_PACKAGE_PATH`` first, then the workspace around the model file, then
workbench's own packages (``urdf/`` is ``workbench_urdf``), then the robot
descriptions of example-robot-data when it is installed.
"""

from __future__ import annotations

from pathlib import Path

from workbench.errors import ModelError
from workbench.model.robot_library import library_packages
from workbench.ros_packages import ORIGIN_EMULATED, all_packages, package_name

__all__ = ["PackageNotFoundError", "PackageResolver", "package_name"]


class PackageNotFoundError(ModelError):
    """A ``package://`` URI names a package that is not on the search path."""


class PackageResolver:
    """Maps package names to directories for one model file.

    Args:
        model_path: The model file; its own package (package.xml upwards) comes first.
    """

    def __init__(self, model_path: Path | None = None) -> None:
        near = model_path.resolve().parent if model_path is not None else None
        found = all_packages(near)
        self.packages: dict[str, Path] = {name: location.path for name, location in found.items()}
        #: The names a user's files can mean (not the ROS packages workbench emulates).
        self.known = sorted(n for n, at in found.items() if at.origin != ORIGIN_EMULATED)
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
                known = ", ".join(self.known) or "none"
                raise PackageNotFoundError(
                    f"unknown package '{name}' in {uri} (known packages: {known})",
                    path=where,
                    line=line,
                    hint="add the folder holding its package.xml to ROS_PACKAGE_PATH",
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
