"""ModelBuilder.add_sensor, and the manual's simpledoifffbot (Experiment 6 steps 23-27) built with it."""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

import pytest
from lxml import etree

from workbench.errors import ModelError
from workbench.model import ModelBuilder
from workbench.sim.loading import load_sim_model
from workbench.sim.model_paths import find_model_file
from workbench.sim.sensors import parse_sensor

REPO = Path(__file__).resolve().parents[2]
SCRIPT = REPO / "examples" / "gazebo" / "build_simpledoifffbot.py"
CAMERA = {
    "horizontal_fov": 1.047,
    "image": {"width": 320, "height": 240},
    "clip": {"near": 0.1, "far": 100},
}


def test_the_shipped_simpledoifffbot_is_what_the_script_writes_now(tmp_path, monkeypatch):
    out = tmp_path / "robot.sdf"
    monkeypatch.setattr(sys, "argv", [str(SCRIPT), str(out)])
    runpy.run_path(str(SCRIPT), run_name="__main__")
    assert out.read_text() == (REPO / "urdf" / "simpledoifffbot.sdf").read_text()
    assert find_model_file("simpledoifffbot") == REPO / "urdf" / "simpledoifffbot.sdf"


def test_the_depth_camera_sits_on_the_front_of_the_chassis_on_a_fixed_joint():
    robot = runpy.run_path(str(SCRIPT))["build"]()
    assert robot.name == "simpledoifffbot"
    # chassis 2 x 1 x 0.15 centred at z 0.4: front x = 1, top z = 0.475; a 0.1 m cube
    assert robot.link_pose("depth_camera") == pytest.approx((0.95, 0.0, 0.525, 0, 0, 0))
    sdf = etree.fromstring(robot.to_sdf().encode())
    joint = sdf.find(".//joint[@name='depth_camera_joint']")
    assert joint.get("type") == "fixed" and joint.findtext("parent") == "chassis"
    plugin = sdf.find("model/plugin")
    assert (plugin.get("name"), plugin.get("filename")) == ("follower", "libFollowerPlugin.so")


def test_a_sensor_is_written_in_its_link_in_sdf_and_in_a_gazebo_block_in_urdf():
    robot = ModelBuilder("bot")
    robot.add_link("base", pose=(0, 0, 0.4, 0, 0, 0))
    robot.add_box("base", (0.4, 0.3, 0.1))
    robot.add_sensor(
        "base",
        "cam",
        "depth",
        pose=(0.2, 0, 0.1, 0, 0.1, 0),
        update_rate=15,
        always_on=True,
        camera=CAMERA,
    )
    element = etree.fromstring(robot.to_sdf().encode()).find("model/link/sensor")
    spec = parse_sensor(element, model="bot", link="base")
    assert (spec.name, spec.type, spec.width, spec.height, spec.update_rate) == (
        "cam",
        "depth",
        320,
        240,
        15.0,
    )
    assert spec.always_on and spec.far == 100.0
    assert element.findtext("pose") == "0.2 0 0.1 0 0.1 0"
    # URDF: the root link's frame is the model frame, so the sensor moves up by 0.4 m
    urdf = etree.fromstring(robot.to_urdf().encode())
    block = urdf.find("gazebo[@reference='base']")
    assert block is not None
    assert [float(v) for v in block.findtext("sensor/pose").split()] == pytest.approx(
        [0.2, 0.0, 0.5, 0.0, 0.1, 0.0]
    )


def test_a_built_sensor_reaches_the_simulator(tmp_path):
    robot = runpy.run_path(str(SCRIPT))["build"](image=(64, 48), update_rate=10)
    model = load_sim_model(robot.save(tmp_path / "bot.sdf"))
    [(link, xml)] = model.sensors
    spec = parse_sensor(xml, model=model.name, link=link)
    assert (link, spec.width, spec.height, spec.update_rate) == ("depth_camera", 64, 48, 10.0)


def test_bad_sensors_are_one_line_errors():
    robot = ModelBuilder("bot")
    robot.add_link("base")
    with pytest.raises(ModelError, match="unknown type 'lidar'"):
        robot.add_sensor("base", "s", "lidar")
    with pytest.raises(ModelError, match="has no link 'arm'"):
        robot.add_sensor("arm", "s", "camera")
    with pytest.raises(ModelError, match="not a finite number"):
        robot.add_sensor("base", "s", "camera", camera={"horizontal_fov": float("nan")})
    with pytest.raises(ModelError, match="XML text"):
        robot.add_sensor("base", "s", "camera", topic="<a>")
    robot.add_sensor("base", "s", "camera")
    with pytest.raises(ModelError, match="already has a sensor 's'"):
        robot.add_sensor("base", "s", "imu")
