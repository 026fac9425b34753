"""From a file, a ``urdf/`` name or an XML string to a :class:`SimModel` the simulator can spawn."""

from __future__ import annotations

import os
from pathlib import Path

from workbench.errors import ModelError, SimulationError
from workbench.sim.model_spec import SimModel


def xml_format(xml: str) -> str | None:
    """``"urdf"``, ``"sdf"`` or None, from the root element of ``xml``."""
    from lxml import etree

    try:
        root = etree.fromstring(xml.strip().encode())
    except etree.XMLSyntaxError:
        return None
    tag = root.tag if isinstance(root.tag, str) else ""
    if tag == "robot":
        return "urdf"
    if tag in ("sdf", "model", "gazebo"):
        return "sdf"
    return None


def sim_model_from_xml(
    xml: str, *, name: str | None, source: str, base_dir: Path | None = None
) -> SimModel:
    """A model from URDF or SDF text (a spawn request's ``model_xml``, a parameter).

    Args:
        xml: The URDF or SDF text.
        name: The model's name in the world (None: the file's own).
        source: Where the text came from, for messages.
        base_dir: Folder relative mesh paths are resolved against (default: cwd).

    Raises:
        SimulationError: The text is neither URDF nor SDF, or cannot be loaded.
    """
    from workbench.sim.gazebo_sdf import sim_model_from_sdf
    from workbench.sim.gazebo_urdf import sim_model_from_urdf

    kind = xml_format(xml)
    if kind == "urdf":
        from workbench.model import RobotDescription

        folder = base_dir if base_dir is not None else Path.cwd()
        try:
            description = RobotDescription.from_text(xml, folder / "robot_description.urdf")
        except ModelError as error:
            raise SimulationError(f"{source}: {error.message}", hint=error.hint) from None
        return sim_model_from_urdf(description, name, source=source)
    if kind == "sdf":
        return sim_model_from_sdf(xml, name=name, source=source, base_dir=base_dir)
    raise SimulationError(
        f"{source}: the model is neither URDF (<robot>) nor SDF (<sdf>/<model>)",
        hint="spawn a .urdf, .urdf.xacro or .sdf file",
    )


def load_sim_model(
    source: str | os.PathLike[str],
    name: str | None = None,
    mappings: dict[str, str] | None = None,
) -> SimModel:
    """A model from a file (URDF, xacro or SDF) or a name in ``urdf/`` (``"simple_box"``).

    Raises:
        SimulationError: Not found, unreadable, or not loadable.
    """
    from workbench.model import RobotDescription
    from workbench.sim.gazebo_sdf import sim_model_from_sdf
    from workbench.sim.gazebo_urdf import sim_model_from_urdf

    try:
        description = RobotDescription.load(source, mappings)
    except ModelError as error:
        raise SimulationError(str(error.message), path=error.path, hint=error.hint) from None
    if description.format == "urdf":
        return sim_model_from_urdf(description, name, source=str(description.path))
    return sim_model_from_sdf(
        description.text,
        name=name,
        source=str(description.path),
        base_dir=description.path.parent,
    )
