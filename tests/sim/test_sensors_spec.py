"""Sensor blocks: SDFormat's defaults, and each bad value as one clear line that names it.

A model with a bad sensor still spawns, without that sensor's plugins.
"""

from __future__ import annotations

import logging
import math

import pytest
from sensor_helpers import laser_xml, sdf_model, sensor_robot_sdf

from workbench.errors import SimulationError
from workbench.sim import World
from workbench.sim.sensors import CameraSpec, ImuSpec, LaserSpec, parse_sensor
from workbench.sim.server import SERVER_PHYSICS, SimServer


def test_a_laser_block_is_read_with_sdformat_defaults_for_what_it_leaves_out():
    spec = parse_sensor(
        '<sensor type="gpu_ray" name="l"><ray><range><max>5</max></range></ray></sensor>',
        model="m",
        link="k",
    )
    assert isinstance(spec, LaserSpec)
    assert spec.horizontal.samples == 640 and spec.horizontal.count == 640
    assert spec.vertical.count == 1 and spec.count == 640
    assert (spec.range_min, spec.range_max, spec.noise) == (0.0, 5.0, None)
    assert (spec.update_rate, spec.always_on, spec.X_LS) == (0.0, False, (0.0,) * 6)


def test_the_lab_laser_block_is_read_in_full():
    spec = parse_sensor(
        laser_xml(
            samples=720,
            min_angle=-1.578,
            max_angle=1.578,
            rate=40,
            noise="<noise><type>gaussian</type><mean>0.01</mean><stddev>0.02</stddev></noise>",
        ),
        model="m",
        link="laser_scanner",
    )
    assert isinstance(spec, LaserSpec)
    assert spec.horizontal.angles()[[0, -1]] == pytest.approx([-1.578, 1.578])
    assert spec.update_rate == 40 and spec.range_resolution == 0.01
    assert spec.noise is not None and (spec.noise.mean, spec.noise.stddev) == (0.01, 0.02)
    assert spec.X_LS == (0.0, 0.0, 0.1, 0.0, 0.0, 0.0)


def test_camera_depth_and_imu_blocks():
    camera = parse_sensor(
        """<sensor type="depth" name="kinect"><update_rate>20</update_rate><always_on>true</always_on>
        <camera><horizontal_fov>1.0472</horizontal_fov><image><width>64</width><height>48</height>
        <format>B8G8R8</format></image><clip><near>0.05</near><far>8</far></clip></camera></sensor>""",
        model="m",
        link="k",
    )
    assert isinstance(camera, CameraSpec)
    assert (camera.width, camera.height, camera.encoding) == (64, 48, "bgr8")
    assert camera.focal_length == pytest.approx(32 / math.tan(0.5236))
    assert (camera.near, camera.far, camera.always_on) == (0.05, 8.0, True)
    imu = parse_sensor(
        """<sensor type="imu" name="imu"><imu><angular_velocity><x><noise type="gaussian">
        <mean>0</mean><stddev>0.01</stddev></noise></x></angular_velocity>
        <noise><type>gaussian</type><accel><mean>0</mean><stddev>0.1</stddev></accel></noise>
        </imu></sensor>""",
        model="m",
        link="k",
    )
    assert isinstance(imu, ImuSpec)
    x, y, _ = imu.angular_velocity_noise
    assert x is not None and x.stddev == 0.01 and y is None
    assert all(n is not None and n.stddev == 0.1 for n in imu.linear_acceleration_noise)


BAD = [
    (laser_xml(range_min=-1), "<ray><range><min> must be a number >= 0, got '-1'"),
    (laser_xml(samples=0), "<ray><scan><horizontal><samples> must be a whole number >= 1, got '0'"),
    (
        laser_xml(min_angle=1.0, max_angle=-1.0),
        "<min_angle> (1) must not be greater than <max_angle> (-1)",
    ),
    (laser_xml(range_max="far"), "<ray><range><max> must be a number, got 'far'"),
    (laser_xml(range_min=5, range_max=2), "<ray><range><max> (2) must be greater than <min> (5)"),
    (laser_xml(rate=-3), "<update_rate> must be a number >= 0, got '-3'"),
    (
        laser_xml(noise="<noise><type>gaussian</type><stddev>-0.1</stddev></noise>"),
        "<ray><noise><stddev> must be a number >= 0, got '-0.1'",
    ),
    (
        '<sensor type="camera" name="laser"><camera><image><width>0</width></image></camera></sensor>',
        "<camera><image><width> must be a whole number >= 1, got '0'",
    ),
    (
        '<sensor type="camera" name="laser"><camera><clip><near>2</near><far>1</far></clip></camera></sensor>',
        "<camera><clip><far> (1) must be greater than <near> (2)",
    ),
    (
        '<sensor type="ray" name="laser"><pose>1 2 x</pose><ray/></sensor>',
        "<pose> must be six numbers",
    ),
]


@pytest.mark.parametrize(("xml", "problem"), BAD)
def test_each_bad_value_is_one_line_naming_model_link_sensor_and_element(xml, problem):
    with pytest.raises(SimulationError) as caught:
        parse_sensor(xml, model="bot", link="base")
    message = caught.value.one_line()
    assert "\n" not in message
    assert message.startswith("model 'bot', link 'base', sensor 'laser': ")
    assert problem in message


def test_a_model_with_a_bad_sensor_spawns_without_it_and_says_so_once(caplog):
    plugin = (
        '<plugin name="p" filename="libgazebo_ros_laser.so"><topicName>/scan</topicName></plugin>'
    )
    good = laser_xml(name="good", plugin=plugin)
    bad = laser_xml(name="bad", range_min=-1, plugin=plugin.replace('"p"', '"q"'))
    model = sdf_model(sensor_robot_sdf("bot", good + bad))
    server = SimServer(World(**SERVER_PHYSICS), real_time_factor=0)
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        server.spawn(model, [0, 0, 0.5])
    assert "bot" in server.world.model_names()
    lines = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert lines == [
        "model 'bot', link 'base', sensor 'bad': <ray><range><min> must be a number >= 0, "
        "got '-1'; the model runs without this sensor"
    ]
    assert [p.spec.name for p in server.plugins] == ["good"]
    server.run(until=0.05)  # and it runs
    server.stop()


def test_a_plugin_on_the_wrong_kind_of_sensor_is_one_line_and_not_loaded(caplog):
    camera_plugin = '<plugin name="cam" filename="libgazebo_ros_camera.so"/>'
    model = sdf_model(sensor_robot_sdf("bot", laser_xml(plugin=camera_plugin)))
    server = SimServer(World(**SERVER_PHYSICS), real_time_factor=0)
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        server.spawn(model, [0, 0, 0.5])
    lines = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert lines == [
        "model 'bot': plugin 'cam' not loaded: model 'bot', link 'base', sensor 'laser': camera "
        "plugin 'cam' needs a sensor of type camera, not 'ray'"
    ]
    assert server.plugins == []
    server.stop()


def test_a_sensor_type_workbench_does_not_simulate_is_a_warning():
    from workbench.sim.sensors.check import check_sensors

    model = sdf_model(sensor_robot_sdf("bot", '<sensor type="gps" name="gps"/>'))
    assert check_sensors(model) == {}
