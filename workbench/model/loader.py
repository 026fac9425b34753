"""Load URDF, SDF and xacro descriptions into a Drake MultibodyPlant."""

from __future__ import annotations

import contextlib
import copy
import logging
import os
import re
from pathlib import Path
from typing import Any

from lxml import etree

from workbench.errors import ModelError
from workbench.model.info import LinkInfo
from workbench.model.meshes import prepare_mesh
from workbench.model.packages import PackageResolver
from workbench.model.robot import Robot, joint_info_from_plant
from workbench.model.sources import read_description, resolve_robot_path
from workbench.model.tree import build_tree
from workbench.model.urdf_xml import UrdfDocument, parse_urdf_text


class DrakeLoadError(ModelError):
    """Drake refused a description that workbench could read."""


_LOG = logging.getLogger("workbench.model")


class _Collector(logging.Handler):
    def __init__(self) -> None:
        super().__init__(logging.DEBUG)
        self.messages: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        if record.levelno >= logging.WARNING:
            self.messages.append(record.getMessage())


@contextlib.contextmanager
def _drake_warnings(path: Path, into: list[str]):
    """Collect Drake's parser warnings, name the real file in them, and log them once."""
    logger = logging.getLogger("drake")
    collector = _Collector()
    propagate = logger.propagate
    logger.addHandler(collector)
    logger.propagate = False
    try:
        yield
    finally:
        logger.removeHandler(collector)
        logger.propagate = propagate
        for message in collector.messages:
            text = " ".join(message.replace("<literal-string>.urdf", str(path)).split())
            into.append(text)
            _LOG.warning("%s", text)


def load_document(
    source: str | os.PathLike[str], mappings: dict[str, str] | None = None
) -> UrdfDocument:
    """Find, read (expanding xacro) and parse a URDF without loading it into Drake.

    Raises:
        ModelError: The file cannot be found, read or parsed, or it is SDF.
    """
    path = resolve_robot_path(source)
    description = read_description(path, mappings)
    if description.format != "urdf":
        raise ModelError("this is an SDF file; only URDF can be read here", path=path)
    return parse_urdf_text(description.text, path)


def prepared_urdf(document: UrdfDocument) -> str:
    """The URDF text with every mesh URI replaced by an absolute path Drake can read.

    Raises:
        ModelError: Unknown packages, missing meshes, unsupported mesh formats.
    """
    path = document.path
    base = path.parent if path is not None else Path.cwd()
    resolver = PackageResolver(path)
    root = copy.deepcopy(document.root)
    for mesh in root.iter("mesh"):
        filename = mesh.get("filename")
        if not filename:
            continue
        resolved = resolver.resolve(filename, base, where=path, line=mesh.sourceline)
        mesh.set("filename", prepare_mesh(resolved, where=path, line=mesh.sourceline).as_uri())
    _fill_forward_materials(root)
    # Blank lines in place of the prolog keep Drake's line numbers those of the file.
    padding = "\n" * ((document.root.sourceline or 1) - 1)
    return padding + etree.tostring(root, encoding="unicode")


def _fill_forward_materials(root) -> None:
    """Give colour-less material references the colour defined later in the file.

    ROS accepts ``<material name="black"/>`` in a visual before any
    ``black`` has a colour (and draws it transparent); Drake refuses it. The
    colour the file gives ``black`` later is used instead.
    """
    defined = {m.get("name") for m in root.iterchildren("material")}
    later: dict[str, object] = {}
    for material in root.iter("material"):
        color = material.find("color")
        if color is not None and material.get("name") not in later:
            later[material.get("name")] = color
    for link in root.iterchildren("link"):
        for material in link.iter("material"):
            name = material.get("name")
            has_colour = material.find("color") is not None or material.find("texture") is not None
            if has_colour:
                defined.add(name)
            elif name not in defined:
                if name in later:
                    material.append(copy.deepcopy(later[name]))
                    defined.add(name)
                else:
                    material.getparent().remove(material)


def _raise_tree_problems(document: UrdfDocument) -> str:
    tree = build_tree(document)
    if tree.problems:
        first = tree.problems[0]
        raise ModelError(
            f"{first.element}: {first.message}",
            path=document.path,
            line=first.line,
            hint=first.hint or None,
        )
    assert tree.root is not None
    for joint in document.joints:
        # Drake aborts the whole process on reversed limits, so they never reach it.
        if joint.lower is not None and joint.upper is not None and joint.lower > joint.upper:
            raise ModelError(
                f"joint '{joint.name}': lower limit {joint.lower:g} is above upper limit "
                f"{joint.upper:g}",
                path=document.path,
                line=joint.line,
                hint="swap them",
            )
    return tree.root


