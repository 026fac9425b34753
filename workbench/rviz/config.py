"""RViz's ``.rviz`` configuration files (YAML): the fixed frame and the display list.

Read: ``Visualization Manager`` → ``Global Options`` → ``Fixed Frame``,
``Displays`` (each with ``Class``, ``Name``, ``Enabled`` and, per class, its
topic: ``Topic``, ``Marker Topic``, or ``Robot Description``; a Map's ``Color
Scheme`` and ``Alpha``; the ``Color`` and ``Alpha`` of Path, PoseArray and
Polygon) and ``Tools`` (``rviz/SetInitialPose`` and ``rviz/SetGoal`` with their
``Topic`` and standard deviations). Displays of classes workbench does not draw
are listed in one warning and skipped; a file that is not YAML or not an RViz
config is a one-line error.

A config is read within bounds (:data:`MAX_CONFIG_BYTES`, :data:`CONFIG_LIMITS`,
:data:`MAX_DISPLAYS`, :data:`MAX_GROUP_DEPTH`, and the Grid's
:data:`~workbench.rviz.displays.MAX_GRID_CELLS`): the YAML is checked event by event
before anything is built, so an alias bomb, a huge file or a display list of
thousands is one line naming the file, and every number is checked (finite, in
range) before a display is made from it.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.errors import ViewerError
from workbench.limits import MiB, TreeLimits, load_yaml, read_text_bounded
from workbench.rviz.pose_tools import TOOL_LABELS, ToolSettings

#: Largest ``.rviz`` file read, bytes (RViz's own are a few KiB).
MAX_CONFIG_BYTES = 1 * MiB
#: Bounds of the YAML inside, after alias expansion.
CONFIG_LIMITS = TreeLimits(max_depth=64, max_nodes=50_000, max_bytes=4 * MiB)
#: Most displays a config may list, those inside groups included.
MAX_DISPLAYS = 500
#: Most display groups nested in one another.
MAX_GROUP_DEPTH = 16
#: Longest display name quoted in a message.
_NAME_SHOWN = 60


@dataclass
class DisplaySpec:
    """One display of a config: RViz class name (without ``rviz/``), name, options."""

    class_name: str
    name: str
    enabled: bool = True
    options: dict[str, Any] = field(default_factory=dict)


@dataclass
class RvizConfig:
    """What workbench uses of an ``.rviz`` file."""

    fixed_frame: str | None
    displays: list[DisplaySpec]
    unknown: list[str]
    tools: ToolSettings = field(default_factory=ToolSettings)


def load_config(path: str | os.PathLike[str]) -> RvizConfig:
    """Read an ``.rviz`` file.

    Raises:
        ViewerError: Missing, not a regular UTF-8 file, too large, not YAML, past a bound,
            without ``Visualization Manager``, or a display option out of range.
    """
    from workbench.rviz.rviz import DISPLAY_CLASSES

    file = Path(path)
    text = read_text_bounded(file, ".rviz config", ViewerError, MAX_CONFIG_BYTES)
    data = load_yaml(text, ".rviz config", CONFIG_LIMITS, ViewerError, file)
    manager = data.get("Visualization Manager") if isinstance(data, dict) else None
    if not isinstance(manager, dict):
        raise ViewerError(
            "not an RViz config: no 'Visualization Manager' section",
            path=file,
            hint="save one from RViz (File > Save Config) or start from the README's example",
        )
    options = manager.get("Global Options") or {}
    fixed = options.get("Fixed Frame") if isinstance(options, dict) else None
    displays: list[DisplaySpec] = []
    unknown: list[str] = []
    for entry in _flatten(manager.get("Displays") or [], file):
        class_name = str(entry.get("Class", "")).split("/")[-1]
        name = str(entry.get("Name", class_name))
        if class_name not in DISPLAY_CLASSES:
            unknown.append(f"{_shown(name)} ({_shown(str(entry.get('Class', '?')))})")
            continue
        try:
            options = _options(class_name, entry)
        except (TypeError, ValueError) as error:
            raise ViewerError(f"display '{_shown(name)}': {error}", path=file) from None
        _check_names(options, f"display '{_shown(name)}'", file)
        try:  # what the display itself refuses, with the file named
            DISPLAY_CLASSES[class_name](name=name, **options)
        except ViewerError as error:
            raise ViewerError(error.message, path=file, hint=error.hint) from None
        displays.append(DisplaySpec(class_name, name, bool(entry.get("Enabled", True)), options))
    tools = _tools(manager.get("Tools"), file)
    return RvizConfig(str(fixed) if fixed else None, displays, unknown, tools)


def _shown(text: str) -> str:
    """``text`` cut to a length a message can quote."""
    return text if len(text) <= _NAME_SHOWN else text[: _NAME_SHOWN - 3] + "..."


def _tools(entries: Any, file: Path) -> ToolSettings:
    """The pose tools a ``Tools:`` list names (none when it names none; both without one)."""
    settings = ToolSettings()
    if not isinstance(entries, list):
        return settings
    present = []
    for entry in entries:
        if not isinstance(entry, dict):
            continue
        tool = str(entry.get("Class", "")).split("/")[-1]
        if tool not in TOOL_LABELS:
            continue
        present.append(tool)
        if tool == "SetGoal":
            settings.goal_topic = str(entry.get("Topic", "goal"))  # GoalTool's own default
            continue
        settings.initial_pose_topic = str(entry.get("Topic", settings.initial_pose_topic))
        for key, attribute in (
            ("X std deviation", "std_dev_x"),
            ("Y std deviation", "std_dev_y"),
            ("Theta std deviation", "std_dev_theta"),
        ):
            if key in entry:
                setattr(settings, attribute, _number(entry[key], f"Tools: {tool}: {key}", file))
    settings.tools = tuple(present)
    _check_names(
        {"topic": settings.goal_topic, "pose topic": settings.initial_pose_topic}, "Tools", file
    )
    return settings


def _check_names(options: dict[str, Any], where: str, file: Path) -> None:
    """Refuse topic and parameter names the bus would refuse (before the viewer joins it).

    Raises:
        ViewerError: A name that is not a legal ROS name.
    """
    from workbench.bus.names import check_name
    from workbench.errors import WorkbenchError

    for key, value in options.items():
        if key in ("topic", "pose topic", "param") and value:
            what = "parameter name" if key == "param" else "topic name"
            try:
                check_name(value, what)
            except WorkbenchError as error:
                raise ViewerError(f"{where}: {error.message}", path=file, hint=error.hint) from None


def _number(value: Any, where: str, file: Path) -> float:
    try:
        number = _finite(value, where)
    except ValueError as error:
        raise ViewerError(str(error), path=file) from None
    if number < 0:
        raise ViewerError(f"{where} must be 0 or more, not {number:g}", path=file)
    return number


def _finite(value: Any, key: str, low: float | None = None) -> float:
    """``value`` as a finite number (at least ``low``).

    Raises:
        ValueError: Not a number, NaN, infinite, or below ``low``.
    """
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise ValueError(f"{key} is not a number: {_shown(repr(value))}")
    try:
        number = float(value)
    except (ValueError, OverflowError):
        raise ValueError(f"{key} is not a number: {_shown(repr(value))}") from None
    if not math.isfinite(number):
        raise ValueError(f"{key} must be a finite number, not {number}")
    if low is not None and number < low:
        raise ValueError(f"{key} must be at least {low:g}, not {number:g}")
    return number


def _alpha(value: Any, key: str = "Alpha") -> float:
    """RViz's alpha: a finite number, kept in [0, 1] as RViz's property does."""
    return min(max(_finite(value, key), 0.0), 1.0)


def _cells(value: Any) -> int:
    """A Grid's ``Plane Cell Count``: a whole number from 1 to ``MAX_GRID_CELLS``."""
    from workbench.rviz.displays import MAX_GRID_CELLS

    number = _finite(value, "Plane Cell Count")
    if number != int(number) or not 1 <= number <= MAX_GRID_CELLS:
        raise ValueError(
            f"Plane Cell Count must be a whole number from 1 to {MAX_GRID_CELLS:,}, "
            f"not {int(number):,}"
            if number == int(number)
            else f"Plane Cell Count must be a whole number, not {number:g}"
        )
    return int(number)


