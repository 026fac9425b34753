"""Finding the files benchmarks/corpus.py runs: what kind each is, in a folder of ROS packages.

Kinds (each with the workbench command benchmarks/corpus.py runs on it):

* ``launch``: ``*.launch``, and ``*.xml`` and ``*.machine`` whose root element is ``<launch>``;
* ``description``: ``*.urdf`` and ``*.xacro`` whose root element is ``<robot>``;
* ``world``: ``*.world``;
* ``model``: each Gazebo model folder (one with a ``model.config``), the SDF file
  its ``model.config`` names for the newest SDF version, as Gazebo picks it;
* ``srdf``: ``*.srdf``, with the robot description its MoveIt package's
  ``planning_context.launch`` loads;
* ``map``: ``*.yaml`` in map_server's format (``image`` and ``resolution`` keys);
* ``bag``: ``*.bag``;
* ``rviz``: ``*.rviz``.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

KINDS = ("launch", "description", "world", "model", "srdf", "map", "bag", "rviz")

#: Largest file sniffed for its root element or keys, bytes.
SNIFF_BYTES = 4 * 1024 * 1024


@dataclass(frozen=True)
class Item:
    """One file to run.

    Attributes:
        kind: One of :data:`KINDS`.
        path: The file.
        extra: A second file the command needs (the SRDF's robot description), or None.
    """

    kind: str
    path: Path
    extra: Path | None = None


def walk(root: Path) -> Iterator[Path]:
    """Every regular file under ``root``, sorted, skipping hidden folders."""
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for name in sorted(files):
            path = Path(folder) / name
            if path.is_file():
                yield path


def root_tag(path: Path) -> str | None:
    """The name of the root element of an XML file (None when it is not XML)."""
    try:
        if path.stat().st_size > SNIFF_BYTES:
            return None
        for _event, element in ET.iterparse(path, events=("start",)):
            return element.tag.rsplit("}", 1)[-1]
    except (ET.ParseError, OSError, UnicodeDecodeError):
        return None
    return None


_MAP_KEY = re.compile(r"^(image|resolution)\s*:", re.MULTILINE)


def is_map_yaml(path: Path) -> bool:
    """A map_server map description: top-level ``image:`` and ``resolution:`` keys."""
    try:
        if path.stat().st_size > SNIFF_BYTES:
            return False
        text = path.read_text(errors="replace")
    except OSError:
        return False
    return {m.group(1) for m in _MAP_KEY.finditer(text)} == {"image", "resolution"}


def _version(text: str) -> tuple[int, ...]:
    try:
        return tuple(int(part) for part in text.strip().split("."))
    except ValueError:
        return (0,)


def model_sdf(folder: Path) -> Path | None:
    """The SDF file of a Gazebo model folder: its model.config's newest ``<sdf>`` entry.

    Gazebo 11 reads SDF up to 1.7, so newer entries are passed over; a folder
    whose model.config names nothing usable falls back to ``model.sdf``.
    """
    config = folder / "model.config"
    try:
        tree = ET.parse(config)
    except (ET.ParseError, OSError):
        tree = None
    best: tuple[tuple[int, ...], Path] | None = None
    if tree is not None:
        for entry in tree.getroot().iter("sdf"):
            version = _version(entry.get("version", "0"))
            file = folder / (entry.text or "").strip()
            if version <= (1, 7) and file.is_file() and (best is None or version > best[0]):
                best = (version, file)
    if best is not None:
        return best[1]
    fallback = folder / "model.sdf"
    return fallback if fallback.is_file() else None


def package_index(root: Path) -> dict[str, Path]:
    """Package name -> folder, for every package.xml under ``root`` (the first one wins)."""
    index: dict[str, Path] = {}
    for path in walk(root):
        if path.name != "package.xml":
            continue
        try:
            match = re.search(r"<name>\s*([^<\s]+)\s*</name>", path.read_text(errors="replace"))
        except OSError:
            continue
        if match:
            index.setdefault(match.group(1), path.parent)
    return index


_FIND = re.compile(r"\$\(find ([\w-]+)\)(/[^'\"\s]+\.(?:urdf|xacro))")


def srdf_description(srdf: Path, packages: dict[str, Path]) -> Path | None:
    """The robot description an SRDF belongs to, from its MoveIt package's planning context.

    MoveIt's setup assistant writes ``launch/planning_context.launch`` beside
    ``config/ROBOT.srdf``; its ``robot_description`` parameter loads the URDF
    (``textfile=``) or the xacro (``command="xacro ..."``).
    """
    for folder in list(srdf.parents)[:3]:
        context = folder / "launch" / "planning_context.launch"
        if not context.is_file():
            continue
        for line in context.read_text(errors="replace").split("<param")[1:]:
            if "_semantic" in line.split(">", 1)[0]:
                continue
            for package, rest in _FIND.findall(line):
                if package in packages and (packages[package] / rest.lstrip("/")).is_file():
                    return packages[package] / rest.lstrip("/")
    return None


def discover(
    root: Path, models: Iterable[Path] = (), only: Iterable[str] | None = None
) -> list[Item]:
    """The files under ``root`` (and the Gazebo models under each of ``models``) by kind."""
    wanted = set(only or KINDS)
    items: list[Item] = []
    model_folders: list[Path] = []
    packages = package_index(root) if "srdf" in wanted else {}
    for path in walk(root):
        name = path.name
        if name == "model.config":
            model_folders.append(path.parent)
        elif name.endswith(".launch") or (
            name.endswith((".xml", ".machine"))
            and name != "package.xml"
            and root_tag(path) == "launch"
        ):
            items.append(Item("launch", path))
        elif name.endswith((".urdf", ".xacro")) and root_tag(path) == "robot":
            items.append(Item("description", path))
        elif name.endswith(".world"):
            items.append(Item("world", path))
        elif name.endswith(".srdf"):
            items.append(Item("srdf", path, srdf_description(path, packages)))
        elif name.endswith((".yaml", ".yml")) and is_map_yaml(path):
            items.append(Item("map", path))
        elif name.endswith(".bag"):
            items.append(Item("bag", path))
        elif name.endswith(".rviz"):
            items.append(Item("rviz", path))
    for folder in models:
        model_folders += [config.parent for config in sorted(folder.glob("*/model.config"))]
    seen: set[Path] = set()
    for folder in model_folders:
        sdf = model_sdf(folder)
        if sdf is not None and sdf.resolve() not in seen:
            seen.add(sdf.resolve())
            items.append(Item("model", sdf))
    return [item for item in items if item.kind in wanted]