def _drake_error(
    error: Exception, path: Path, document: UrdfDocument | None = None
) -> DrakeLoadError:
    text = str(error).strip()
    lines = [line for line in text.splitlines() if line.strip()]
    message = lines[0] if lines else type(error).__name__
    line_number = None
    match = re.match(r"^(?:.*?):(\d+): (?:error: )?(.*)$", message)
    if match:
        line_number, message = int(match.group(1)), match.group(2)
    element = document.element_at(line_number) if document is not None else "model"
    where = "" if element == "model" else f"{element}: "
    return DrakeLoadError(
        f"{where}Drake cannot load the model: {message}",
        path=path,
        line=line_number,
        hint="fix that element; 'workbench check' lists every problem",
    )


def load_robot(
    source: str | os.PathLike[str],
    *,
    floating_base: bool = False,
    builder: Any = None,
    time_step: float = 0.0,
    finalize: bool = True,
    plant: Any = None,
    model_name: str | None = None,
    mappings: dict[str, str] | None = None,
) -> Robot:
    """Load a robot description into a Drake MultibodyPlant.

    Args:
        source: A path (URDF, SDF or ``.xacro``) or a name from ``urdf/`` such as
            ``"robot_arm"``. ``package://`` URIs resolve through the file's own
            package.xml, the checkout's ``urdf/`` and ``WORKBENCH_PACKAGE_PATH`` /
            ``ROS_PACKAGE_PATH``.
        floating_base: Leave the root link free (a 6-dof floating joint) instead of
            welding it to the world frame at the origin.
        builder: A ``DiagramBuilder`` to add the plant and scene graph to; None makes one.
        time_step: Plant time step in seconds (0 = continuous).
        finalize: Finalize the plant. Pass False to add obstacles or further models,
            then call :meth:`Robot.finalize`.
        plant: Add to this existing (unfinalized) plant instead of creating one.
        model_name: Rename the model instance (to load one description twice).
        mappings: xacro arguments (``name -> value``).

    Returns:
        The loaded :class:`Robot`.

    Raises:
        ModelError: The description cannot be found, read, or loaded; the message
            names the file and line.
    """
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import AddMultibodyPlantSceneGraph
    from pydrake.systems.framework import DiagramBuilder

    path = resolve_robot_path(source)
    description = read_description(path, mappings)
    document: UrdfDocument | None = None
    if description.format == "urdf":
        document = parse_urdf_text(description.text, path)
        if model_name:
            document.root.set("name", model_name)
            document.name = model_name
        root_link = _raise_tree_problems(document)
        text = prepared_urdf(document)

    scene_graph = None
    if plant is None:
        builder = builder if builder is not None else DiagramBuilder()
        plant, scene_graph = AddMultibodyPlantSceneGraph(builder, time_step)
    elif builder is not None and builder.HasSubsystemNamed("scene_graph"):
        scene_graph = builder.GetSubsystemByName("scene_graph")
    if plant.is_finalized():
        raise ModelError(
            "cannot add a model to a finalized plant",
            path=path,
            hint="load the first robot with finalize=False",
        )

    parser = Parser(plant)
    PackageResolver(path).fill_package_map(parser.package_map())
    warnings: list[str] = []
    try:
        with _drake_warnings(path, warnings):
            if document is not None:
                instances = parser.AddModelsFromString(text, "urdf")
            else:
                instances = parser.AddModels(str(path))  # type: ignore[arg-type]
    except RuntimeError as error:
        raise _drake_error(error, path, document) from None
    if not instances:
        raise ModelError("the file defines no model", path=path)
    instance = instances[0]
    name = plant.GetModelInstanceName(instance)

    if document is not None:
        links = document.link_infos()
        joints = list(document.joints)
        materials = {
            material.name: material.rgba
            for material in document.materials.values()
            if material.rgba is not None
        }
    else:
        bodies = [plant.get_body(index) for index in plant.GetBodyIndices(instance)]
        links = [
            LinkInfo(
                body.name(),
                bool(plant.GetVisualGeometriesForBody(body)),
                bool(plant.GetCollisionGeometriesForBody(body)),
                float(body.default_mass()),
            )
            for body in bodies
        ]
        joints = [
            joint_info_from_plant(plant.get_joint(index))
            for index in plant.GetJointIndices(instance)
        ]
        children = {joint.child for joint in joints}
        roots = [link.name for link in links if link.name not in children]
        root_link = roots[0] if roots else links[0].name
        materials = {}

    # A root link called "world" is Drake's world body: the model is fixed already.
    if not floating_base and root_link != "world":
        try:
            root_body = plant.GetBodyByName(root_link, instance)
            already_welded = any(
                plant.get_joint(index).child_body().index() == root_body.index()
                for index in plant.GetJointIndices(instance)
            )
            if not already_welded:
                plant.WeldFrames(plant.world_frame(), root_body.body_frame())
        except RuntimeError as error:
            raise _drake_error(error, path, document) from None

    robot = Robot(
        name=name,
        path=path,
        builder=builder,
        plant=plant,
        scene_graph=scene_graph,
        model_instance=instance,
        links=links,
        joints=joints,
        root_link=root_link,
        floating_base=floating_base,
        materials=materials,
        document=document,
    )
    robot.load_warnings = warnings
    if finalize:
        try:
            robot.finalize()
        except RuntimeError as error:
            raise _drake_error(error, path, document) from None
    return robot
