"""Well-known robots by name from a maintained description package installed with pip.

PyPI's ``example-robot-data`` (BSD-3-Clause, the Gepetto team's collection)
installs URDFs, SRDFs and meshes of about forty robots, the Franka Emika Panda
among them, under ``site-packages/cmeel.prefix/share/example-robot-data``. Its
URDFs name their meshes ``package://example-robot-data/robots/...``; the
package.xml beside them calls itself ``example_robot_descriptions``, so both
names map to that folder. workbench's extra ``[robots]`` installs it (with
pycollada for the ``.dae`` visual meshes).
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

#: The pip distribution holding the descriptions.
DISTRIBUTION = "example-robot-data"
#: Where it puts them, relative to its installation prefix.
SHARE = "cmeel.prefix/share/example-robot-data"
#: The package names its URDFs and package.xml use for that folder.
PACKAGE_NAMES = ("example-robot-data", "example_robot_descriptions")
#: What a user installs to get them.
INSTALL_HINT = 'pip install -e ".[robots]" (or pip install example-robot-data pycollada)'


@lru_cache(maxsize=1)
def library_root() -> Path | None:
    """The installed ``share/example-robot-data`` folder, or None when it is not installed."""
    from importlib.metadata import PackageNotFoundError, distribution

    try:
        root = Path(str(distribution(DISTRIBUTION).locate_file(SHARE)))
    except PackageNotFoundError:
        return None
    return root if (root / "robots").is_dir() else None


@lru_cache(maxsize=1)
def library_robots() -> dict[str, Path]:
    """Robot name to URDF: each ``robots/*/urdf/<name>.urdf`` by its stem (``panda``,
    ``ur5_robot``), and ``<x>_robot`` also as ``<x>`` (``ur5``)."""
    root = library_root()
    if root is None:
        return {}
    found: dict[str, Path] = {}
    for urdf in sorted((root / "robots").glob("*/urdf/*.urdf")):
        found.setdefault(urdf.stem, urdf)
    for name, urdf in list(found.items()):
        if name.endswith("_robot"):
            found.setdefault(name.removesuffix("_robot"), urdf)
    return dict(sorted(found.items()))


def library_robot(name: str) -> Path | None:
    """The URDF of robot ``name`` in the library, or None."""
    return library_robots().get(name)


def library_srdf(urdf: Path) -> Path | None:
    """The SRDF shipped beside a library URDF (``../srdf/<stem>.srdf``), or None."""
    root = library_root()
    if root is None or root not in urdf.resolve().parents:
        return None
    srdf = urdf.resolve().parent.parent / "srdf" / f"{urdf.stem}.srdf"
    return srdf if srdf.is_file() else None


def library_packages() -> dict[str, Path]:
    """Package names to folders, for ``package://`` URIs in the library's files."""
    root = library_root()
    return {name: root for name in PACKAGE_NAMES} if root is not None else {}
