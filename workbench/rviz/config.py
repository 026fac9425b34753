"""RViz's ``.rviz`` configuration files (YAML): the fixed frame and the display list.

Read: ``Visualization Manager`` → ``Global Options`` → ``Fixed Frame``,
``Displays`` (each with ``Class``, ``Name``, ``Enabled`` and, per class, its
topic: ``Topic``, ``Marker Topic``, or ``Robot Description``; a Map's ``Color
Scheme`` and ``Alpha``; the ``Color`` and ``Alpha`` of Path, PoseArray and
Polygon) and ``Tools`` (``rviz/SetInitialPose`` and ``rviz/SetGoal`` with their
``Topic`` and standard deviations). Displays of classes workbench does not draw
are listed in one warning and skipped; a file that is not YAML or not an RViz
config is a one-line error.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.errors import ViewerError
from workbench.rviz.pose_tools import TOOL_LABELS, ToolSettings


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
        ViewerError: Missing, not YAML, or without ``Visualization Manager``.
    """
    import yaml

    from workbench.rviz.rviz import DISPLAY_CLASSES

    file = Path(path)
    try:
        data = yaml.safe_load(file.read_text(encoding="utf-8"))
    except OSError as error:
        raise ViewerError(f"cannot read the RViz config: {error.strerror}", path=file) from None
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        raise ViewerError(
            f"not YAML: {getattr(error, 'problem', None) or error}",
            path=file,
            line=mark.line + 1 if mark is not None else None,
        ) from None
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
    for entry in _flatten(manager.get("Displays") or []):
        class_name = str(entry.get("Class", "")).split("/")[-1]
        name = str(entry.get("Name", class_name))
        if class_name not in DISPLAY_CLASSES:
            unknown.append(f"{name} ({entry.get('Class', '?')})")
            continue
        try:
            options = _options(class_name, entry)
        except (TypeError, ValueError) as error:
            raise ViewerError(f"display '{name}': {error}", path=file) from None
        displays.append(DisplaySpec(class_name, name, bool(entry.get("Enabled", True)), options))
    tools = _tools(manager.get("Tools"), file)
    return RvizConfig(str(fixed) if fixed else None, displays, unknown, tools)


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
    return settings


def _number(value: Any, where: str, file: Path) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ViewerError(f"{where} is not a number: {value!r}", path=file) from None


def _colour(value: Any, default: tuple[float, float, float]) -> tuple[float, float, float]:
    """RViz's ``"r; g; b"`` (0-255) as floats in [0, 1] (the default when unreadable)."""
    parts = str(value).split(";")
    try:
        rgb = tuple(min(max(float(p) / 255.0, 0.0), 1.0) for p in parts)
    except ValueError:
        return default
    return (rgb[0], rgb[1], rgb[2]) if len(rgb) == 3 else default


def _flatten(entries: Any) -> list[dict[str, Any]]:
    """Displays, with those inside RViz's display groups."""
    flat: list[dict[str, Any]] = []
    for entry in entries if isinstance(entries, list) else []:
        if not isinstance(entry, dict):
            continue
        if str(entry.get("Class", "")).endswith("/Group"):
            flat += _flatten(entry.get("Displays") or [])
        else:
            flat.append(entry)
    return flat


def _options(class_name: str, entry: dict[str, Any]) -> dict[str, Any]:
    if class_name == "Marker":
        return {"topic": entry.get("Marker Topic", "visualization_marker")}
    if class_name == "InteractiveMarkers":
        topic = str(entry.get("Update Topic", "basic_controls/update"))
        return {"topic": topic.rsplit("/update", 1)[0]}
    if class_name == "RobotModel":
        return {"param": entry.get("Robot Description", "robot_description")}
    if class_name == "Grid":
        return {
            "cells": int(entry.get("Plane Cell Count", 10)),
            "cell_size": float(entry.get("Cell Size", 1.0)),
        }
    if class_name == "TF":
        return {"scale": 0.3 * float(entry.get("Marker Scale", 1.0))}
    if class_name == "Axes":
        return {
            "frame": str(entry.get("Reference Frame", "") or "").replace("<Fixed Frame>", ""),
            "length": float(entry.get("Length", 1.0)),
        }
    options: dict[str, Any] = {"topic": entry["Topic"]} if "Topic" in entry else {}
    if class_name == "Map":
        options["color_scheme"] = str(entry.get("Color Scheme", "map"))
        options["alpha"] = float(entry.get("Alpha", 0.7))
    if class_name in ("Path", "PoseArray", "Polygon"):
        from workbench.rviz.rviz import DISPLAY_CLASSES

        default = DISPLAY_CLASSES[class_name].default_color  # type: ignore[attr-defined]
        options["color"] = _colour(entry.get("Color", ""), default)
        options["alpha"] = float(entry.get("Alpha", 1.0))
    if class_name == "PoseArray" and "Arrow Length" in entry:
        options["arrow_length"] = float(entry["Arrow Length"])
    return options
