"""Models inside models, flattened into one model as Gazebo 11 reads them.

An ``<include>`` inside a ``<model>`` is replaced by the model it names (found
through :mod:`workbench.model.gazebo_models`), with the include's ``<name>``,
``<pose>`` (it replaces the model's own), ``<static>`` and ``<plugin>``
elements applied. Then every nested ``<model>`` (included or written inline)
is merged into its parent, as Gazebo's SDFormat 9 merges an included model:
its links, joints and frames are renamed ``NESTED::NAME``, the nested
model's pose is composed into its links' and frames' poses, joint axes given
in the nested model's frame are turned into the parent's, and its plugins move
to the parent with the names they mention renamed alike. A nested model
written inline keeps its own ``<static>`` (Gazebo loads it as a model of its
own); an included one takes its parent's (Gazebo merges it into the parent).

A joint that shares its name with a link (SDFormat before 1.7 allows it) gets
the mark of :mod:`workbench.model.sdf_names` so Drake accepts it; its name
stays the file's. Names use Gazebo's ``::`` here; :func:`drake_names` turns
them into the names Drake is given.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from lxml import etree

from workbench.errors import ModelError
from workbench.model.limits import MAX_LINKS, MAX_MODEL_BYTES, check_input_file
from workbench.model.sdf_names import JOINT_MARK, drake_name, shown_name

#: Deepest chain of models including models.
MAX_INCLUDE_DEPTH = 16
#: Elements that name a frame of the model (a link, joint or frame).
_FRAMES = ("link", "joint", "frame")
#: Attributes that refer to a frame by name.
_REFERENCES = ("relative_to", "attached_to", "expressed_in", "canonical_link")
#: Marks an axis given in its model's frame while files of several versions are merged.
_IN_MODEL = "__in_model__"
#: Elements of a nested model that belong to it alone and are dropped when it is merged.
_DROPPED = ("pose", "static", "self_collide", "allow_auto_disable", "enable_wind", "name")


@dataclass
class Nesting:
    """What flattening found, for the simulator.

    Attributes:
        static_links: Links of inline nested models, by their flattened name, and
            whether their model is static (their roots are welded or free by it).
        warnings: One line per name that was changed so Drake accepts it.
        files: Files that were included, in the order they were read.
        version: The newest SDFormat version among the files: the flattened model is
            written in it (axes and poses said the way it says them).
    """

    static_links: dict[str, bool] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    files: list[Path] = field(default_factory=list)
    version: str = "1.4"


def flatten_model(
    model: Any, *, path: Path | None, version: str | None, nesting: Nesting | None = None
) -> Nesting:
    """Expand the includes of ``model`` and merge its nested models into it, in place.

    Args:
        model: A parsed ``<model>`` element.
        path: The file it was read from (relative include URIs start there).
        version: The SDFormat version of that file.
        nesting: Collects what was found (a new one when None).

    Raises:
        ModelError: An include that cannot be resolved or read, a cycle of includes,
            a nested model with a pose relative to a named frame, too many links.
    """
    nesting = nesting if nesting is not None else Nesting()
    _mark_axes(model, version, nesting)
    _expand_includes(model, path, version, nesting, (path,) if path else (), 0)
    _merge_nested(model, version, path, nesting)
    _mark_clashing_joints(model, version, path, nesting)
    _revolute2_as_universal(model, path, nesting)
    _write_for_version(model, nesting.version)
    links = len(model.findall("link"))
    if links > MAX_LINKS:
        raise ModelError(
            f"model '{model.get('name')}' has {links} links with its nested models, more "
            f"than {MAX_LINKS}",
            path=path,
        )
    return nesting


def drake_names(model: Any) -> None:
    """Write every link, joint and frame name of a flattened ``model`` (and every reference to
    one) as Drake is given it (:func:`workbench.model.sdf_names.drake_name`), in place."""
    for tag in _FRAMES:
        for element in model.findall(tag):
            name = element.get("name")
            if name is not None:
                element.set("name", drake_name(name))
    for element in model.iter():
        if not isinstance(element.tag, str) or _inside_plugin(element):
            continue
        for key in _REFERENCES:
            value = element.get(key)
            if value is not None:
                element.set(key, drake_name(value))
        if element.tag in ("parent", "child") and element.getparent().tag == "joint":
            element.text = drake_name((element.text or "").strip())
        if element.tag == "canonical_link" and element.text:
            element.text = drake_name(element.text.strip())


# --- includes -----------------------------------------------------------------------


def _expand_includes(
    model: Any,
    path: Path | None,
    version: str | None,
    nesting: Nesting,
    chain: tuple[Path, ...],
    depth: int,
) -> None:
    for child in list(model):
        if not isinstance(child.tag, str):
            continue
        if child.tag == "model":
            _expand_includes(child, path, version, nesting, chain, depth)
        elif child.tag == "include":
            included = _included_model(child, path, version, nesting, chain, depth)
            model.replace(child, included)


def _included_model(
    include: Any,
    path: Path | None,
    version: str | None,
    nesting: Nesting,
    chain: tuple[Path, ...],
    depth: int,
) -> Any:
    from workbench.model.sdf_uris import resolve_mesh_uris

    line = include.sourceline
    uri = (include.findtext("uri") or "").strip()
    if include.get("merge", "").strip().lower() in ("1", "true"):
        raise ModelError(
            f"<include merge='true'> of {uri} is not supported",
            path=path,
            line=line,
            hint="include it without merge: its links are then named MODEL::LINK",
        )
    file = include_file(uri, path, line, top=chain[0] if chain else None)
    if depth + 1 > MAX_INCLUDE_DEPTH:
        raise ModelError(
            f"<include> of {uri}: models include each other more than {MAX_INCLUDE_DEPTH} deep",
            path=path,
            line=line,
        )
    if file.resolve() in {c.resolve() for c in chain}:
        raise ModelError(
            f"<include> of {uri} includes itself (through {file})", path=path, line=line
        )
    root = read_sdf_file(file)
    inner = root.find("model") if root.tag == "sdf" else None
    if inner is None:
        raise ModelError(
            f"<include> of {uri}: {file} holds no SDF <model>",
            path=path,
            line=line,
            hint="a model included in a model must be an SDF <model>",
        )
    nesting.files.append(file)
    inner_version = root.get("version") or version
    _mark_axes(inner, inner_version, nesting)
    _expand_includes(inner, file, inner_version, nesting, (*chain, file), depth + 1)
    _merge_nested(inner, inner_version, file, nesting)
    _mark_clashing_joints(inner, inner_version, file, nesting)
    resolve_mesh_uris(inner, file.parent, file)
    inner.set("__included__", "1")
    name = (include.findtext("name") or "").strip()
    if name:
        inner.set("name", name)
    for tag in ("pose", "static"):
        override = include.find(tag)
        if override is not None:
            for old in inner.findall(tag):
                inner.remove(old)
            inner.insert(0, copy.deepcopy(override))
    for plugin in include.findall("plugin"):
        inner.append(copy.deepcopy(plugin))
    return inner


def include_file(uri: str, path: Path | None, line: int | None, *, top: Path | None = None) -> Path:
    """The model file an ``<include>``'s ``<uri>`` names: ``model://NAME`` (a model folder's
    ``model.config`` entry), a model folder or an SDF file (absolute, ``file://`` or relative
    to ``path``), which must lie where model files are read from
    (:func:`workbench.model.gazebo_models.allowed_model_file`; ``top``: the file the chain of
    includes started from).

    Raises:
        ModelError: Nothing found, or a file outside the model folders, naming ``path`` and
            ``line``.
    """
    from workbench.model.gazebo_models import (
        allowed_model_file,
        find_model_file,
        model_search_path,
        uri_path,
    )

    base = path.parent if path is not None else Path.cwd()
    if uri.startswith("model://"):
        name = uri[len("model://") :]
        if uri_path(name) is None:
            shown = uri if len(uri) <= 80 else uri[:77] + "..."
            raise ModelError(
                f"cannot resolve {shown}: a model:// URI names a folder inside the model "
                "folders and may not climb out with '..'",
                path=path,
                line=line,
                hint="write model://NAME (GAZEBO_MODEL_PATH lists the model folders)",
            )
        try:
            file = find_model_file(name)
        except ModelError as error:
            raise ModelError(error.message, path=path, line=line, hint=error.hint) from None
        if file is None:
            folders = ", ".join(str(p) for p in model_search_path())
            raise ModelError(
                f"cannot resolve {uri}: no model '{name.strip('/')}' (no folder of that name "
                "with a model.config)",
                path=path,
                line=line,
                hint=f"looked in {folders}; add folders to GAZEBO_MODEL_PATH",
            )
        return file
    if not uri or "://" in uri.replace("file://", "", 1):
        raise ModelError(
            f"<include> needs <uri>model://NAME</uri> or a file path, got '{uri}'",
            path=path,
            line=line,
        )
    target = Path(uri.removeprefix("file://"))
    target = target if target.is_absolute() else base / target
    allowed_model_file(target, path, uri=uri, line=line, top=top)
    if target.is_dir() and (target / "model.config").is_file():
        from workbench.model.gazebo_models import config_file

        try:
            return config_file(target)
        except ModelError as error:
            raise ModelError(error.message, path=path, line=line, hint=error.hint) from None
    if not target.is_file():
        raise ModelError(
            f"<include> of '{uri}': no such file or model folder", path=path, line=line
        )
    return target


def read_sdf_file(file: Path) -> Any:
    """Parse an SDF file after checking its size and its names and numbers (the checks Drake
    needs, :func:`workbench.model.drake_guard.check_sdf_file`); the root element.

    Raises:
        ModelError: Too big, not a regular file, not XML, or a name or number Drake cannot take.
    """
    from workbench.model.drake_guard import check_sdf_file
    from workbench.model.sdf_xml import read_sdf_text

    check_input_file(file, "model file", MAX_MODEL_BYTES)
    check_sdf_file(file)
    return read_sdf_text(file)


# --- merging nested models ----------------------------------------------------------


def _merge_nested(model: Any, version: str | None, path: Path | None, nesting: Nesting) -> None:
    for nested in [c for c in model if isinstance(c.tag, str) and c.tag == "model"]:
        _merge_nested(nested, version, path, nesting)
        if nested.get("__included__") != "1":
            _mark_clashing_joints(nested, version, path, nesting)
        _merge_one(model, nested, nesting)


def _merge_one(parent: Any, nested: Any, nesting: Nesting) -> None:
    prefix = nested.get("name", "")
    included = nested.get("__included__") == "1"
    X_PM = _pose_of(nested, where=f"model '{prefix}'")
    R_PM = X_PM[:3, :3]
    static_element = nested.find("static")
    static = _truth(static_element.text) if static_element is not None else False
    renamed = {
        element.get("name"): f"{prefix}::{element.get('name')}"
        for tag in _FRAMES
        for element in nested.findall(tag)
        if element.get("name") is not None
    }
    for element in nested.iter():
        if not isinstance(element.tag, str):
            continue
        if _inside_plugin(element) or element.tag == "plugin":
            _rename_plugin_text(element, renamed)
            continue
        for key in _REFERENCES:
            value = element.get(key)
            if value in renamed:
                element.set(key, renamed[value])
        if element.tag in ("parent", "child") and element.getparent().tag == "joint":
            text = (element.text or "").strip()
            if text != "world":
                element.text = renamed.get(text, f"{prefix}::{text}")
    for axis in nested.iter("axis", "axis2"):
        _rotate_model_axis(axis, R_PM)
    position = parent.index(nested)
    moved = []
    for child in list(nested):
        if not isinstance(child.tag, str) or child.tag in _DROPPED:
            continue
        if child.tag in _FRAMES and child.get("name") is not None:
            old = child.get("name")
            child.set("name", renamed[old])
            if child.tag in ("link", "frame"):
                _compose_pose(child, X_PM, renamed)
        moved.append(child)
    for link in (c for c in moved if c.tag == "link"):
        name = link.get("name")
        inner = nesting.static_links.pop(_unprefixed(name, prefix), None)
        if not included:
            nesting.static_links[name] = static if inner is None else inner
        elif inner is not None:
            nesting.static_links[name] = inner
    parent.remove(nested)
    for offset, child in enumerate(moved):
        parent.insert(position + offset, child)


def _unprefixed(name: str, prefix: str) -> str:
    return name[len(prefix) + 2 :] if name.startswith(f"{prefix}::") else name


def _compose_pose(element: Any, X_PM: np.ndarray, renamed: dict[str, str]) -> None:
    """Give ``element`` (a link or frame of a nested model) its pose in the parent model."""
    pose = element.find("pose")
    relative_to = pose.get("relative_to") if pose is not None else None
    attached = element.get("attached_to") not in (None, "", "__model__")
    if element.tag == "frame" and attached and relative_to in (None, ""):
        return  # relative to the frame it is attached to, which moves with it
    if relative_to not in (None, "", "__model__"):
        return  # relative to a frame of the nested model, renamed with it
    X_ML = _pose_of(element, where=f"{element.tag} '{element.get('name')}'")
    X = X_PM @ X_ML
    if pose is None:
        pose = etree.SubElement(element, "pose")
    for key in ("relative_to", "frame", "rotation_format", "degrees"):
        pose.attrib.pop(key, None)
    pose.text = _pose_text(X)


def _rotate_model_axis(axis: Any, R_PM: np.ndarray) -> None:
    """Turn an axis given in the nested model's frame into the parent model's frame."""
    xyz = axis.find("xyz")
    if axis.get(_IN_MODEL) != "1" or xyz is None:
        return
    try:
        vector = np.array([float(v) for v in (xyz.text or "").split()], dtype=float)
    except ValueError:
        return  # Drake reports the malformed axis
    if vector.shape != (3,):
        return
    xyz.text = " ".join(f"{v:.17g}" for v in R_PM @ vector)


def _mark_axes(model: Any, version: str | None, nesting: Nesting) -> None:
    """Note on each joint axis of one file whether it is given in the model frame (SDFormat
    1.4 always, 1.5 and 1.6 with ``use_parent_model_frame``, 1.7 with ``expressed_in``),
    so files of different versions can be merged; :func:`_write_for_version` writes it back."""
    if _version(version) > _version(nesting.version):
        nesting.version = version or "1.7"
    for axis in model.iter("axis", "axis2"):
        if _inside_plugin(axis) or axis.get(_IN_MODEL) is not None:
            continue
        flag = axis.find("use_parent_model_frame")
        xyz = axis.find("xyz")
        expressed = xyz.get("expressed_in") if xyz is not None else None
        if flag is not None:
            in_model = _truth(flag.text)
            axis.remove(flag)
        else:
            in_model = expressed == "__model__" or _version(version) < (1, 5)
        if expressed == "__model__":
            del xyz.attrib["expressed_in"]
        axis.set(_IN_MODEL, "1" if in_model else "0")


def _write_for_version(model: Any, version: str) -> None:
    """Say model-frame axes (and pose frames) the way SDFormat ``version`` says them."""
    modern = _version(version) >= (1, 7)
    for axis in model.iter("axis", "axis2"):
        in_model = axis.attrib.pop(_IN_MODEL, None) == "1"
        xyz = axis.find("xyz")
        if not in_model or xyz is None:
            continue
        if modern:
            xyz.set("expressed_in", "__model__")
        elif _version(version) >= (1, 5):
            etree.SubElement(axis, "use_parent_model_frame").text = "true"
    if modern:
        for pose in model.iter("pose"):
            frame = pose.attrib.pop("frame", None)
            if frame and pose.get("relative_to") is None:
                pose.set("relative_to", frame)


def _mark_clashing_joints(
    model: Any, version: str | None, path: Path | None, nesting: Nesting
) -> None:
    """Mark joints named like a link or frame (allowed before SDFormat 1.7, as libsdformat
    allows it) so Drake accepts them; the name shown stays the file's."""
    taken = {e.get("name") for tag in ("link", "frame") for e in model.findall(tag)}
    for joint in model.findall("joint"):
        name = joint.get("name", "")
        if name not in taken or name.endswith(JOINT_MARK):
            continue
        if _version(version) >= (1, 7):
            raise ModelError(
                f"joint '{name}' of model '{model.get('name')}' has the name of a link or frame, "
                "which SDFormat 1.7 and later forbid",
                path=path,
                line=joint.sourceline,
                hint="rename the joint",
            )
        joint.set("name", name + JOINT_MARK)
        nesting.warnings.append(
            f"{path or 'model'}:{joint.sourceline}: joint '{name}' of model "
            f"'{model.get('name')}' has the name of a link (SDFormat before 1.7 allows it; "
            "libsdformat calls it '" + name + "_joint')"
        )


