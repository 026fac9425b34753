"""Robot descriptions: find, read, check, draw and load URDF/SDF/xacro into Drake.

Importing this package is cheap; pydrake is imported when a robot is loaded
and pydot when a graph is drawn.

Example::

    from workbench.model import check_robot, graph_robot, load_robot

    print(check_robot("robot_arm"))          # check_urdf's report + findings
    graph_robot("robot_arm")                 # a pydot graph; Jupyter shows it
    robot = load_robot("robot_arm")          # urdf/robot_arm.urdf, welded to the world
    poses = robot.forward_kinematics(robot.default_positions())
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from workbench.model.builder import ModelBuilder
from workbench.model.check import CheckReport, check_robot
from workbench.model.description import RobotDescription, describe_robot
from workbench.model.findings import Finding
from workbench.model.info import JointInfo, LinkInfo
from workbench.model.loader import as_robot, load_document, load_robot
from workbench.model.robot import Robot
from workbench.model.sources import available_robots, resolve_robot_path

if TYPE_CHECKING:
    from workbench.model.graph import RobotGraph


def graph_robot(source: str | os.PathLike[str]) -> RobotGraph:
    """The link/joint graph of a description (``urdf_to_graphviz``) as a pydot graph.

    Jupyter draws it (needs graphviz ``dot``); ``graph.source`` is the ``.gv`` text
    and ``graph.write_pdf(path)`` writes a PDF.
    """
    from workbench.model.graph import robot_graph

    return robot_graph(load_document(source))


__all__ = [
    "CheckReport",
    "Finding",
    "JointInfo",
    "LinkInfo",
    "ModelBuilder",
    "Robot",
    "RobotDescription",
    "as_robot",
    "available_robots",
    "check_robot",
    "describe_robot",
    "graph_robot",
    "load_document",
    "load_robot",
    "resolve_robot_path",
]
