"""The simulation World: building, tracking trajectories, contacts and bad input."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import SimulationError
from workbench.sim import JointTrajectory, World

ARM = [
    "shoulder_pan_joint",
    "shoulder_pitch_joint",
    "elbow_roll_joint",
    "elbow_pitch_joint",
    "wrist_roll_joint",
]


def smooth_move(start, goal, duration, samples=60):
    """A rest-to-rest cubic from start to goal (arrays), as JointTrajectory arrays."""
    start, goal = np.asarray(start, float), np.asarray(goal, float)
    t = np.linspace(0.0, duration, samples)
    s = t / duration
    blend = (3 * s**2 - 2 * s**3)[:, None]
    rate = ((6 * s - 6 * s**2) / duration)[:, None]
    q = start + blend * (goal - start)
    qd = rate * (goal - start)
    return t, q, qd


@pytest.fixture
def arm_world():
    world = World(time_step=0.001)
    world.add_robot("robot_arm", X_WB=[0.0, 0.0, 0.05])
    world.build()
    return world


def test_tracks_a_trajectory_closely(arm_world):
    goal = [0.5, 0.3, -0.4, 0.6, 0.2]
    t, q, qd = smooth_move(np.zeros(5), goal, 1.5)
    report = arm_world.track_trajectory("robot_arm", JointTrajectory(ARM, t, q, qd))
    assert report.joint_names == ARM
    assert report.duration == pytest.approx(1.5)
    assert report.q_actual.shape == report.q_desired.shape == (len(report.t), 5)
    assert report.max_abs_error < 0.01
    assert report.succeeded
    q_end = arm_world.get_positions("robot_arm")
    np.testing.assert_allclose(q_end[:5], goal, atol=2e-3)
    # fingers were not in the trajectory: held where they were
    np.testing.assert_allclose(q_end[5:], [0.0, 0.0], atol=1e-3)
    assert arm_world.time == pytest.approx(2.0)
    assert report.contacts == []
    assert "max tracking error" in report.summary()


def test_accepts_the_json_layout_and_continues_in_time(arm_world):
    arm_world.set_positions("robot_arm", [0.2, 0, 0, 0, 0, 0, 0])
    t, q, qd = smooth_move([0.2], [-0.3], 1.0, samples=20)
    plan = {
        "joint_names": ["shoulder_pan_joint"],
        "t": t.tolist(),
        "q": q.tolist(),
        "qd": qd.tolist(),
    }
    first = arm_world.track_trajectory("robot_arm", plan, settle_time=0.2)
    assert first.final_error[0] < 2e-3
    started = arm_world.time
    back = arm_world.track_trajectory(
        "robot_arm", {**plan, "q": q[::-1].tolist(), "qd": (-qd[::-1]).tolist()}, settle_time=0.2
    )
    assert arm_world.time == pytest.approx(started + 1.2)
    assert abs(arm_world.get_positions("robot_arm")[0] - 0.2) < 2e-3
    assert back.succeeded


def test_an_obstacle_in_the_way_shows_in_contacts_and_error():
    world = World()
    world.add_robot("arm3")
    # a wall where the straight-up arm swings through when the shoulder pitches forward
    world.add_box("wall", size=(0.05, 0.4, 0.3), X_WB={"xyz": [0.35, 0.0, 0.45], "rpy": [0, 0, 0]})
    world.build()
    names = world.joint_names("arm3")
    t, q, qd = smooth_move([0, 0, 0], [0, 1.4, 0], 1.5)
    report = world.track_trajectory("arm3", JointTrajectory(names, t, q, qd))
    assert any("wall" in pair for pair in report.contacts)
    assert not report.succeeded
    assert report.max_error[1] > 0.05


def test_pid_controller_tracks_roughly():
    world = World()
    world.add_robot("arm3", controller="pid", gains={"kp": 400.0, "ki": 50.0, "kd": 40.0})
    world.build()
    names = world.joint_names("arm3")
    t, q, qd = smooth_move([0, 0, 0], [0.5, 0.3, -0.5], 2.0)
    report = world.track_trajectory("arm3", JointTrajectory(names, t, q, qd), settle_time=1.0)
    assert report.max_abs_error < 0.1
    assert np.all(report.final_error < 0.05)


def test_set_positions_teleports_and_holds(arm_world):
    q = [0.1, -0.2, 0.3, 0.4, -0.5, 0.01, -0.01]
    arm_world.set_positions("robot_arm", q)
    arm_world.advance_to(arm_world.time + 0.3)
    np.testing.assert_allclose(arm_world.get_positions("robot_arm"), q, atol=2e-3)


def test_two_robots_in_one_world():
    world = World()
    world.add_robot("arm3", name="left", X_WB=[0.0, 0.5, 0.0])
    world.add_robot("arm3", name="right", X_WB=[0.0, -0.5, 0.0])
    world.build()
    names = world.joint_names("right")
    t, q, qd = smooth_move([0, 0, 0], [0.4, 0.2, 0.3], 1.0)
    report = world.track_trajectory("right", JointTrajectory(names, t, q, qd), settle_time=0.2)
    assert report.succeeded
    np.testing.assert_allclose(world.get_positions("left"), 0.0, atol=1e-3)


@pytest.mark.parametrize(
    ("make", "text"),
    [
        (lambda t, q, qd: JointTrajectory(ARM, t, q[:, :3], qd), "q has shape"),
        (lambda t, q, qd: JointTrajectory(ARM, t[::-1], q, qd), "increasing"),
        (lambda t, q, qd: JointTrajectory(ARM[:4] + ["nope"], t, q, qd), "no joint 'nope'"),
        (lambda t, q, qd: JointTrajectory(ARM, t, q * np.nan, qd), "NaN"),
        (lambda t, q, qd: {"t": t, "q": q, "qd": qd}, "no joint_names"),
    ],
)
def test_bad_trajectories(arm_world, make, text):
    t, q, qd = smooth_move(np.zeros(5), np.ones(5) * 0.1, 1.0, samples=5)
    with pytest.raises(SimulationError, match=text):
        arm_world.track_trajectory("robot_arm", make(t, q, qd))


def test_bad_world_use(arm_world):
    with pytest.raises(SimulationError, match="no robot named 'arm'"):
        arm_world.get_positions("arm")
    with pytest.raises(SimulationError, match="already built"):
        arm_world.add_box("late", size=(1, 1, 1))
    with pytest.raises(SimulationError, match="takes 7 positions, got 2"):
        arm_world.set_positions("robot_arm", [0, 0])
    with pytest.raises(SimulationError, match="cannot advance"):
        arm_world.advance_to(-1.0)
    world = World()
    with pytest.raises(SimulationError, match="size must be 3 positive numbers"):
        world.add_box("b", size=(1, -1, 1))
    world.add_sphere("ball", 0.1, X_WB=[1, 0, 0.1])
    with pytest.raises(SimulationError, match="already used"):
        world.add_cylinder("ball", 0.1, 0.2)
    with pytest.raises(SimulationError, match="call build"):
        world.get_positions("x")
    with pytest.raises(SimulationError, match="time_step must be positive"):
        World(time_step=0.0)


def test_draws_in_meshcat():
    from workbench.viz import Viewer

    meshcat = Viewer.instance().meshcat
    world = World()
    world.add_robot("arm3", name="drawn_arm3")
    world.add_box("drawn_box", size=(0.1, 0.1, 0.1), X_WB=[0.5, 0.0, 0.05])
    world.build(meshcat=meshcat)
    world.advance_to(0.02)
    assert meshcat.HasPath("/drake/visualizer/drawn_arm3/forearm_link")
    assert meshcat.HasPath("/drake/visualizer/drawn_box")


def test_zero_length_trajectory_holds(arm_world):
    q0 = np.array([[0.1, 0.0, 0.0, 0.0, 0.0]])
    arm_world.set_positions("robot_arm", [0.1, 0, 0, 0, 0, 0, 0])
    plan = {"joint_names": ARM, "t": [0.0, 0.0], "q": np.vstack([q0, q0]), "qd": np.zeros((2, 5))}
    report = arm_world.track_trajectory("robot_arm", plan, settle_time=0.1)
    assert report.duration == 0.0
    assert report.succeeded
    with pytest.raises(SimulationError, match="appears twice with different positions"):
        arm_world.track_trajectory(
            "robot_arm", {**plan, "q": np.vstack([q0, q0 + 0.1])}, settle_time=0.1
        )


def test_shapes_and_poses_in_the_spatial_vocabulary():
    from workbench import spatial
    from workbench.model import RobotDescription

    description = RobotDescription.load("arm3")
    world = World()
    # two robots from one description, the second placed by a 4x4 matrix
    world.add_robot(description, name="left")
    X = spatial.pose_matrix([0.0, -1.0, 0.0], rpy=[0, 0, np.pi / 2])
    world.add_robot(description, name="right", X_WB=X)
    world.add_shape("crate", spatial.make_shape("box", size=[0.2, 0.2, 0.2]), [1.0, 1.0, 0.1])
    world.add_shape(
        "drum",
        spatial.make_shape("cylinder", radius=0.1, length=0.3),
        {"xyz": [-1, 1, 0.15], "quaternion": [0, 0, 0, 1]},
    )
    world.build()
    assert world.obstacles == ["crate", "drum"]
    context = world.plant.GetMyContextFromRoot(world.context)
    right = world.robots["right"]
    root = world.plant.GetBodyByName(right.root_link, right.model_instance)
    X_WR = world.plant.EvalBodyPoseInWorld(context, root).GetAsMatrix4()
    np.testing.assert_allclose(X_WR, X, atol=1e-12)
    with pytest.raises(SimulationError, match="a pose is a RigidTransform"):
        World().add_box("b", size=(1, 1, 1), X_WB="origin")
    with pytest.raises(SimulationError, match="mesh file for 'm' not found"):
        World().add_shape("m", spatial.make_shape("mesh", filename="/no/such.obj"))


def test_hundreds_of_obstacles_beside_the_ground_build_and_run():
    """Drake 1.51 crashed making a context for a half space anchored among a few hundred
    anchored shapes; obstacles sit on welded bodies instead (a subprocess: a crash is a
    signal, not an exception)."""
    import subprocess
    import sys

    script = (
        "from pydrake.math import RigidTransform\n"
        "from workbench.sim import World\n"
        "w = World()\n"
        "for i in range(400):\n"
        "    w.add_box(f'b{i}', (0.2, 0.2, 0.5), RigidTransform([0.3 * (i % 20), 0.3 * (i // 20), 0.25]))\n"
        "w.build()\n"
        "w.advance_to(0.01)\n"
        "print(len(w.model_names()))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, timeout=300
    )
    assert done.returncode == 0, done.stderr[-2000:]
