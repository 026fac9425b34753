"""Formatting and parsing behind the introspection tools, without a bus.

Matched against ROS 1 Noetic's tools: rostopic pub takes one YAML value per
argument (fields in order) or one YAML mapping; rostopic echo prints YAML
documents ended by ``---``, strings quoted, ``--noarr`` replacing arrays with
``<array type: T, length: N>``; rostopic hz prints ``average rate`` with
min/max/std dev/window, rostopic bw ``average: X/s`` with mean/min/max/window;
rosmsg show expands nested types indented by two spaces.
"""

from __future__ import annotations

import pytest

from workbench.errors import BusError, MessageError
from workbench.introspect.args import message_from_args
from workbench.introspect.definitions import show_any, show_message, show_service
from workbench.introspect.echo import format_echo, get_field, split_topic_field
from workbench.introspect.rates import BwMeter, HzMeter
from workbench.msgs import get_type
from workbench.msgs.turtlesim import Pose


def test_pub_positional_args_like_the_manual():
    msg = message_from_args("geometry_msgs/Twist", ["[2.0, 0.0, 0.0]", "[0.0, 0.0, 1.8]"])
    assert (msg.linear.x, msg.angular.z) == (2.0, 1.8)


def test_pub_dict_and_single_field_and_service_words():
    assert message_from_args("geometry_msgs/Twist", ["{angular: {z: -1.8}}"]).angular.z == -1.8
    assert message_from_args("std_msgs/String", ["hello"]).data == "hello"
    spawn = message_from_args("turtlesim/SpawnRequest", ["2", "2", "0.2", "turtle2"])
    assert (spawn.x, spawn.y, spawn.name) == (2.0, 2.0, "turtle2")
    pen = message_from_args("turtlesim/SetPenRequest", ["255", "0", "255", "3", "off"])
    assert (pen.r, pen.b, pen.width, pen.off) == (255, 255, 3, 0)


def test_pub_args_that_do_not_fit_name_the_field():
    with pytest.raises(MessageError, match=r"field 'y' of geometry_msgs/Vector3.*'linear'"):
        message_from_args("geometry_msgs/Twist", ["[2.0, abc, 0.0]"], what="topic /turtle1/cmd_vel")
    with pytest.raises(MessageError, match="no field 'q'"):
        message_from_args("geometry_msgs/Twist", ["{linear: {q: 1}}"])
    with pytest.raises(MessageError, match="not valid YAML"):
        message_from_args("geometry_msgs/Twist", ["[2.0"])
    with pytest.raises(MessageError, match="2 fields"):
        message_from_args("geometry_msgs/Twist", ["[1,0,0]", "[0,0,1]", "[0,0,0]"])
    with pytest.raises(MessageError, match="unknown message type"):
        message_from_args("geometry_msgs/Twst", [])


def test_echo_yaml_document():
    text = format_echo(message_from_args("geometry_msgs/Twist", ["[-2.0, 0, 0]", "[0, 0, 0]"]))
    assert text.splitlines() == [
        "linear: ", "  x: -2.0", "  y: 0.0", "  z: 0.0",
        "angular: ", "  x: 0.0", "  y: 0.0", "  z: 0.0", "---",
    ]  # fmt: skip
    assert format_echo(get_type("std_msgs/String")(data="hi")) == 'data: "hi"\n---'


def test_echo_noarr_and_field_paths():
    scan = get_type("sensor_msgs/LaserScan")(ranges=[1.0, 2.0, 3.0])
    assert 'ranges: "<array type: float32, length: 3>"' in format_echo(scan, noarr=True)
    topic, fields = split_topic_field("/turtle1/pose/x", ["/turtle1/pose", "/turtle1/cmd_vel"])
    assert (topic, fields) == ("/turtle1/pose", ["x"])
    assert get_field(Pose(x=4.5), fields) == 4.5
    assert format_echo(get_field(scan, ["ranges[1]"])) == "2.0\n---"
    with pytest.raises(BusError, match="no field 'z' in turtlesim/Pose"):
        get_field(Pose(), ["z"], topic="/turtle1/pose")
    with pytest.raises(BusError, match="does not appear to be published"):
        split_topic_field("/nope/x", ["/turtle1/pose"])


def test_hz_and_bw_reports():
    hz = HzMeter()
    assert hz.report() is None
    for i in range(63):
        hz.add(i * 0.016)
    lines = hz.report().splitlines()
    assert lines[0] == "average rate: 62.500"
    assert lines[1] == "\tmin: 0.016s max: 0.016s std dev: 0.00000s window: 63"
    bw = BwMeter()
    for i in range(11):
        bw.add(i * 0.1, 20)
    assert bw.report().splitlines() == [
        "average: 220.00B/s",
        "\tmean: 20.00B min: 20.00B max: 20.00B window: 11",
    ]


def test_msg_and_srv_show():
    assert show_message("geometry_msgs/Twist").splitlines() == [
        "geometry_msgs/Vector3 linear", "  float64 x", "  float64 y", "  float64 z",
        "geometry_msgs/Vector3 angular", "  float64 x", "  float64 y", "  float64 z",
    ]  # fmt: skip
    assert show_service("turtlesim/Spawn").splitlines() == [
        "float32 x", "float32 y", "float32 theta", "string name", "---", "string name",
    ]  # fmt: skip
    assert show_any("std_srvs/Empty") == "---"
    assert "  uint32 seq" in show_message("rosgraph_msgs/Log")
