"""ROS packages by name, found as ``rospack`` finds them, then workbench's own.

A package is a folder holding a ``package.xml`` whose ``<name>`` names it.
``$(find NAME)`` in launch files and xacro, ``package://NAME/...`` in models,
``workbench launch NAME FILE`` and ``workbench run NAME EXE`` all look a name
up here, in this order (the first folder found wins):

1. every folder on ``WORKBENCH_PACKAGE_PATH``, then on ``ROS_PACKAGE_PATH``
   (``os.pathsep``-separated, in order), crawled as rospkg crawls them: all
   the way down, a package's folder not entered further, ``CATKIN_IGNORE``
   and ``rospack_nosubdirs`` honoured, hidden folders skipped, metapackages
   (``<export><metapackage/>``) not packages;
2. the workspace of the file that asks (``near``): its own package and the
   packages beside it, so a launch file run by its path finds its siblings;
   then, when the working directory is inside a package, that package's workspace;
3. the packages workbench ships: ``urdf/`` (``workbench_urdf``), ``mapping/``
   (``workbench_maps``), ``examples/packages/*`` (the ROS packages the labs
   name, emulated: ``gazebo_ros``, ``turtlebot3_gazebo`` ...) and the lab's
   own packages in ``examples/`` (``learning_tf``).

So a user's real package of the same name shadows the emulated one, as an
overlay workspace does in catkin. :func:`locate_package` says which folder was
chosen and what it shadows. Only the standard library and lxml are used.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from workbench.errors import WorkbenchError

#: The variables searched first, in this order.
ENV_VARIABLES = ("WORKBENCH_PACKAGE_PATH", "ROS_PACKAGE_PATH")
#: Largest package.xml read, bytes (a FIFO or a huge file named package.xml is no package).
PACKAGE_XML_BYTES = 1024 * 1024
#: Most folders one crawl of a path entry visits (a home folder on the path must not hang us).
MAX_FOLDERS = 200_000
#: How far above a file its workspace is looked for (its package, then ``src/``).
NEAR_LEVELS = 4

ORIGIN_SHIPPED = "shipped with workbench"
ORIGIN_EMULATED = "emulated by workbench"


class PackageLookupError(WorkbenchError):
    """No package of that name is on the search path."""


@dataclass(frozen=True)
class PackageLocation:
    """Where a package was found.

    Attributes:
        name: The package's name.
        path: Its folder.
        origin: Where it was found: ``ROS_PACKAGE_PATH``, ``WORKBENCH_PACKAGE_PATH``,
            ``beside <folder>``, ``beside the working directory``, ``shipped with workbench``
            (its own data) or ``emulated by workbench`` (a ROS package the labs name).
        shadows: Folders of the same name further down the search order.
    """

    name: str
    path: Path
    origin: str
    shadows: tuple[Path, ...] = field(default=())


def read_package_xml(path: Path) -> tuple[str, bool] | None:
    """``(name, is_metapackage)`` of a package.xml, or None when it is unreadable or nameless."""
    from lxml import etree

    try:
        if not path.is_file() or path.stat().st_size > PACKAGE_XML_BYTES:
            return None
        parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)
        root = etree.parse(str(path), parser).getroot()
    except (OSError, etree.XMLSyntaxError, ValueError):
        return None
    name = (root.findtext("name") or "").strip()
    if not name:
        return None
    return name, root.find("export/metapackage") is not None


def package_name(package_xml: Path) -> str | None:
    """The ``<name>`` of a package.xml, or None when it has none or cannot be read."""
    found = read_package_xml(package_xml)
    return found[0] if found else None


@lru_cache(maxsize=64)
def crawl(root: str) -> tuple[tuple[str, str], ...]:
    """The ``(name, folder)`` of every package below ``root``, as rospkg lists them.

    Folders are visited in sorted order (rospkg's order is the file system's), links are
    followed once (a link back up the tree is not a loop), at most :data:`MAX_FOLDERS`.
    """
    found: list[tuple[str, str]] = []
    names: set[str] = set()
    seen: set[str] = set()
    stack = [Path(root).expanduser()]
    visited = 0
    while stack and visited < MAX_FOLDERS:
        folder = stack.pop()
        try:
            real = os.path.realpath(folder)
            if real in seen or not folder.is_dir():
                continue
            seen.add(real)
            visited += 1
            entries = sorted(os.scandir(folder), key=lambda e: e.name)
        except OSError:
            continue
        files = {e.name for e in entries if not _is_dir(e)}
        if "CATKIN_IGNORE" in files:
            continue
        if "package.xml" in files:
            package = read_package_xml(folder / "package.xml")
            if package is not None and not package[1]:
                if package[0] not in names:
                    names.add(package[0])
                    found.append((package[0], str(folder)))
                continue
        if "rospack_nosubdirs" in files:
            continue
        children = [folder / e.name for e in entries if _is_dir(e) and not e.name.startswith(".")]
        stack.extend(reversed(children))
    return tuple(found)


def _is_dir(entry: os.DirEntry[str]) -> bool:
    try:
        return entry.is_dir()
    except OSError:
        return False


def _path_entries() -> Iterator[tuple[str, str]]:
    for variable in ENV_VARIABLES:
        for entry in os.environ.get(variable, "").split(os.pathsep):
            if entry.strip():
                yield variable, entry.strip()


def _near_workspace(near: Path, *, below: bool = True) -> Iterator[tuple[str, Path]]:
    """The packages of the workspace around ``near``: its own package, then those beside it
    (and in the folder above, a workspace's ``src``); with no package around, those below
    ``near`` when ``below``."""
    levels = [near] if below else []
    for directory in [near, *near.parents][:NEAR_LEVELS]:
        package = read_package_xml(directory / "package.xml")
        if package is not None and not package[1]:
            yield package[0], directory
            levels = [directory.parent, directory.parent.parent]
            break
    for level in levels:
        for name, folder in _shallow(str(level)):
            yield name, Path(folder)


@lru_cache(maxsize=64)
def _shallow(parent: str) -> tuple[tuple[str, str], ...]:
    """Packages one or two levels below ``parent`` (a workspace's ``src`` and its repositories)."""
    found: list[tuple[str, str]] = []
    root = Path(parent)
    try:
        children = sorted(c for c in root.iterdir() if c.is_dir() and not c.name.startswith("."))
    except OSError:
        return ()
    for child in children:
        package = read_package_xml(child / "package.xml")
        if package is not None:
            if not package[1]:
                found.append((package[0], str(child)))
            continue
        try:
            grandchildren = sorted(g for g in child.iterdir() if g.is_dir())
        except OSError:
            continue
        for grandchild in grandchildren:
            package = read_package_xml(grandchild / "package.xml")
            if package is not None and not package[1]:
                found.append((package[0], str(grandchild)))
    return tuple(found)


def shipped_packages() -> dict[str, tuple[Path, str]]:
    """The packages workbench ships, with their origin: its own data (``urdf/``,
    ``mapping/``), the ROS packages the labs name, emulated (``examples/packages/*``), and
    the lab's own packages (``examples/*``)."""
    from workbench.paths import examples_dir, mapping_dir, urdf_dir

    return dict(_shipped(str(urdf_dir()), str(mapping_dir()), str(examples_dir())))


@lru_cache(maxsize=8)
def _shipped(urdf: str, mapping: str, examples: str) -> dict[str, tuple[Path, str]]:
    found: dict[str, tuple[Path, str]] = {}
    for folder in (Path(urdf), Path(mapping)):
        name = package_name(folder / "package.xml")
        if name:
            found.setdefault(name, (folder, ORIGIN_SHIPPED))
    for name, folder in _shallow(str(Path(examples) / "packages")):
        found.setdefault(name, (Path(folder), ORIGIN_EMULATED))
    for name, folder in _shallow(examples):  # the lab's own (learning_tf)
        found.setdefault(name, (Path(folder), ORIGIN_SHIPPED))
    return found


def candidates(near: Path | None = None) -> Iterator[tuple[str, Path, str]]:
    """Every ``(name, folder, origin)`` in search order (names may repeat: first wins)."""
    for variable, entry in _path_entries():
        for name, folder in crawl(entry):
            yield name, Path(folder), variable
    if near is not None:
        for name, folder in _near_workspace(near):
            yield name, folder, f"beside {near}"
    cwd = _working_directory()
    if cwd is not None and cwd != near:
        for name, folder in _near_workspace(cwd, below=False):
            yield name, folder, "beside the working directory"
    for name, (folder, origin) in shipped_packages().items():
        yield name, folder, origin


def _working_directory() -> Path | None:
    try:
        return Path.cwd()
    except OSError:  # the working directory was deleted
        return None


def locate_package(name: str, near: Path | None = None) -> PackageLocation:
    """Where package ``name`` is, what found it, and what it shadows.

    Args:
        name: The package name.
        near: A folder asking (a launch file's folder): its workspace is searched
            after the path variables and before workbench's own packages.

    Raises:
        PackageLookupError: No package of that name is on the search path.
    """
    chosen: tuple[Path, str] | None = None
    shadowed: list[Path] = []
    for found, folder, origin in candidates(near):
        if found != name:
            continue
        if chosen is None:
            chosen = (folder, origin)
        elif folder.resolve() != chosen[0].resolve() and folder not in shadowed:
            shadowed.append(folder)
    if chosen is None:
        path_text = ", ".join(f"{v}={os.environ[v]}" for v in ENV_VARIABLES if os.environ.get(v))
        raise PackageLookupError(
            f"package '{name}' not found (searched {path_text or 'no ROS_PACKAGE_PATH'}, "
            "then workbench's own packages)",
            hint="add the folder holding it (or its workspace's src/) to ROS_PACKAGE_PATH",
        )
    return PackageLocation(name, chosen[0], chosen[1], tuple(shadowed))


def find_package(name: str, near: Path | None = None) -> Path:
    """The folder of package ``name`` (see the module docstring for the order).

    Raises:
        PackageLookupError: Not found.
    """
    for found, folder, _ in candidates(near):
        if found == name:
            return folder  # the first one: what it shadows is not looked for
    return locate_package(name, near).path  # raises the error naming the search path


def all_packages(near: Path | None = None) -> dict[str, PackageLocation]:
    """Every package name on the search path with where it is found (first wins)."""
    found: dict[str, PackageLocation] = {}
    for name, folder, origin in candidates(near):
        found.setdefault(name, PackageLocation(name, folder, origin))
    return found