def _revolute2_as_universal(model: Any, path: Path | None, nesting: Nesting) -> None:
    """A ``revolute2`` joint (Gazebo's hinge-2: one axis on the parent, one on the child) with
    orthogonal axes moves as a universal joint, which Drake has; without suspension."""
    for joint in model.findall("joint"):
        if joint.get("type") != "revolute2":
            continue
        axes = [joint.find(tag) for tag in ("axis", "axis2")]
        if any(a is None or a.find("xyz") is None for a in axes):
            continue
        try:
            u, v = (np.array([float(x) for x in (a.findtext("xyz") or "").split()]) for a in axes)
        except ValueError:
            continue
        same_frame = axes[0].get(_IN_MODEL) == axes[1].get(_IN_MODEL)
        if u.shape != (3,) or v.shape != (3,) or not same_frame:
            continue
        if abs(float(u @ v)) > 1e-9 * float(np.linalg.norm(u) * np.linalg.norm(v)):
            continue  # Drake's universal joint needs orthogonal axes; Drake refuses it
        joint.set("type", "universal")
        nesting.warnings.append(
            f"{path or 'model'}:{joint.sourceline}: revolute2 joint "
            f"'{shown_name(joint.get('name', ''))}' moves as a universal joint (its two axes "
            "are orthogonal); Gazebo's suspension (<suspension>) is not simulated"
        )


