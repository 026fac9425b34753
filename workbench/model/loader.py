"""Load URDF, SDF and xacro descriptions into a Drake MultibodyPlant."""

from __future__ import annotations

import contextlib
import logging
import os
import re
from pathlib import Path
from typing import Any

from workbench.errors import ModelError
from workbench.model.description import RobotDescription, describe_robot
from workbench.model.description import prepared_urdf as prepared_urdf  # re-exported
from workbench.model.drake_guard import ModelInputError, check_sdf_file, check_urdf_element
from workbench.model.info import LinkInfo
from workbench.model.robot import Robot, joint_info_from_plant
from workbench.model.sdf_names import shown_name
from workbench.model.urdf_xml import UrdfDocument


class DrakeLoadError(ModelError):
    """Drake refused a description that workbench could read."""


_LOG = logging.getLogger("workbench.model")
#: Longest part of a Drake message kept in an error, characters.
_LONGEST_MESSAGE = 500


#: URDF tags for ROS's drivers that Drake ignores with a warning; not worth one when loading
#: (``workbench check`` still lists them).
_ROS_RUNTIME_TAGS = ("safety_controller", "calibration")
#: Drake's warning about an SDFormat element it does not read; group 1 is the element.
_IGNORED_SDF = re.compile(r"Ignoring unsupported SDFormat element in \w+: (\w+)")


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
        ignored: dict[str, int] = {}
        for message in collector.messages:
            for literal in ("<literal-string>.urdf", "<literal-string>.sdf"):
                message = message.replace(literal, str(path))
            text = shown_name(" ".join(message.split()))
            match = _IGNORED_SDF.search(text)
            if match:  # Gazebo's own elements (sensors, material scripts): one line for all
                ignored[match.group(1)] = ignored.get(match.group(1), 0) + 1
                continue
            into.append(text)
            quiet = any(f"tag '{tag}' found" in text for tag in _ROS_RUNTIME_TAGS)
            _LOG.log(logging.DEBUG if quiet else logging.WARNING, "%s", text)
        if ignored:
            counts = ", ".join(f"{tag} ({n})" for tag, n in sorted(ignored.items()))
            text = f"Drake does not read these SDFormat elements (Gazebo's own): {counts}"
            into.append(text)
            _LOG.debug("%s: %s", path, text)


def load_document(
    source: str | os.PathLike[str], mappings: dict[str, str] | None = None
) -> UrdfDocument:
    """Find, read (expanding xacro) and parse a URDF without loading it into Drake.

    Raises:
        ModelError: The file cannot be found, read or parsed, or it is SDF.
    """
    description = describe_robot(source, mappings)
    if description.document is None:
        raise ModelError("this is an SDF file; only URDF can be read here", path=description.path)
    return description.document


def _mesh_line(message: str, description: RobotDescription | None) -> int | None:
    """The line of the ``<mesh>`` whose file Drake names in ``message``, if any."""
    document = description.document if description is not None else None
    if document is None or description is None:
        return None
    base = description.path.parent
    for mesh in document.root.iter("mesh"):
        try:
            resolved = description.packages.resolve(mesh.get("filename", ""), base)
        except ModelError:
            continue
        if str(resolved.resolve()) in message:
            return mesh.sourceline
    return None


