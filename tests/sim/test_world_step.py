"""The wheeled robots' worlds' 8 ms physics step against Gazebo's 1 ms step.

The shipped house, arena and lab_room worlds declare ``<max_step_size>0.008``
(their plans in mapping/plans say why). What a Gazebo user expects of a coarser
step: the same robot, driven by the same commands, ends where it ends at 1 ms (to
within what contact and wheel slip allow) and does not creep or bounce at rest.
Measured on the TurtleBot3 burger (urdf/turtlebot3_burger.urdf) through its own
diff drive plugin. Also: ``--max-step-size`` overrides a world's step, and an IMU
nobody listens to costs no physics chunks.
"""

from __future__ import annotations

import math

import pytest

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import Twist
from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.gazebo_ros_plugins.diff_drive import GazeboRosDiffDrive
from workbench.sim.gzserver import ServerOptions, build_server
from workbench.sim.loading import load_sim_model
from workbench.sim.sensors.imu_plugin import GazeboRosImuSensor
from workbench.sim.server import SERVER_PHYSICS, SimServer
from workbench.sim.world_file import load_world

WHEELED_WORLDS = ("house", "arena", "lab_room")
STEP = 0.008

#: (start s, forward m/s, turn rad/s): straight, turn in place, arc, reverse, arc back.
DRIVE = [(0.0, 0.2, 0.0), (5.0, 0.0, 1.0), (8.0, 0.15, 0.5), (13.0, -0.1, 0.0), (15.0, 0.2, -0.8)]
END = 20.0


def _drive(time_step: float) -> tuple[float, float, float]:
    world = World(**{**SERVER_PHYSICS, "time_step": time_step})
    server = SimServer(world, real_time_factor=0)
    server.spawn(load_sim_model(urdf_dir() / "turtlebot3_burger.urdf"), [0, 0, 0])
    (drive,) = [p for p in server.plugins if isinstance(p, GazeboRosDiffDrive)]
    for start, forward, turn in DRIVE:
        server.run(until=start)
        command = Twist()
        command.linear.x, command.angular.z = forward, turn
        drive.on_command(command)
    server.run(until=END)
    X = world.get_model_pose("turtlebot3_burger")
    server.stop()
    p = X.translation()
    return float(p[0]), float(p[1]), float(X.rotation().ToRollPitchYaw().yaw_angle())


def test_the_fast_step_drives_the_turtlebot3_where_the_1_ms_step_does():
    x1, y1, yaw1 = _drive(0.001)
    xf, yf, yawf = _drive(STEP)
    assert math.hypot(x1, y1) > 0.3  # it went somewhere (the drive ends 0.5 m from its start)
    assert math.hypot(xf - x1, yf - y1) < 0.05
    assert abs(math.remainder(yawf - yaw1, math.tau)) < math.radians(5)


def test_at_the_fast_step_the_turtlebot3_rests_without_creeping():
    world = World(**{**SERVER_PHYSICS, "time_step": STEP})
    world.add_model(load_sim_model(urdf_dir() / "turtlebot3_burger.urdf"), [0, 0, 0.01])
    world.build()
    world.advance_to(1.0)
    before = world.get_model_pose("turtlebot3_burger").translation()
    world.advance_to(11.0)
    after = world.get_model_pose("turtlebot3_burger").translation()
    assert abs(after - before).max() < 1e-3


@pytest.mark.parametrize("name", WHEELED_WORLDS)
def test_the_wheeled_robots_worlds_declare_the_coarser_step(name):
    assert load_world(name).physics.time_step == STEP
    assert load_world("empty").physics.time_step == SERVER_PHYSICS["time_step"]


def test_max_step_size_overrides_the_worlds_step():
    bus = Bus(threaded=False)
    world, server, _ = build_server(ServerOptions(world="house", fast=True, view=False), bus)
    assert world.time_step == STEP
    server.stop()
    options = ServerOptions(world="house", view=False, max_step_size=0.001)
    world, server, _ = build_server(options, bus)
    assert world.time_step == 0.001
    server.stop()
    bus.shutdown()


@pytest.mark.parametrize("step", [0.0, -0.001, 0.5, math.nan])
def test_a_bad_max_step_size_is_refused_in_one_line(step):
    from workbench.errors import SimulationError

    with pytest.raises(SimulationError, match="--max-step-size must be in"):
        build_server(ServerOptions(view=False, max_step_size=step))


def test_an_imu_nobody_listens_to_does_not_cut_the_physics_into_its_periods():
    """gazebo_ros_imu_sensor computes only for subscribers; an idle IMU costs no chunks."""
    bus = Bus(threaded=False)
    world = World(**{**SERVER_PHYSICS, "time_step": 0.001})
    server = SimServer(world, bus=bus, real_time_factor=0)
    server.spawn(load_sim_model(urdf_dir() / "turtlebot3_burger.urdf"), [0, 0, 0])
    chunks: list[float] = []
    server.hooks.append(lambda s: chunks.append(s.world.time))
    server.run(until=0.2)
    idle = len(chunks)
    (imu,) = [p for p in server.plugins if isinstance(p, GazeboRosImuSensor)]
    messages: list = []
    Node("listener", bus=bus).create_subscription(
        imu.topic, "sensor_msgs/Imu", messages.append, queue_size=100
    )
    imu.listeners.forget()  # the plugin looks up its subscribers 5 times a wall second
    chunks.clear()
    server.run(until=0.4)
    while bus.spin_once(0.0):
        pass
    assert len(chunks) > 1.5 * idle  # the 200 Hz IMU now cuts the physics into 5 ms chunks
    assert len(messages) >= 30
    server.stop()
    bus.shutdown()


COUNTER = """from workbench.sim.plugins import WorldPlugin


class Counter(WorldPlugin):
    def load(self, world, sdf, node):
        self.times = []

    def update(self, info):
        self.times.append(info.sim_time)
"""


@pytest.mark.parametrize("rate, step", [(100.0, 0.008), (40.0, 0.008), (200.0, 0.001)])
def test_a_plugin_keeps_its_rate_on_average_when_steps_do_not_divide_its_period(
    tmp_path, rate, step
):
    """Updating at the first step a whole period after the last update would turn a 100 Hz
    drive into 62.5 Hz at 8 ms steps; the updates keep to the period's grid instead, at the
    step nearest each due time, so the rate holds on average."""
    from sim_helpers import plugin_spec

    path = tmp_path / "counter.py"
    path.write_text(COUNTER)
    world = World(**{**SERVER_PHYSICS, "time_step": step})
    server = SimServer(world, real_time_factor=0)
    body = f"<update_rate>{rate:g}</update_rate>"
    plugin = server.load_plugin(plugin_spec(str(path), "counter", body, kind="world"))
    server.run(until=2.0)
    times = plugin.times
    assert len([t for t in times if t < 2.0 - 1e-9]) == pytest.approx(2.0 * rate, abs=1)
    assert max(abs(t - k / rate) for k, t in enumerate(times)) <= step / 2 + 1e-9
    server.stop()
