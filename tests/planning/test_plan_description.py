"""One robot description feeds the planner, the simulator and the state publisher.

The description is read, xacro-expanded and parsed once; each consumer loads
it into its own Drake diagram. Counted by wrapping the one read and the one
parse function that :class:`RobotDescription` uses.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np
import pytest

import workbench.model.description as description_module
from workbench.model import RobotDescription
from workbench.paths import urdf_dir


@pytest.fixture
def counted(monkeypatch):
    """Counts of description reads, URDF parses and direct reads of the arm's file."""
    counts: Counter[str] = Counter()
    real_read = description_module.read_description
    real_parse = description_module.parse_urdf_text
    arm_file = (urdf_dir() / "robot_arm.urdf").resolve()
    real_read_text, real_read_bytes = Path.read_text, Path.read_bytes

    def read(*args, **kwargs):
        counts["read"] += 1
        return real_read(*args, **kwargs)

    def parse(*args, **kwargs):
        counts["parse"] += 1
        return real_parse(*args, **kwargs)

    def read_text(self, *args, **kwargs):
        if self.resolve() == arm_file:
            counts["file"] += 1
        return real_read_text(self, *args, **kwargs)

    def read_bytes(self, *args, **kwargs):
        if self.resolve() == arm_file:
            counts["file"] += 1
        return real_read_bytes(self, *args, **kwargs)

    monkeypatch.setattr(description_module, "read_description", read)
    monkeypatch.setattr(description_module, "parse_urdf_text", parse)
    monkeypatch.setattr(Path, "read_text", read_text)
    monkeypatch.setattr(Path, "read_bytes", read_bytes)
    return counts


def test_plan_and_execute_parses_the_robot_once(counted):
    """What ``workbench plan robot_arm --to home --execute`` does, in process."""
    from workbench.planning.config import load_config
    from workbench.planning.execute import execute
    from workbench.planning.pipeline import MotionPlanner

    planner = MotionPlanner(config=load_config("robot_arm"))
    result = planner.plan("home", start="random", seed=3)
    report = execute(planner, result, settle_time=0.1)
    assert report.max_error.shape == (len(planner.joint_names),)
    assert counted == Counter(read=1, parse=1, file=1)


def _movable_fk(robot, q) -> dict[str, np.ndarray]:
    return {name: X.GetAsMatrix4() for name, X in robot.forward_kinematics(q).items()}


def test_planner_world_and_state_publisher_agree(counted):
    from workbench.bus import Bus, Node
    from workbench.planning.config import load_config
    from workbench.planning.pipeline import MotionPlanner
    from workbench.robot_state.state_publisher import RobotStatePublisher
    from workbench.sim import World
    from workbench.spatial import matrix_from_msg

    description = RobotDescription.load("robot_arm")
    planner = MotionPlanner(config=load_config("robot_arm"), description=description)
    world = World(ground=False)
    sim_robot = world.add_robot(description)
    world.build()
    bus = Bus(threaded=False)
    try:
        publisher = RobotStatePublisher(description, node=Node("rsp", bus=bus))
        assert counted == Counter(read=1, parse=1, file=1)

        names = planner.robot.joint_names
        assert names == sim_robot.joint_names == publisher.robot.joint_names
        assert world.joint_names(sim_robot.name) == names
        for robot in (sim_robot, publisher.robot):
            np.testing.assert_array_equal(robot.lower_limits, planner.robot.lower_limits)
            np.testing.assert_array_equal(robot.upper_limits, planner.robot.upper_limits)
        # three plants, not one shared
        assert len({id(planner.robot.plant), id(world.plant), id(publisher.robot.plant)}) == 3

        rng = np.random.default_rng(1)
        lower, upper = planner.robot.lower_limits, planner.robot.upper_limits
        for _ in range(5):
            q = rng.uniform(lower, upper)
            expected = _movable_fk(planner.robot, q)
            by_publisher = _movable_fk(publisher.robot, q)
            assert by_publisher.keys() == expected.keys()
            for link, X in by_publisher.items():
                np.testing.assert_allclose(X, expected[link], atol=1e-12)
            world.set_positions(sim_robot.name, q)
            plant_context = world.plant.GetMyContextFromRoot(world.context)
            for body in sim_robot.link_bodies():
                X_WB = world.plant.EvalBodyPoseInWorld(plant_context, body).GetAsMatrix4()
                np.testing.assert_allclose(X_WB, expected[body.name()], atol=1e-12)
            joints = publisher.robot.movable_joints
            for joint, msg in zip(joints, publisher.joint_transforms(joints, q, 0), strict=True):
                X_PC = np.linalg.inv(expected[joint.parent]) @ expected[joint.child]
                np.testing.assert_allclose(matrix_from_msg(msg), X_PC, atol=1e-12)
    finally:
        bus.shutdown()