# --- small helpers ------------------------------------------------------------------


def _pose_of(element: Any, *, where: str) -> np.ndarray:
    from workbench.spatial import pose_matrix

    pose = element.find("pose")
    if pose is None:
        return np.eye(4)
    if pose.get("relative_to") not in (None, "", "__model__") and element.tag == "model":
        raise ModelError(
            f"{where}: a nested model placed relative_to '{pose.get('relative_to')}' is not "
            "supported",
            line=pose.sourceline,
            hint="give the nested model's pose in its parent model's frame",
        )
    return pose_matrix(**_pose_values(pose, where))


def _pose_values(pose: Any, where: str) -> dict[str, Any]:
    text = (pose.text or "").strip()
    try:
        values = [float(v) for v in text.split()] if text else [0.0] * 6
    except ValueError:
        values = []
    quaternion = (pose.get("rotation_format") or "").strip() == "quat_xyzw"
    if len(values) != (7 if quaternion else 6) or not all(math.isfinite(v) for v in values):
        raise ModelError(
            f"{where}: <pose> must be 'x y z roll pitch yaw', got '{text}'", line=pose.sourceline
        )
    if quaternion:
        return {"xyz": values[:3], "quaternion": values[3:]}
    rpy = values[3:]
    if _truth(pose.get("degrees")):
        rpy = [math.radians(v) for v in rpy]
    return {"xyz": values[:3], "rpy": rpy}


def _pose_text(X: np.ndarray) -> str:
    from workbench.spatial import xyz_rpy_from_matrix

    xyz, rpy = xyz_rpy_from_matrix(X)
    return " ".join(f"{v:.17g}" for v in (*xyz, *rpy))


def _rename_plugin_text(element: Any, renamed: dict[str, str]) -> None:
    text = (element.text or "").strip()
    if text in renamed:
        element.text = renamed[text]


def _inside_plugin(element: Any) -> bool:
    return any(a.tag == "plugin" for a in element.iterancestors())


def _truth(text: str | None) -> bool:
    return (text or "").strip().lower() in ("1", "true")


def _version(text: str | None) -> tuple[int, ...]:
    parts = [p for p in (text or "").split(".") if p.isdigit()]
    return tuple(int(p) for p in parts) if parts else (1, 7)
