"""An SDF ``<model>`` as Gazebo reads it, turned into a :class:`SimModel`.

The model gets its world name; its own ``<pose>`` is lifted into
``SimModel.pose`` (the world composes placement and pose, as gazebo_ros's
spawner does); ``<static>`` and ``<self_collide>`` become fields (the simulator
welds a static model where it is put); ``<gravity>false</gravity>`` on every
link switches gravity off for the model; ``<plugin>`` and ``<sensor>`` elements
are lifted out; ``<include>`` and nested ``<model>`` elements are merged into
the model (:mod:`workbench.model.sdf_nesting`, names as Gazebo gives them);
``model://NAME/...`` and relative mesh URIs become files Drake can read
(:mod:`workbench.model.sdf_uris`); stock Gazebo material scripts become colours;
``<ode>`` friction's ``<mu>`` and ``<mu2>`` become their mean, as static and dynamic
friction. Drake reads the rest of SDFormat itself. Inertias that break the triangle
inequality are fixed with a warning, as in URDF (:mod:`workbench.sim.inertia`).
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import numpy as np
from lxml import etree

from workbench.errors import ModelError, SimulationError
from workbench.model.sdf_names import drake_name, shown_name
from workbench.model.sdf_nesting import drake_names, flatten_model
from workbench.model.sdf_uris import drop_material_scripts, resolve_mesh_uris
from workbench.sim.inertia import ENTRIES, repaired
from workbench.sim.model_spec import CollisionPieces, SimModel, element_text, plugin_spec

DRAKE_NS = "http://drake.mit.edu"


def sim_model_from_sdf(
    text: str, *, name: str | None, source: str, base_dir: Path | None = None
) -> SimModel:
    """The :class:`SimModel` of an SDF file with one ``<model>`` (or a bare ``<model>``).

    Raises:
        SimulationError: Not XML, no ``<model>``, a model without links, an include that
            cannot be resolved, a mesh that cannot be found.
    """
    from workbench.model.sdf_xml import parse_sdf_text

    try:
        root = parse_sdf_text(text.strip())
    except ModelError as error:
        raise SimulationError(f"{source}: not valid XML: {error.message}") from None
    model_element = root if root.tag == "model" else root.find("model")
    if model_element is None:
        what = "a world, not a model" if root.find("world") is not None else "no <model>"
        raise SimulationError(f"{source}: the SDF has {what}", hint="spawn an SDF <model>")
    model_element = copy.deepcopy(model_element)
    return sim_model_from_element(
        model_element, name=name, source=source, base_dir=base_dir, version=root.get("version")
    )


def sim_model_from_element(
    model_element: Any,
    *,
    name: str | None,
    source: str,
    base_dir: Path | None,
    version: str | None = None,
) -> SimModel:
    """:func:`sim_model_from_sdf` for a parsed ``<model>`` element (changed in place)."""
    from workbench.model.drake_guard import check_sdf_element
    from workbench.sim.bounds import check_model_name

    if name:
        check_model_name(name, "model name")
    where = f"{source}:{model_element.sourceline}" if model_element.sourceline else source
    path = Path(source) if base_dir is not None and Path(source).is_file() else None
    if _truth(model_element.findtext("static")):
        _drop_broken_inertials(model_element)
    try:
        check_sdf_element(model_element, path)
    except ModelError as error:
        message = error.message if error.path is not None else f"{source}: {error.message}"
        raise SimulationError(message, path=error.path, line=error.line, hint=error.hint) from None
    try:
        nesting = flatten_model(model_element, path=path, version=version)
    except ModelError as error:
        raise SimulationError(
            error.message, path=error.path or path, line=error.line, hint=error.hint
        ) from None
    links = model_element.findall("link")
    if not links:
        raise SimulationError(f"{where}: model '{model_element.get('name')}' has no <link>")
    if name:
        model_element.set("name", name)
    canonical = model_element.get("canonical_link") or links[0].get("name", "")
    model = SimModel(
        name=model_element.get("name", ""),
        format="sdf",
        text="",
        root_link=drake_name(canonical),
        source=source,
    )
    model.warnings.extend(nesting.warnings)
    pose = model_element.find("pose")
    if pose is not None:
        model.pose = _pose(pose, where)
        model_element.remove(pose)
    for tag in ("static", "self_collide"):
        element = model_element.find(tag)
        if element is not None:
            setattr(model, "static" if tag == "static" else "self_collide", _truth(element.text))
            model_element.remove(element)
    for plugin in model_element.findall("plugin"):
        model.plugins.append(plugin_spec(plugin, "model", None, base_dir, source))
        model_element.remove(plugin)
    gravity_off = []
    for link in links:
        link_name = link.get("name", "")
        for sensor in link.findall("sensor"):
            for plugin in sensor.iter("plugin"):
                model.plugins.append(
                    plugin_spec(
                        plugin, "sensor", shown_name(link_name), base_dir, source, sensor=sensor
                    )
                )
            model.sensors.append((shown_name(link_name), element_text(sensor)))
            link.remove(sensor)
        gravity = link.find("gravity")
        if gravity is not None:
            if not _truth(gravity.text):
                gravity_off.append(link_name)
            link.remove(gravity)
        if not nesting.static_links.get(link_name, model.static):
            _fix_inertia(link, model, where)
    if gravity_off and len(gravity_off) == len(links):
        model.gravity = False
    elif gravity_off:
        model.warnings.append(
            f"{where}: <gravity>false</gravity> on links {', '.join(gravity_off)} only; "
            "workbench switches gravity per model, so it stays on"
        )
    model.static_links = {
        drake_name(link): static
        for link, static in nesting.static_links.items()
        if static != model.static
    }
    _ball_casters(model_element, model, where)
    try:
        resolve_mesh_uris(model_element, base_dir, path)
    except ModelError as error:
        raise SimulationError(
            error.message, path=error.path or path, line=error.line, hint=error.hint
        ) from None
    _material_colours(model_element)
    _isotropic_friction(model_element)
    drop_material_scripts(model_element)
    for link in links:
        _planes_as_boxes(link, where)
    for link in links:
        if nesting.static_links.get(link.get("name", ""), model.static):
            _split_concave_meshes(link, model, where)
    drake_names(model_element)
    sdf = etree.Element("sdf", version=nesting.version)
    sdf.append(model_element)
    model.text = etree.tostring(sdf, encoding="unicode")
    return model


def _drop_broken_inertials(model_element: Any) -> None:
    """Remove the ``<inertial>`` of a static model's links where it holds NaN or inf.

    Gazebo ignores a static model's inertia, and worlds saved from it carry
    ``<ixx>nan</ixx>`` for massless walls (turtlebot3_autorace); the simulator welds
    the links, so their inertia is never used.
    """
    for link in model_element.findall("link"):
        inertial = link.find("inertial")
        if inertial is None:
            continue
        for element in inertial.iter():
            try:
                finite = all(np.isfinite([float(v) for v in (element.text or "").split()]))
            except ValueError:
                continue
            if not finite:
                link.remove(inertial)
                break


def _split_concave_meshes(link: Any, model: SimModel, where: str) -> None:
    """Take the concave collision meshes of a static link out of the SDF as convex pieces."""
    from urllib.parse import unquote, urlparse

    from workbench.model.mesh_pieces import TooManyPieces, convex_pieces

    for collision in link.findall("collision"):
        mesh = collision.find("geometry/mesh")
        uri = (mesh.findtext("uri") or "").strip() if mesh is not None else ""
        pose = collision.find("pose")
        if (
            not uri.startswith("file://")
            or mesh.find("submesh") is not None
            or (pose is not None and pose.get("relative_to") not in (None, ""))
        ):
            continue
        scale = _vector(mesh.find("scale"), (1.0, 1.0, 1.0))
        try:
            pieces = convex_pieces(Path(unquote(urlparse(uri).path)), np.array(scale))
        except TooManyPieces as error:
            model.warnings.append(
                f"{where}: collision '{collision.get('name')}' of link "
                f"'{shown_name(link.get('name', ''))}' is a concave mesh with {error}; it "
                "collides, and the laser sees it, as its convex hull"
            )
            continue
        except Exception:  # trimesh cannot read it again: Drake keeps its hull
            continue
        if pieces is None:
            continue
        mu = [
            value
            for value in (
                _vector(collision.find(f"surface/friction/ode/{key}"), (), count=1)
                for key in ("mu", "mu2")
            )
            if value
        ]
        model.collision_pieces.append(
            CollisionPieces(
                link=drake_name(link.get("name", "")),
                name=collision.get("name", "collision"),
                pose=_pose(pose, where) if pose is not None else (0.0,) * 6,
                pieces=tuple(pieces),
                friction=float(np.mean([m[0] for m in mu])) if mu else 1.0,
            )
        )
        link.remove(collision)


#: The side of the box a collision ``<plane>`` becomes, and its thickness below the plane, m.
PLANE_SIDE, PLANE_THICKNESS = 200.0, 1.0


def _planes_as_boxes(link: Any, where: str) -> None:
    """Give ``<plane>`` shapes as boxes whose top face is the plane.

    Gazebo's plane collides as an infinite plane; Drake 1.51 crashes (in its broad
    phase) once a second half space, beside the ground's, shares a plant with a few
    hundred shapes. A box :data:`PLANE_SIDE` wide and :data:`PLANE_THICKNESS` deep
    under the plane collides the same wherever a robot drives; a visual plane
    becomes a thin box of the plane's ``<size>``.
    """
    from workbench.spatial import pose_matrix, xyz_rpy_from_matrix

    for element in [*link.findall("collision"), *link.findall("visual")]:
        geometry = element.find("geometry")
        plane = geometry.find("plane") if geometry is not None else None
        if plane is None:
            continue
        normal = np.array(_vector(plane.find("normal"), (0.0, 0.0, 1.0)), dtype=float)
        normal = normal / np.linalg.norm(normal) if np.linalg.norm(normal) > 0 else np.eye(3)[2]
        if element.tag == "collision":
            size = (PLANE_SIDE, PLANE_SIDE, PLANE_THICKNESS)
        else:
            drawn = _vector(plane.find("size"), (PLANE_SIDE, PLANE_SIDE), count=2)
            size = (drawn[0], drawn[1], 0.001)
        # a rotation taking z to the normal, then the box moved half its depth under the plane
        axis = np.cross([0.0, 0.0, 1.0], normal)
        angle = float(np.arctan2(np.linalg.norm(axis), normal[2]))
        R = np.eye(3)
        if np.linalg.norm(axis) > 1e-12:
            k = axis / np.linalg.norm(axis)
            K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
            R = np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K
        elif normal[2] < 0:
            R = np.diag([1.0, -1.0, -1.0])
        X_PB = np.eye(4)
        X_PB[:3, :3] = R
        X_PB[:3, 3] = -normal * size[2] / 2.0
        pose = element.find("pose")
        own = _pose(pose, where) if pose is not None else (0.0,) * 6
        X = pose_matrix(own[:3], rpy=own[3:]) @ X_PB
        if pose is None:
            pose = etree.SubElement(element, "pose")
        xyz, rpy = xyz_rpy_from_matrix(X)
        pose.text = " ".join(f"{v:.17g}" for v in (*xyz, *rpy))
        geometry.remove(plane)
        box = etree.SubElement(geometry, "box")
        etree.SubElement(box, "size").text = " ".join(f"{v:g}" for v in size)


def _isotropic_friction(model_element: Any) -> None:
    """Give ``<ode>`` friction the mean of its ``<mu>`` and ``<mu2>`` in both.

    Gazebo's two coefficients are along two directions; Drake reads them as static and
    dynamic friction and refuses a dynamic one above the static one (a model with only
    ``<mu>0.8</mu>`` got ``<mu2>``'s default, 1). As for URDF's ``mu1``/``mu2``, the
    collision gets the mean of the coefficients it gives, as both.
    """
    for ode in model_element.iter("ode"):
        if ode.getparent() is None or ode.getparent().tag != "friction":
            continue
        given = [ode.find(key) for key in ("mu", "mu2")]
        try:
            values = [float((e.text or "").strip()) for e in given if e is not None]
        except ValueError:
            continue  # a malformed number: Drake names it
        if not values or not all(np.isfinite(values)):
            continue
        mean = float(np.mean(values))
        for key, element in zip(("mu", "mu2"), given, strict=True):
            if element is None:
                element = etree.SubElement(ode, key)
            element.text = f"{mean:.17g}"


def _vector(element: Any, default: tuple[float, ...], count: int = 3) -> tuple[float, ...]:
    """The numbers of ``element``, ``default`` when it is missing or not ``count`` finite numbers."""
    if element is None:
        return default
    try:
        values = tuple(float(v) for v in (element.text or "").split())
    except ValueError:
        return default
    ok = len(values) == count and all(np.isfinite(values)) and min(map(abs, values)) > 0
    return values if ok else default


def _material_colours(model_element: Any) -> None:
    """Give visuals that name one of Gazebo's stock material scripts its colour (Drake reads
    ``<diffuse>``, not scripts)."""
    from workbench.sim.gazebo_urdf import GAZEBO_COLOURS

    for material in model_element.iter("material"):
        script_name = (material.findtext("script/name") or "").strip()
        rgba = GAZEBO_COLOURS.get(script_name)
        if rgba is not None and material.find("diffuse") is None:
            etree.SubElement(material, "diffuse").text = " ".join(f"{c:g}" for c in rgba)


def _ball_casters(model_element: Any, model: SimModel, where: str) -> None:
    """Ball joints that carry a sphere caster become fixed, frictionless casters.

    Drake's ball joint is a roll-pitch-yaw joint that stops the simulation at
    pitch = pi/2, which a rolling caster reaches at once. A caster's job, carrying
    weight without resisting motion, is done as well by a fixed sphere without
    friction (what URDF robots do). Other ball joints are left alone.
    """
    parents = {j.findtext("parent") for j in model_element.findall("joint")}
    for joint in model_element.findall("joint"):
        if joint.get("type") != "ball":
            continue
        child_name = (joint.findtext("child") or "").strip()
        child = next(
            (lk for lk in model_element.findall("link") if lk.get("name") == child_name), None
        )
        collisions = child.findall("collision") if child is not None else []
        spheres = [c for c in collisions if c.find("geometry/sphere") is not None]
        if (
            child is None
            or child_name in parents
            or not collisions
            or len(spheres) != len(collisions)
        ):
            continue
        joint.set("type", "fixed")
        for axis in joint.findall("axis"):
            joint.remove(axis)
        for collision in collisions:
            for old in collision.findall(f"{{{DRAKE_NS}}}proximity_properties"):
                collision.remove(old)
            properties = etree.SubElement(
                collision, f"{{{DRAKE_NS}}}proximity_properties", nsmap={"drake": DRAKE_NS}
            )
            for key in ("mu_dynamic", "mu_static"):
                etree.SubElement(properties, f"{{{DRAKE_NS}}}{key}").text = "0"
        model.warnings.append(
            f"{where}: ball joint '{shown_name(joint.get('name', ''))}' carries a sphere caster: simulated as a "
            "fixed, frictionless caster (Drake's ball joint stops at pitch = pi/2)"
        )


def _fix_inertia(link: Any, model: SimModel, where: str) -> None:
    inertia = link.find("inertial/inertia")
    if inertia is None:
        return
    defaults = {"ixx": 1.0, "iyy": 1.0, "izz": 1.0}
    values = []
    for key in ENTRIES:
        element = inertia.find(key)
        try:
            values.append(float(element.text) if element is not None else defaults.get(key, 0.0))
        except (TypeError, ValueError):
            return  # Drake reports malformed numbers itself
    repair = repaired(values, link.get("name", ""), where)
    if repair is None:
        return
    fixed, warning = repair
    model.warnings.append(warning)
    for key, value in zip(ENTRIES, fixed, strict=True):
        element = inertia.find(key)
        if element is None:
            element = etree.SubElement(inertia, key)
        element.text = f"{value:.12g}"


def _pose(element: Any, where: str) -> tuple[float, float, float, float, float, float]:
    try:
        values = [float(v) for v in (element.text or "").split()]
    except ValueError:
        values = []
    if len(values) != 6 or not np.all(np.isfinite(values)):
        raise SimulationError(
            f"{where}: <pose> must be six finite numbers 'x y z roll pitch yaw', got "
            f"'{(element.text or '').strip()}'"
        )
    return (values[0], values[1], values[2], values[3], values[4], values[5])


def _truth(text: str | None) -> bool:
    return (text or "").strip().lower() in ("1", "true", "yes", "on")
