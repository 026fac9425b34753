"""A world file's ``<state>``: where Gazebo puts its models when it loads the world.

Worlds saved from Gazebo hold the models as first written plus a ``<state>``
with where everything was when the world was saved; Gazebo loads the models,
then applies the first state (later ones are ignored). Applied here:

* ``<model><pose>``: the model's pose in the world, which replaces where the
  world put it;
* ``<link><pose>`` of a link no joint moves: its pose in the world (read
  relative to the model's new pose);
* ``<joint><angle axis="0">``: the position of a 1-dof joint (revolute,
  prismatic, continuous, screw), rad or m;
* nested ``<model>`` states: the same for the links of a model inside a model
  (merged into it as ``NESTED::link``);
* ``<insertions>``: models added to the world; ``<deletions>``: models removed.

Velocities, accelerations, wrenches, lights and times are not applied. A state
for a model the world does not have is skipped with a warning, as Gazebo does.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from lxml import etree

from workbench.errors import SimulationError
from workbench.model.sdf_names import drake_name, shown_name

if TYPE_CHECKING:
    from workbench.sim.world_file import WorldFile, WorldModel

_LOG = logging.getLogger("workbench.sim")


def apply_state(state: Any, world: WorldFile, path: Path, version: str | None) -> None:
    """Apply a ``<state>`` element to the models read from a world file, in place.

    Raises:
        SimulationError: A pose or angle that is not finite numbers (file and line).
    """
    from workbench.sim.world_file import WorldModel, world_model

    insertions = state.find("insertions")
    if insertions is not None:
        for element in insertions.findall("model"):
            world.models.append(WorldModel(world_model(element, path, version)))
    deletions = state.find("deletions")
    if deletions is not None:
        gone = {(n.text or "").strip() for n in deletions.findall("name")}
        world.models = [m for m in world.models if m.model.name not in gone]
    by_name = {m.model.name: m for m in world.models}
    for element in state.findall("model"):
        name = element.get("name", "")
        item = by_name.get(name)
        if item is None:
            if name != "ground_plane":
                _LOG.warning(
                    "%s:%s: <state> of model '%s', which the world does not have: skipped",
                    path,
                    element.sourceline,
                    name,
                )
            continue
        _apply_model_state(element, item, path)


def _apply_model_state(element: Any, item: WorldModel, path: Path) -> None:
    from workbench.spatial import pose_matrix

    pose = element.find("pose")
    if pose is not None:
        values = _numbers(pose, path)
        item.pose = (values[0], values[1], values[2], values[3], values[4], values[5])
        item.model.pose = (0.0,) * 6
    own = item.model.pose
    X_WM = pose_matrix(item.pose[:3], rpy=item.pose[3:]) @ pose_matrix(own[:3], rpy=own[3:])
    root = etree.fromstring(item.model.text.encode())
    model = root.find("model")
    assert model is not None  # a SimModel of an SDF file holds one model
    moved = {(j.findtext("child") or "").strip() for j in model.findall("joint")}
    links = {link.get("name"): link for link in model.findall("link")}
    changed = False
    for prefix, link_state in _link_states(element, ""):
        link = links.get(drake_name(prefix + link_state.get("name", "")))
        pose = link_state.find("pose")
        if link is None or pose is None or link.get("name") in moved:
            continue
        values = _numbers(pose, path)
        X_WL = pose_matrix(values[:3], rpy=values[3:])
        _set_pose(link, np.linalg.solve(X_WM, X_WL))
        changed = True
    one_dof = {
        shown_name(j.get("name", ""))
        for j in model.findall("joint")
        if j.get("type") in ("revolute", "prismatic", "continuous", "screw")
    }
    for prefix, joint_state in _joint_states(element, ""):
        angle = joint_state.find("angle")
        name = prefix + joint_state.get("name", "")
        if angle is not None and angle.get("axis", "0") == "0" and name in one_dof:
            item.joint_positions[name] = _numbers(angle, path, count=1)[0]
    if changed:
        item.model.text = etree.tostring(root, encoding="unicode")


def _link_states(element: Any, prefix: str) -> list[tuple[str, Any]]:
    found = [(prefix, link) for link in element.findall("link")]
    for nested in element.findall("model"):
        found += _link_states(nested, f"{prefix}{nested.get('name', '')}::")
    return found


def _joint_states(element: Any, prefix: str) -> list[tuple[str, Any]]:
    found = [(prefix, joint) for joint in element.findall("joint")]
    for nested in element.findall("model"):
        found += _joint_states(nested, f"{prefix}{nested.get('name', '')}::")
    return found


def _set_pose(link: Any, X_ML: np.ndarray) -> None:
    from workbench.spatial import xyz_rpy_from_matrix

    pose = link.find("pose")
    if pose is None:
        pose = etree.Element("pose")
        link.insert(0, pose)
    for key in ("relative_to", "frame", "rotation_format", "degrees"):
        pose.attrib.pop(key, None)
    xyz, rpy = xyz_rpy_from_matrix(X_ML)
    pose.text = " ".join(f"{v:.17g}" for v in (*xyz, *rpy))


def _numbers(element: Any, path: Path, count: int = 6) -> list[float]:
    text = (element.text or "").strip()
    try:
        values = [float(v) for v in text.split()]
    except ValueError:
        values = []
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise SimulationError(
            f"<state>: <{element.tag}> must be {count} finite number"
            f"{'s' if count > 1 else ''}, got '{text}'",
            path=path,
            line=element.sourceline,
        )
    return values
