"""A URDF with ``<gazebo>`` extension blocks, as Gazebo reads it, turned into a :class:`SimModel`.

What the blocks say and where it goes (gazebo_ros's URDF extensions):

* ``<material>Gazebo/Blue</material>``: the link's visuals get that colour (the
  diffuse colour of Gazebo's material script; unknown names keep the URDF colour
  with a warning).
* ``<mu1>``/``<mu2>``: Drake has one isotropic Coulomb coefficient, so the link's
  collisions get their mean as static and dynamic friction
  (``drake:mu_static``/``drake:mu_dynamic``).
* ``<kp>`` (N/m): ``drake:point_contact_stiffness``. ``<kd>`` (N s/m, a linear
  damper in ODE): Drake's Hunt-Crossley dissipation ``d`` damps with
  ``kp * x * d * v``; ``d = kd / (kp * 1 mm)`` gives the same damping at 1 mm of
  penetration.
* ``<selfCollide>``, ``<static>``, ``<gravity>`` (model level, or every link):
  the :class:`SimModel` fields. Gravity switched off on some links only cannot
  be expressed per link here: warned about and ignored.
* ``<plugin>`` (model level) and ``<sensor>`` (with their plugins): lifted out.

Every ``<gazebo>`` element is then removed. Links a floating model cannot do
without get what Gazebo tolerates fixed, each with a one-line warning: an
inertia that breaks the triangle inequality (:mod:`workbench.sim.inertia`), and
a missing ``<inertial>`` or a mass that is not positive (SDFormat's default
inertial, 1 kg and 1 kg m^2, as Gazebo gives an SDF link without one). A link
without ``<inertial>`` that fixed joints tie to a link with mass (a
``base_footprint``, a sensor frame) is left massless, without a warning: Gazebo
lumps fixed-joint links into one body, where it adds nothing.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
from lxml import etree

from workbench.errors import SimulationError
from workbench.sim.inertia import DEFAULT_MASS, DEFAULT_MOMENT, ENTRIES, repaired
from workbench.sim.model_spec import SimModel, element_text, plugin_spec

DRAKE_NS = "http://drake.mit.edu"
KD_REFERENCE_PENETRATION = 0.001

#: Diffuse colours (r, g, b, a) of Gazebo's stock material scripts.
GAZEBO_COLOURS: dict[str, tuple[float, float, float, float]] = {
    "Gazebo/Black": (0.0, 0.0, 0.0, 1.0),
    "Gazebo/FlatBlack": (0.1, 0.1, 0.1, 1.0),
    "Gazebo/DarkGrey": (0.175, 0.175, 0.175, 1.0),
    "Gazebo/Grey": (0.7, 0.7, 0.7, 1.0),
    "Gazebo/White": (1.0, 1.0, 1.0, 1.0),
    "Gazebo/Red": (1.0, 0.0, 0.0, 1.0),
    "Gazebo/RedBright": (0.87, 0.26, 0.07, 1.0),
    "Gazebo/Green": (0.0, 1.0, 0.0, 1.0),
    "Gazebo/Blue": (0.0, 0.0, 1.0, 1.0),
    "Gazebo/SkyBlue": (0.53, 0.81, 0.98, 1.0),
    "Gazebo/Yellow": (1.0, 1.0, 0.0, 1.0),
    "Gazebo/ZincYellow": (0.9725, 0.9529, 0.2078, 1.0),
    "Gazebo/DarkYellow": (0.7, 0.7, 0.0, 1.0),
    "Gazebo/Purple": (1.0, 0.0, 1.0, 1.0),
    "Gazebo/Turquoise": (0.0, 1.0, 1.0, 1.0),
    "Gazebo/Orange": (1.0, 0.5088, 0.0468, 1.0),
    "Gazebo/Indigo": (0.33, 0.0, 0.5, 1.0),
    "Gazebo/Wood": (0.62, 0.44, 0.26, 1.0),
    "Gazebo/Gold": (0.8, 0.64, 0.2, 1.0),
}


def sim_model_from_urdf(
    description: Any, name: str | None = None, *, source: str | None = None
) -> SimModel:
    """The :class:`SimModel` of a ``workbench.model.RobotDescription`` (a URDF).

    Args:
        description: The parsed URDF (``RobotDescription.load`` / ``from_text``).
        name: The model's name in the world (default: the robot's name).
        source: Where it came from, for messages (default: the file).

    Raises:
        SimulationError: No links, or meshes that cannot be found.
    """
    from workbench.errors import ModelError
    from workbench.model.drake_guard import check_urdf_element
    from workbench.sim.bounds import check_model_name

    if name:
        check_model_name(name, "model name")
    where = source or str(description.path)
    try:
        if description.document is not None:
            # lines are the file's only for a file read as it is (not text, not xacro output)
            in_file = source in (None, str(description.path)) and not description.expanded
            check_urdf_element(description.document.root, description.path if in_file else None)
        text = description.prepared_text(name)
        root_link = description.root_link()
    except ModelError as error:
        if error.line is not None and error.path is not None:
            raise SimulationError(
                error.message, path=error.path, line=error.line, hint=error.hint
            ) from None
        raise SimulationError(f"{where}: {error.message}", hint=error.hint) from None
    root = etree.fromstring(text.encode())
    links = {link.get("name"): link for link in root.iterchildren("link")}
    if not links:
        raise SimulationError(f"{where}: the URDF has no <link>", hint="a model needs a link")
    model = SimModel(
        name=root.get("name", ""),
        format="urdf",
        text="",
        package_map={k: str(v) for k, v in description.packages.packages.items()},
        root_link=root_link,
        source=where,
    )
    base_dir = Path(description.path).parent
    gravity_off: set[str] = set()
    for block in list(root.iterchildren("gazebo")):
        _apply_block(block, links, model, base_dir, where, gravity_off)
        root.remove(block)
    if gravity_off and gravity_off >= set(links):
        model.gravity = False
    elif gravity_off:
        model.warnings.append(
            f"{where}: <gravity>0</gravity> on links {', '.join(sorted(gravity_off))} only; "
            "workbench switches gravity per model, so it stays on"
        )
    if not model.static:
        welded = _welded_to_mass(root, links)
        for link_name, link in links.items():
            if link_name not in welded:
                _fix_inertial(link, link_name, model, where)
    model.text = etree.tostring(root, encoding="unicode")
    return model


def _apply_block(
    block: Any,
    links: dict[str, Any],
    model: SimModel,
    base_dir: Path,
    where: str,
    gravity_off: set[str],
) -> None:
    reference = block.get("reference")
    line = f"{where}:{block.sourceline}" if block.sourceline else where
    if reference is not None and reference not in links:
        model.warnings.append(
            f"{line}: <gazebo reference='{reference}'> names no link (joints' blocks are ignored)"
        )
        return
    targets = [links[reference]] if reference else list(links.values())
    for element in block:
        if not isinstance(element.tag, str):
            continue
        tag, text = element.tag, (element.text or "").strip()
        if tag == "material" and reference:
            _colour(links[reference], text, model, line)
        elif tag in ("mu1", "mu2", "kp", "kd"):
            _number(element, line)
        elif tag == "selfCollide":
            model.self_collide = _truth(text)
        elif tag == "static":
            model.static = _truth(text)
        elif tag in ("gravity", "turnGravityOff"):
            off = not _truth(text) if tag == "gravity" else _truth(text)
            if off:
                gravity_off.update(link.get("name") for link in targets)
        elif tag == "plugin":
            model.plugins.append(plugin_spec(element, "model", reference, base_dir, where))
        elif tag == "sensor":
            for plugin in element.iter("plugin"):
                model.plugins.append(
                    plugin_spec(plugin, "sensor", reference, base_dir, where, sensor=element)
                )
            model.sensors.append((reference or model.root_link or "", element_text(element)))
    contact = {e.tag: _number(e, line) for e in block if e.tag in ("mu1", "mu2", "kp", "kd")}
    if contact and reference:
        _contact(links[reference], contact)


def _colour(link: Any, name: str, model: SimModel, where: str) -> None:
    rgba = GAZEBO_COLOURS.get(name)
    if rgba is None:
        model.warnings.append(f"{where}: unknown Gazebo material '{name}'; the URDF colour stays")
        return
    for visual in link.iterchildren("visual"):
        for old in visual.findall("material"):
            visual.remove(old)
        material = etree.SubElement(visual, "material", name=name)
        etree.SubElement(material, "color", rgba=" ".join(f"{c:g}" for c in rgba))


def _contact(link: Any, values: dict[str, float]) -> None:
    friction = [values[k] for k in ("mu1", "mu2") if k in values]
    for collision in link.iterchildren("collision"):
        properties = collision.find(f"{{{DRAKE_NS}}}proximity_properties")
        if properties is None:
            properties = etree.SubElement(
                collision, f"{{{DRAKE_NS}}}proximity_properties", nsmap={"drake": DRAKE_NS}
            )
        entries: dict[str, float] = {}
        if friction:
            mean = float(np.mean(friction))
            entries["mu_dynamic"] = entries["mu_static"] = mean
        if "kp" in values:
            entries["point_contact_stiffness"] = values["kp"]
            if "kd" in values and values["kp"] > 0:
                entries["hunt_crossley_dissipation"] = values["kd"] / (
                    values["kp"] * KD_REFERENCE_PENETRATION
                )
        for key, value in entries.items():
            etree.SubElement(properties, f"{{{DRAKE_NS}}}{key}", value=f"{value:.12g}")


def _welded_to_mass(root: Any, links: dict[str, Any]) -> set[str]:
    """Links without ``<inertial>`` that fixed joints tie to a link with mass.

    Gazebo lumps links joined by fixed joints into one body, so such a link (a
    ``base_footprint``, a sensor frame) adds no mass there; Drake welds it massless.
    """
    groups: dict[str, set[str]] = {name: {name} for name in links}
    for joint in root.iterchildren("joint"):
        if joint.get("type") != "fixed":
            continue
        parent, child = joint.find("parent"), joint.find("child")
        a = parent.get("link") if parent is not None else None
        b = child.get("link") if child is not None else None
        if a in groups and b in groups and groups[a] is not groups[b]:
            merged = groups[a] | groups[b]
            for name in merged:
                groups[name] = merged
    massless = {name for name, link in links.items() if link.find("inertial") is None}
    return {name for name in massless if groups[name] - massless}


def _fix_inertial(link: Any, link_name: str, model: SimModel, where: str) -> None:
    inertial = link.find("inertial")
    mass_element = inertial.find("mass") if inertial is not None else None
    mass = _float(mass_element.get("value")) if mass_element is not None else None
    if inertial is None or mass is None or not mass > 0:
        problem = "has no <inertial>" if inertial is None else f"has mass {mass}"
        model.warnings.append(
            f"{where}: link '{link_name}' {problem}; using SDFormat's default "
            f"({DEFAULT_MASS:g} kg, {DEFAULT_MOMENT:g} kg m^2), as Gazebo does for SDF"
        )
        if inertial is not None:
            link.remove(inertial)
        inertial = etree.SubElement(link, "inertial")
        etree.SubElement(inertial, "mass", value=f"{DEFAULT_MASS:g}")
        m = f"{DEFAULT_MOMENT:g}"
        etree.SubElement(inertial, "inertia", ixx=m, iyy=m, izz=m, ixy="0", ixz="0", iyz="0")
        return
    inertia = inertial.find("inertia")
    if inertia is None:
        return
    values = [_float(inertia.get(k, "0")) for k in ENTRIES]
    if any(v is None for v in values):
        return  # malformed numbers are the URDF parser's to report
    repair = repaired([float(v) for v in values if v is not None], link_name, where)
    if repair is None:
        return
    fixed, warning = repair
    model.warnings.append(warning)
    for key, value in zip(ENTRIES, fixed, strict=True):
        inertia.set(key, f"{value:.12g}")


def _number(element: Any, where: str) -> float:
    value = _float((element.text or "").strip())
    if value is None or not np.isfinite(value) or value < 0:
        raise SimulationError(
            f"{where}: <{element.tag}> must be a number >= 0, got '{(element.text or '').strip()}'"
        )
    return value


def _float(text: str | None) -> float | None:
    try:
        return float(text) if text is not None else None
    except ValueError:
        return None


def _truth(text: str) -> bool:
    return text.strip().lower() in ("1", "true", "yes", "on")