def _colour(value: Any, default: tuple[float, float, float]) -> tuple[float, float, float]:
    """RViz's ``"r; g; b"`` (0-255) as floats in [0, 1] (the default when unreadable)."""
    parts = str(value).split(";", 3)
    try:
        numbers = [float(p) for p in parts]
    except ValueError:
        return default
    if len(numbers) != 3 or not all(math.isfinite(n) for n in numbers):
        return default
    rgb = [min(max(n / 255.0, 0.0), 1.0) for n in numbers]
    return (rgb[0], rgb[1], rgb[2])


def _flatten(entries: Any, file: Path) -> list[dict[str, Any]]:
    """Displays, with those inside RViz's display groups, in order (without recursion).

    Raises:
        ViewerError: More than :data:`MAX_DISPLAYS` displays, or groups nested more than
            :data:`MAX_GROUP_DEPTH` deep.
    """
    flat: list[dict[str, Any]] = []
    # (the list, where in it, the depth of groups around it)
    stack: list[tuple[list[Any], int, int]] = [(entries if isinstance(entries, list) else [], 0, 0)]
    count = 0
    while stack:
        items, at, depth = stack.pop()
        if at >= len(items):
            continue
        stack.append((items, at + 1, depth))
        entry = items[at]
        if not isinstance(entry, dict):
            continue
        count += 1
        if count > MAX_DISPLAYS:
            raise ViewerError(
                f"the config lists more than {MAX_DISPLAYS} displays",
                path=file,
                hint="is it the right file? RViz's own configs have a few dozen",
            )
        if str(entry.get("Class", "")).endswith("/Group"):
            if depth + 1 > MAX_GROUP_DEPTH:
                name = _shown(str(entry.get("Name", "Group")))
                raise ViewerError(
                    f"display group '{name}' is nested more than {MAX_GROUP_DEPTH} groups deep",
                    path=file,
                    hint="flatten the groups",
                )
            inner = entry.get("Displays") or []
            stack.append((inner if isinstance(inner, list) else [], 0, depth + 1))
        else:
            flat.append(entry)
    return flat


