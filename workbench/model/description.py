"""A robot description read, expanded and parsed once, then loaded into as many plants as needed.

The planner, the simulator, the viewer and the robot state publisher each build
their own Drake diagram. They all start from one :class:`RobotDescription`:
the file is found, read (xacro expanded) and parsed here exactly once, and its
mesh URIs are resolved once; each ``load_robot(description, ...)`` then only
hands the prepared text to Drake's parser for its own plant.

Example::

    from workbench.model import RobotDescription, load_robot

    description = RobotDescription.load("robot_arm")
    robot_for_viewer = load_robot(description)
    robot_for_sim = load_robot(description, time_step=0.001, finalize=False)
"""

from __future__ import annotations

import copy
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lxml import etree

from workbench.errors import ModelError
from workbench.model.meshes import prepare_mesh
from workbench.model.packages import PackageResolver
from workbench.model.sources import read_description, resolve_robot_path
from workbench.model.tree import checked_tree
from workbench.model.urdf_for_drake import adapt_for_drake
from workbench.model.urdf_xml import UrdfDocument, parse_urdf_text

if TYPE_CHECKING:
    from workbench.model.info import JointInfo
    from workbench.model.robot import Robot
    from workbench.model.sdf_prepare import PreparedSdf


@dataclass(eq=False)
class RobotDescription:
    """One robot description file, resolved and parsed.

    Build it with :meth:`load` (a name from ``urdf/`` or a path) or :meth:`from_text`
    (URDF XML, e.g. a ``robot_description`` parameter); pass it wherever a robot
    source is accepted (``load_robot``, ``MotionPlanner``, ``World.add_robot``,
    ``RobotStatePublisher``).

    Attributes:
        path: The description file (for ``from_text``, the file name errors should show).
        format: ``"urdf"`` or ``"sdf"``.
        text: The URDF/SDF XML after xacro.
        expanded: True when ``text`` came out of xacro.
        mappings: The xacro arguments used.
        document: The parsed URDF (links, joints with limits, materials); None for SDF.
        packages: ``package://`` name -> directory, for the file's meshes and Drake's parser.
    """

    path: Path
    format: str
    text: str
    expanded: bool = False
    mappings: dict[str, str] = field(default_factory=dict)
    document: UrdfDocument | None = None
    packages: PackageResolver = field(default_factory=PackageResolver)
    _root_link: str | None = field(default=None, init=False, repr=False)
    _guarded: bool = field(default=False, init=False, repr=False)
    _prepared: Any = field(default=None, init=False, repr=False)

    @classmethod
    def load(
        cls, source: str | os.PathLike[str], mappings: dict[str, str] | None = None
    ) -> RobotDescription:
        """Find, read (expanding xacro) and parse a description: the only place that does.

        Args:
            source: A name from ``urdf/`` (``"robot_arm"``) or a URDF, SDF or xacro path.
            mappings: xacro arguments (``name -> value``).

        Raises:
            ModelError: Not found, unreadable, failing xacro, or malformed URDF.
        """
        path = resolve_robot_path(source)
        text = read_description(path, mappings)
        document = parse_urdf_text(text.text, path) if text.format == "urdf" else None
        return cls(
            path=path,
            format=text.format,
            text=text.text,
            expanded=text.expanded,
            mappings=dict(mappings or {}),
            document=document,
            packages=PackageResolver(path),
        )

    @classmethod
    def from_text(cls, text: str, path: str | os.PathLike[str] | None = None) -> RobotDescription:
        """A description from URDF XML that is not in a file (e.g. ``robot_description``).

        Args:
            text: The URDF XML.
            path: Where it notionally lives: relative mesh paths and the package of
                ``package://`` URIs are found from there (default: the working directory).

        Raises:
            ModelError: Malformed URDF.
        """
        where = Path(path) if path is not None else Path.cwd() / "robot_description.urdf"
        document = parse_urdf_text(text, where)
        return cls(
            path=where, format="urdf", text=text, document=document, packages=PackageResolver(where)
        )

    # --- what the loaders need -------------------------------------------------------

    @property
    def name(self) -> str | None:
        """The robot name in the file (None for SDF, whose model names Drake reads)."""
        return self.document.name if self.document is not None else None

    @property
    def joints(self) -> list[JointInfo]:
        """Every URDF joint with origin, axis and limits, in file order (empty for SDF)."""
        return list(self.document.joints) if self.document is not None else []

    def root_link(self) -> str:
        """The URDF's root link, after checking the tree.

        Raises:
            ModelError: A broken tree (cycles, several roots, unknown links).
        """
        if self.document is None:
            raise ModelError(
                "an SDF model's root is known only once Drake loaded it", path=self.path
            )
        if self._root_link is None:
            self._root_link = _checked_root(self.document)
        return self._root_link

    def prepared_text(self, model_name: str | None = None) -> str:
        """The URDF text for Drake: as ROS reads it (:func:`adapt_for_drake`), mesh URIs absolute.

        Meshes are resolved (and converted where Drake needs it) on the first call only.

        Args:
            model_name: Rename the robot (to load one description twice into a plant).
        """
        if self.document is None:
            raise ModelError("only a URDF has prepared text", path=self.path)
        if self._prepared is None:
            self._prepared = _prepared_root(self.document, self.packages)
        root = self._prepared
        if model_name:
            root = copy.deepcopy(root)
            root.set("name", model_name)
        # Blank lines in place of the prolog keep Drake's line numbers those of the file.
        padding = "\n" * ((self.document.root.sourceline or 1) - 1)
        return padding + etree.tostring(root, encoding="unicode")

    def prepared_sdf(self) -> PreparedSdf | None:
        """An SDF model as Drake is given it (includes expanded, nested models merged, meshes
        resolved through ``GAZEBO_MODEL_PATH`` as ``workbench sim`` does); None for an SDF
        file whose top is not a ``<model>`` (Drake reads it itself). Prepared on the first call.

        Raises:
            ModelError: A URDF, or an include, mesh or ``model://`` URI that cannot be resolved.
        """
        if self.document is not None:
            raise ModelError("only an SDF model has prepared SDF text", path=self.path)
        if self._prepared is None:
            from workbench.model.sdf_prepare import prepare_sdf

            self._prepared = prepare_sdf(self.text, self.path) or False
        return self._prepared or None

    def instantiate(self, **options: Any) -> Robot:
        """Load this description into a new (or the given) Drake plant: ``load_robot(self, ...)``."""
        from workbench.model.loader import load_robot

        return load_robot(self, **options)


