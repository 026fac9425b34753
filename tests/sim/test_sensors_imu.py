"""The IMU: gravity's reaction at rest, free fall, rotation, and gazebo_ros_imu_sensor's topic.

What is matched (gazebo_plugins noetic-devel gazebo_ros_imu_sensor.cpp, gazebo 11 ImuSensor):
``<topicName>`` defaults to ``imu_data`` under ``/<model name>/``; ``<frameName>`` is
required; ``<updateRateHZ>`` defaults to 1; ``<gaussianNoise>`` goes on every
component and its square on the covariance diagonals; the orientation is
relative to the world (REP 145); the linear acceleration is the specific force
(at rest: +g up, in the sensor frame).
"""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
from sensor_helpers import sdf_model, sensor_robot_sdf

from workbench.bus import Bus, Node
from workbench.sim import World
from workbench.sim.sensors import Imu, parse_sensor, sensor_plugin
from workbench.sim.server import SERVER_PHYSICS, SimServer


def imu_xml(pose: str = "0 0 0 0 0 0", rate: float = 100, plugin: str = "", noise: str = "") -> str:
    return f"""<sensor type="imu" name="imu"><always_on>true</always_on>
  <update_rate>{rate}</update_rate><pose>{pose}</pose><imu>{noise}</imu>{plugin}</sensor>"""


def _server(model, pose, *, gravity=9.81, bus=None) -> SimServer:
    world = World(**{**SERVER_PHYSICS, "gravity": gravity})
    server = SimServer(world, bus=bus, real_time_factor=0)
    server.spawn(model, pose)
    return server


PLUGIN = """<plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so">
  <frameName>imu_link</frameName><updateRateHZ>50</updateRateHZ></plugin>"""


def test_at_rest_it_reads_gravitys_reaction_up_in_its_own_frame():
    xml = imu_xml(pose="0 0 0 1.5707963267948966 0 0", plugin=PLUGIN)
    server = _server(sdf_model(sensor_robot_sdf("bot", xml)), [0, 0, 0.5])
    server.run(until=0.05)
    reading = sensor_plugin(server, "imu").latest
    # rolled 90 degrees about x: the world's up is the sensor's +y
    assert reading.linear_acceleration == pytest.approx([0.0, 9.81, 0.0], abs=1e-9)
    assert reading.angular_velocity == pytest.approx([0, 0, 0], abs=1e-12)
    s = math.sin(math.pi / 4)
    assert reading.orientation == pytest.approx([s, 0, 0, s])
    server.stop()


def test_in_free_fall_it_reads_nothing():
    server = _server(
        sdf_model(sensor_robot_sdf("faller", imu_xml(plugin=PLUGIN), static=False)), [0, 0, 5]
    )
    server.run(until=0.3)
    reading = sensor_plugin(server, "imu").latest
    assert np.abs(reading.linear_acceleration).max() < 1e-6
    server.stop()


def test_a_spinning_body_gives_rate_in_the_sensor_frame_and_centripetal_acceleration():
    world = World(**{**SERVER_PHYSICS, "gravity": 0.0})
    model = sdf_model(sensor_robot_sdf("spinner", imu_xml(pose="0.5 0 0 0 0 0"), static=False))
    world.add_model(model, [0, 0, 1])
    world.build()
    world.set_model_state("spinner", [0, 0, 1], [0, 0, 0], [0, 0, 2.0])
    spec = parse_sensor(model.sensors[0][1], model="spinner", link="base")
    body = world.body("spinner::base")
    imu = Imu(spec)
    first = imu.measure(world, body, spec.pose())
    assert first.linear_acceleration == pytest.approx([0, 0, 0])  # nothing to difference yet
    world.advance_to(world.time + 0.001)
    reading = imu.measure(world, body, spec.pose())
    assert reading.angular_velocity == pytest.approx([0, 0, 2.0], abs=1e-6)
    # 0.5 m from the axis at 2 rad/s: 2 m/s^2 towards the axis (S's -x), as the change of
    # velocity over the 1 ms between readings (Gazebo's way), so within omega * dt
    assert reading.linear_acceleration == pytest.approx([-2.0, 0, 0], abs=5e-3)


def test_the_plugin_publishes_on_the_models_namespace_at_its_rate_with_noise_covariance():
    bus = Bus(threaded=False)
    messages: list = []
    Node("listener", bus=bus).create_subscription(
        "/bot/imu_data", "sensor_msgs/Imu", messages.append, queue_size=100
    )
    plugin = PLUGIN.replace("</frameName>", "</frameName><gaussianNoise>0.01</gaussianNoise>")
    server = _server(
        sdf_model(sensor_robot_sdf("bot", imu_xml(plugin=plugin))), [0, 0, 0.5], bus=bus
    )
    server.run(until=0.1)
    while bus.spin_once(0.0):
        pass
    assert [m.header.stamp.to_sec() for m in messages] == pytest.approx(
        [0.02 * k for k in range(5)]
    )
    last = messages[-1]
    assert last.header.frame_id == "imu_link"
    assert list(last.linear_acceleration_covariance) == pytest.approx(
        [1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4]
    )
    assert last.linear_acceleration.z == pytest.approx(9.81, abs=0.05)
    assert last.orientation.w == pytest.approx(1.0, abs=0.05) and last.orientation.w != 1.0
    server.stop()


def test_without_frame_name_the_plugin_is_not_loaded_in_one_line(caplog):
    plugin = '<plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so"/>'
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        server = _server(sdf_model(sensor_robot_sdf("bot", imu_xml(plugin=plugin))), [0, 0, 0.5])
    lines = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert lines == [
        "model 'bot': plugin 'imu_plugin' not loaded: model 'bot', link 'base', sensor 'imu': imu "
        "plugin 'imu_plugin' needs <frameName> (gazebo_ros_imu_sensor's requirement)"
    ]
    assert "bot" in server.world.model_names() and server.plugins == []
    server.stop()