def _options(class_name: str, entry: dict[str, Any]) -> dict[str, Any]:
    """The display's constructor arguments from its entry.

    Raises:
        ValueError: A number that is not finite or out of range.
    """
    if class_name == "Marker":
        return {"topic": str(entry.get("Marker Topic", "visualization_marker"))}
    if class_name == "InteractiveMarkers":
        topic = str(entry.get("Update Topic", "basic_controls/update"))
        return {"topic": topic.rsplit("/update", 1)[0]}
    if class_name == "RobotModel":
        return {"param": str(entry.get("Robot Description", "robot_description"))}
    if class_name == "Grid":
        return {
            "cells": _cells(entry.get("Plane Cell Count", 10)),
            "cell_size": _positive(entry.get("Cell Size", 1.0), "Cell Size"),
        }
    if class_name == "TF":
        return {"scale": 0.3 * _finite(entry.get("Marker Scale", 1.0), "Marker Scale", 0.0)}
    if class_name == "Axes":
        return {
            "frame": str(entry.get("Reference Frame", "") or "").replace("<Fixed Frame>", ""),
            "length": _finite(entry.get("Length", 1.0), "Length", 0.0),
        }
    options: dict[str, Any] = {"topic": str(entry["Topic"])} if "Topic" in entry else {}
    if class_name == "Map":
        options["color_scheme"] = str(entry.get("Color Scheme", "map"))
        options["alpha"] = _alpha(entry.get("Alpha", 0.7))
    if class_name in ("Path", "PoseArray", "Polygon"):
        from workbench.rviz.rviz import DISPLAY_CLASSES

        default = DISPLAY_CLASSES[class_name].default_color  # type: ignore[attr-defined]
        options["color"] = _colour(entry.get("Color", ""), default)
        options["alpha"] = _alpha(entry.get("Alpha", 1.0))
    if class_name == "PoseArray" and "Arrow Length" in entry:
        options["arrow_length"] = _finite(entry["Arrow Length"], "Arrow Length", 0.0)
    return options


def _positive(value: Any, key: str) -> float:
    number = _finite(value, key)
    if number <= 0:
        raise ValueError(f"{key} must be above 0, not {number:g}")
    return number