def describe_robot(
    source: str | os.PathLike[str] | RobotDescription | Any,
    mappings: dict[str, str] | None = None,
) -> RobotDescription:
    """The description of ``source``: itself, a loaded robot's, or a new one read from a file.

    Args:
        source: A :class:`RobotDescription`, a loaded ``Robot``, a name from ``urdf/`` or a path.
        mappings: xacro arguments, used only when a file is read.

    Raises:
        ModelError: xacro arguments that differ from those ``source`` was expanded with.
    """
    carried = getattr(source, "description", None)  # a loaded Robot carries its description
    description = source if isinstance(source, RobotDescription) else None
    if description is None and isinstance(carried, RobotDescription):
        description = carried
    if description is None:
        return RobotDescription.load(source, mappings)  # type: ignore[arg-type]
    if mappings and dict(mappings) != description.mappings:
        raise ModelError(
            "xacro arguments given for a description that is already expanded",
            path=description.path,
            hint="pass them to RobotDescription.load(path, mappings) instead",
        )
    return description


def _prepared_root(document: UrdfDocument, packages: PackageResolver) -> Any:
    path = document.path
    base = path.parent if path is not None else Path.cwd()
    root = copy.deepcopy(document.root)
    adapt_for_drake(root)
    for mesh in root.iter("mesh"):
        filename = mesh.get("filename")
        if not filename:
            continue
        resolved = packages.resolve(filename, base, where=path, line=mesh.sourceline)
        mesh.set("filename", prepare_mesh(resolved, where=path, line=mesh.sourceline).as_uri())
    return root


def prepared_urdf(document: UrdfDocument) -> str:
    """The URDF text with every mesh URI replaced by an absolute path Drake can read.

    Raises:
        ModelError: Unknown packages, missing meshes, unsupported mesh formats.
    """
    root = _prepared_root(document, PackageResolver(document.path))
    padding = "\n" * ((document.root.sourceline or 1) - 1)
    return padding + etree.tostring(root, encoding="unicode")


def _checked_root(document: UrdfDocument) -> str:
    root, _ = checked_tree(document)
    return root
