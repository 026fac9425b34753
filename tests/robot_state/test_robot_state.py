"""robot_state_publisher and joint_state_publisher on the in-process bus."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.bus import Bus, Node
from workbench.model import available_robots, load_robot
from workbench.msgs import Time
from workbench.msgs.sensor_msgs import JointState
from workbench.robot_state import (
    JointStatePublisher,
    RobotModelDisplay,
    RobotStatePublisher,
    ros_default_position,
)
from workbench.tf import Buffer, ExtrapolationException, TransformDataWarning, TransformListener


@pytest.fixture
def bus():
    b = Bus(threaded=False)
    yield b
    b.shutdown()


@pytest.fixture(scope="module")
def arm():
    return load_robot("robot_arm")


def joint_pose(joint, value: float) -> np.ndarray:
    """X_parent_child of a URDF joint at ``value``, from its origin and axis (no Drake)."""
    m = np.identity(4)
    m[:3, :3] = Rotation.from_euler("xyz", joint.rpy).as_matrix()
    m[:3, 3] = joint.xyz
    motion = np.identity(4)
    axis = np.asarray(joint.axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    if joint.type in ("revolute", "continuous"):
        motion[:3, :3] = Rotation.from_rotvec(axis * value).as_matrix()
    elif joint.type == "prismatic":
        motion[:3, 3] = axis * value
    return m @ motion


def pose_matrix(st) -> np.ndarray:
    m = np.identity(4)
    m[:3, :3] = Rotation.from_quat(st.rotation).as_matrix()
    m[:3, 3] = st.translation
    return m


def state(names, positions, stamp=None):
    msg = JointState()
    msg.header.stamp = Time(100) if stamp is None else stamp
    msg.name = list(names)
    msg.position = list(positions)
    return msg


def setup(bus, robot, **kwargs):
    buf = Buffer()
    TransformListener(buf, Node("listener", bus=bus))
    rsp = RobotStatePublisher(robot, Node("robot_state_publisher", bus=bus), **kwargs)
    pub = Node("driver", bus=bus).create_publisher("joint_states", JointState)
    return buf, rsp, pub


def drain(bus):
    while bus.spin_once(0.0):
        pass


def test_fixed_joints_static_and_moving_joints_match_the_urdf(bus, arm):
    buf, rsp, pub = setup(bus, arm)
    rng = np.random.default_rng(0)
    q = rng.uniform(arm.lower_limits, arm.upper_limits)
    pub.publish(state(arm.joint_names, q))
    drain(bus)
    assert rsp.published == 1
    values = dict(zip(arm.joint_names, q, strict=True))
    for joint in arm.joints:
        if joint.type == "fixed":
            # /tf_static: valid at any time
            st = buf.lookup(joint.parent, joint.child, 12345.0)
            assert buf.frames_info()[joint.child]["static"]
            np.testing.assert_allclose(pose_matrix(st), joint_pose(joint, 0.0), atol=1e-9)
        else:
            st = buf.lookup(joint.parent, joint.child, Time(100))
            np.testing.assert_allclose(
                pose_matrix(st), joint_pose(joint, values[joint.name]), atol=1e-9
            )
            with pytest.raises(ExtrapolationException):
                buf.lookup(joint.parent, joint.child, Time(101))


def test_mismatched_arrays_are_ignored_with_an_error(bus, arm):
    buf, rsp, pub = setup(bus, arm)
    pub.publish(state(arm.joint_names, [0.1]))
    pub.publish(state(arm.joint_names[:2], []))
    drain(bus)
    assert rsp.ignored_messages == 2
    assert rsp.published == 0
    assert not buf.frame_exists("shoulder_pitch_link")


def test_unknown_joint_names_are_ignored(bus, arm):
    buf, rsp, pub = setup(bus, arm)
    pub.publish(state(["no_such_joint", "shoulder_pan_joint"], [1.0, 0.5]))
    drain(bus)
    assert rsp.published == 1
    assert "no_such_joint" in rsp._warned
    st = buf.lookup("base_link", "shoulder_pan_link", Time(100))
    np.testing.assert_allclose(
        pose_matrix(st), joint_pose(arm.joint("shoulder_pan_joint"), 0.5), atol=1e-9
    )
    # joints not named in the message get no transform (as in ROS)
    assert not buf.frame_exists("elbow_roll_link")


def test_publish_frequency_limits_the_rate(bus, arm):
    buf, rsp, pub = setup(bus, arm, publish_frequency=10.0)
    for k in range(10):  # 10 messages 20 ms apart = 0.2 s
        pub.publish(state(arm.joint_names, np.zeros(7), Time(0, 100_000_000_000 + k * 20_000_000)))
    drain(bus)
    assert rsp.published == 2  # at 0 ms and at 100 ms
    # time going backwards (a bag loop) publishes again; the old buffer refuses it as tf2 does
    pub.publish(state(arm.joint_names, np.zeros(7), Time(50)))
    with pytest.warns(TransformDataWarning, match="TF_OLD_DATA"):
        drain(bus)
    assert rsp.published == 3


def test_joint_state_publisher_defaults_and_zeros(bus, arm):
    assert ros_default_position(-1.0, 1.0) == 0.0
    assert ros_default_position(0.2, 0.6) == pytest.approx(0.4)
    assert ros_default_position(-np.inf, np.inf) == 0.0
    jsp = JointStatePublisher(arm, Node("jsp", bus=bus), rate=0, zeros={"elbow_pitch_joint": 0.3})
    msg = jsp.publish()
    assert list(msg.name) == arm.joint_names
    expected = [
        0.3 if name == "elbow_pitch_joint" else ros_default_position(lo, hi)
        for name, lo, hi in zip(arm.joint_names, arm.lower_limits, arm.upper_limits, strict=True)
    ]
    np.testing.assert_allclose(msg.position, expected)
    from workbench.model.robot import UnknownJointError

    with pytest.raises(UnknownJointError, match="no_joint"):
        JointStatePublisher(arm, Node("jsp2", bus=bus), rate=0, zeros={"no_joint": 1.0})


def test_joint_state_publisher_feeds_robot_state_publisher_on_a_timer(bus, arm):
    buf, rsp, _ = setup(bus, arm)
    JointStatePublisher(arm, Node("jsp", bus=bus), rate=50.0)
    assert bus.spin_until(lambda: buf.frame_exists("wrist_roll_link"), timeout=5)
    buf.lookup("base_link", "gripper_finger_link1", 0)


class RecordingViewer:
    """Stands in for the Viewer: records the link poses a display sets."""

    def __init__(self):
        self.poses = {}
        outer = self

        class Meshcat:
            def SetTransform(self, path, X):  # noqa: N802 - Meshcat's name
                outer.poses[path] = X.GetAsMatrix4()

        self.meshcat = Meshcat()

    def show_robot(self, robot, q=None, prefix=None):
        return f"/robots/{robot.name}"


def movable_robots():
    names = []
    for name in available_robots():
        try:
            robot = load_robot(name)
        except Exception:  # noqa: BLE001 - a description that does not load is another test's job
            continue
        plant = robot.plant
        multi_dof = any(
            plant.get_joint(j).num_positions() > 1
            for j in plant.GetJointIndices(robot.model_instance)
        )
        # robot_state_publisher (as ROS's) publishes only 1-dof and fixed joints, so a
        # ball joint's child has no frame (RViz reports that link); not this test's case
        if robot.joint_names and not multi_dof:
            names.append(name)
    return names


@pytest.mark.parametrize("name", movable_robots())
def test_robot_state_publisher_drives_the_viewer_for_every_movable_model(bus, name):
    """joint_states -> robot_state_publisher -> tf -> RobotModelDisplay poses = Drake FK."""
    robot = load_robot(name)
    buf, rsp, pub = setup(bus, robot)
    rng = np.random.default_rng(1)
    low = np.where(np.isfinite(robot.lower_limits), robot.lower_limits, -np.pi)
    high = np.where(np.isfinite(robot.upper_limits), robot.upper_limits, np.pi)
    q = rng.uniform(low, high)
    pub.publish(state(robot.joint_names, q))
    drain(bus)
    viewer = RecordingViewer()
    display = RobotModelDisplay(robot, buf, viewer)
    assert display.update() == {}
    fk = robot.forward_kinematics(q)
    X_WR = fk[robot.root_link]
    for link in robot.links:
        expected = (X_WR.inverse() @ fk[link.name]).GetAsMatrix4()
        np.testing.assert_allclose(
            viewer.poses[f"/robots/{robot.name}/{link.name}"], expected, atol=1e-9
        )
