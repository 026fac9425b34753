"""RViz's ``.rviz`` configuration files (YAML): the fixed frame and the display list.

Read: ``Visualization Manager`` → ``Global Options`` → ``Fixed Frame`` and
``Displays`` (each with ``Class``, ``Name``, ``Enabled`` and, per class, its
topic: ``Topic``, ``Marker Topic``, or ``Robot Description``). Displays of
classes workbench does not draw are listed in one warning and skipped; a file
that is not YAML or not an RViz config is a one-line error.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.errors import ViewerError


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
        displays.append(
            DisplaySpec(
                class_name, name, bool(entry.get("Enabled", True)), _options(class_name, entry)
            )
        )
    return RvizConfig(str(fixed) if fixed else None, displays, unknown)


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
    if "Topic" in entry:
        return {"topic": entry["Topic"]}
    return {}
