"""An SDF ``<model>`` as Gazebo reads it, turned into a :class:`SimModel`.

The model gets its world name; its own ``<pose>`` is lifted into
``SimModel.pose`` (the world composes placement and pose, as gazebo_ros's
spawner does); ``<static>`` and ``<self_collide>`` become fields (the simulator
welds a static model where it is put); ``<gravity>false</gravity>`` on every
link switches gravity off for the model; ``<plugin>`` and ``<sensor>`` elements
are lifted out; ``model://NAME/...`` and relative mesh URIs become absolute
files Drake can read. Drake reads the rest of SDFormat itself, including
``<surface><friction><ode><mu>``. Inertias that break the triangle inequality
are fixed with a warning, as in URDF (:mod:`workbench.sim.inertia`).
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import numpy as np
from lxml import etree

from workbench.errors import SimulationError
from workbench.sim.inertia import ENTRIES, repaired
from workbench.sim.model_spec import SimModel, element_text, plugin_spec

DRAKE_NS = "http://drake.mit.edu"


def sim_model_from_sdf(
    text: str, *, name: str | None, source: str, base_dir: Path | None = None
) -> SimModel:
    """The :class:`SimModel` of an SDF file with one ``<model>`` (or a bare ``<model>``).

    Raises:
        SimulationError: Not XML, no ``<model>``, a model without links, a nested
            ``<include>``, a mesh that cannot be found.
    """
    try:
        root = etree.fromstring(text.strip().encode())
    except etree.XMLSyntaxError as error:
        raise SimulationError(f"{source}: not valid XML: {error}") from None
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
    where = f"{source}:{model_element.sourceline}" if model_element.sourceline else source
    links = model_element.findall("link")
    if not links:
        raise SimulationError(f"{where}: model '{model_element.get('name')}' has no <link>")
    if model_element.find("include") is not None or model_element.find("model") is not None:
        raise SimulationError(
            f"{where}: nested models (<include>/<model> inside a <model>) are not supported",
            hint="put the models side by side in the world",
        )
    if name:
        model_element.set("name", name)
    model = SimModel(
        name=model_element.get("name", ""),
        format="sdf",
        text="",
        root_link=model_element.get("canonical_link") or links[0].get("name"),
        source=source,
    )
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
        for sensor in link.findall("sensor"):
            for plugin in sensor.iter("plugin"):
                model.plugins.append(
                    plugin_spec(plugin, "sensor", link.get("name"), base_dir, source, sensor=sensor)
                )
            model.sensors.append((link.get("name", ""), element_text(sensor)))
            link.remove(sensor)
        gravity = link.find("gravity")
        if gravity is not None:
            if not _truth(gravity.text):
                gravity_off.append(link.get("name"))
            link.remove(gravity)
        if not model.static:
            _fix_inertia(link, model, where)
    if gravity_off and len(gravity_off) == len(links):
        model.gravity = False
    elif gravity_off:
        model.warnings.append(
            f"{where}: <gravity>false</gravity> on links {', '.join(gravity_off)} only; "
            "workbench switches gravity per model, so it stays on"
        )
    _ball_casters(model_element, model, where)
    _absolute_uris(model_element, base_dir, where)
    sdf = etree.Element("sdf", version=version or "1.7")
    sdf.append(model_element)
    model.text = etree.tostring(sdf, encoding="unicode")
    return model


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
            f"{where}: ball joint '{joint.get('name')}' carries a sphere caster: simulated as a "
            "fixed, frictionless caster (Drake's ball joint stops at pitch = pi/2)"
        )


def _absolute_uris(model_element: Any, base_dir: Path | None, where: str) -> None:
    from workbench.model.meshes import prepare_mesh
    from workbench.sim.model_paths import find_model_dir

    for uri in model_element.iter("uri"):
        value = (uri.text or "").strip()
        if not value or value.startswith("package://"):
            continue
        if value.startswith("model://"):
            model_name, _, rest = value[len("model://") :].partition("/")
            folder = find_model_dir(model_name)
            if folder is None:
                raise SimulationError(
                    f"{where}: cannot resolve {value}: no model '{model_name}'",
                    hint="add its folder's parent to GAZEBO_MODEL_PATH",
                )
            path = folder / rest
        elif value.startswith("file://"):
            path = Path(value[len("file://") :])
        else:
            path = Path(value)
            if not path.is_absolute():
                path = (base_dir or Path.cwd()) / path
        if uri.getparent() is not None and uri.getparent().tag == "mesh":
            path = prepare_mesh(path, where=None, line=uri.sourceline)
        uri.text = str(path)


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