def _drake_error(
    error: Exception,
    path: Path,
    document: UrdfDocument | None = None,
    description: RobotDescription | None = None,
) -> DrakeLoadError:
    text = str(error).strip()
    lines = [line for line in text.splitlines() if line.strip()]
    message = lines[0] if lines else type(error).__name__
    line_number = None
    match = re.match(r"^(?:.*?):(\d+): (?:error: )?(.*)$", message)
    if match:
        line_number, message = int(match.group(1)), match.group(2)
    message = message.removeprefix("error: ")
    # A mesh parser's "last read: '...'" quotes the mesh file, which may be anyone's file
    message = re.sub(r";? ?last read: .*$", "", message)
    if line_number is None:
        # A mesh Drake cannot read: name the link that uses it, not the model.
        line_number = _mesh_line(message, description)
    if len(message) > _LONGEST_MESSAGE:  # Drake repeats names from the file, however long
        message = message[: _LONGEST_MESSAGE - 3] + "..."
    element = document.element_at(line_number) if document is not None else "model"
    where = "" if element == "model" else f"{element}: "
    return DrakeLoadError(
        f"{where}Drake cannot load the model: {message}",
        path=path,
        line=line_number,
        hint="fix that element; 'workbench check' lists every problem",
    )


def load_robot(
    source: str | os.PathLike[str] | RobotDescription | Robot,
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
        source: A path (URDF, SDF or ``.xacro``), a name from ``urdf/`` such as
            ``"robot_arm"``, a :class:`RobotDescription` (nothing is read or parsed
            again) or a loaded :class:`Robot` (its description is reused).
            ``package://`` URIs resolve through the file's own package.xml, the
            checkout's ``urdf/`` and ``WORKBENCH_PACKAGE_PATH`` / ``ROS_PACKAGE_PATH``.
        floating_base: Leave the root link free (a 6-dof floating joint) instead of
            welding it to the world frame at the origin.
        builder: A ``DiagramBuilder`` to add the plant and scene graph to; None makes one.
        time_step: Plant time step in seconds (0 = continuous).
        finalize: Finalize the plant. Pass False to add obstacles or further models,
            then call :meth:`Robot.finalize`.
        plant: Add to this existing (unfinalized) plant instead of creating one.
        model_name: Rename the model instance (to load one description twice).
        mappings: xacro arguments (``name -> value``), used when a file is read.

    Returns:
        The loaded :class:`Robot`.

    Raises:
        ModelError: The description cannot be found, read, or loaded; the message
            names the file and line.
    """
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import AddMultibodyPlantSceneGraph
    from pydrake.systems.framework import DiagramBuilder

    description = describe_robot(source, mappings)
    path = description.path
    document = description.document
    _guard(description)
    sdf = None
    if document is not None:
        root_link = description.root_link()
        text = description.prepared_text(model_name)
    else:
        sdf = description.prepared_sdf()

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
    description.packages.fill_package_map(parser.package_map())
    warnings: list[str] = []
    try:
        with _drake_warnings(path, warnings):
            if document is not None:
                instances = parser.AddModelsFromString(text, "urdf")
            elif sdf is not None:
                instances = parser.AddModelsFromString(sdf.text, "sdf")
            else:
                instances = parser.AddModels(str(path))  # type: ignore[arg-type]
    except (RuntimeError, ValueError) as error:  # pydrake raises ValueError for bad vectors
        raise _drake_error(error, path, document, description) from None
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
            raise _drake_error(error, path, document, description) from None

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
        description=description,
    )
    robot.load_warnings = (sdf.warnings if sdf is not None else []) + warnings
    if finalize:
        try:
            robot.finalize()
        except RuntimeError as error:
            raise _drake_error(error, path, document, description) from None
    return robot


def _guard(description: RobotDescription) -> None:
    """Check names and numbers Drake would abort or crash on (once per description)."""
    if description._guarded:
        return
    try:
        if description.document is not None:
            check_urdf_element(description.document.root, description.path)
        else:
            check_sdf_file(description.path)
    except ModelInputError as error:
        if not description.expanded:
            raise
        # Lines of xacro's output are not lines of the file the user edits.
        raise ModelInputError(error.message, path=error.path, hint=error.hint) from None
    description._guarded = True


def as_robot(source: str | os.PathLike[str] | RobotDescription | Robot) -> Robot:
    """``source`` itself when it is a loaded :class:`Robot`, else ``load_robot(source)``."""
    return source if isinstance(source, Robot) else load_robot(source)
