"""workbench.msgs: friendly classes, ROS 1 bytes, md5sums, conversions and errors."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

from workbench import msgs
from workbench.errors import MessageError
from workbench.msgs import (
    definition,
    deserialize,
    from_dict,
    get_type,
    md5sum,
    serialize,
    to_dict,
)
from workbench.msgs.geometry_msgs import Twist, Vector3
from workbench.msgs.std_msgs import Float64MultiArray, Header, String, UInt8MultiArray

# md5sums as ROS 1 (genmsg) computes them.
ROS_MD5 = {
    "geometry_msgs/Twist": "9f195f881246fdfa2798d1d3eebca84a",
    "std_msgs/String": "992ce8a1687cec8c8bd883ec73ca41d1",
    "turtlesim/Pose": "863b248d5016ca62ea2e895ae5265cf9",
    "turtlesim/Color": "353891e354491c51aabe32df673fb446",
    "tf2_msgs/TFMessage": "94810edda583a504dfda3829e70d7eec",
    "rosserial_msgs/TopicInfo": "0ad51f88fc44892f8c10684077646005",
    "rosserial_msgs/Log": "11abd731c25933261cd6183bd12d6295",
    "std_srvs/Empty": "d41d8cd98f00b204e9800998ecf8427e",
    "std_srvs/Trigger": "937c9679a518e3a18d831e57125ea522",
    "std_srvs/SetBool": "09fb03525b03e7ea1fd3992bafd87e16",
    "beginner_tutorials/AddTwoInts": "6a2e34150c00229791cc89ff309fff21",
    "turtlesim/Spawn": "0b2d2e872a8e2887d5ed626f2bf2c561",
    "turtlesim/Kill": "c1f3d28f1b044c871e6eff2e9fc3c667",
    "turtlesim/SetPen": "9f452acce566bf0c0954594f69a8e41b",
    "turtlesim/TeleportAbsolute": "a130bc60ee6513855dc62ea83fcc5b20",
    "turtlesim/TeleportRelative": "9d5c2dcd348ac8f76ce2a4307bd63a13",
}


@pytest.mark.parametrize("name", sorted(ROS_MD5))
def test_md5sum_matches_ros(name):
    assert md5sum(name) == ROS_MD5[name]


def test_keyword_construction_and_zero_defaults():
    cmd = Twist(linear=Vector3(x=2.0))
    assert cmd.linear.x == 2.0 and cmd.linear.y == 0.0 and cmd.angular.z == 0.0
    assert Twist._type == "geometry_msgs/Twist" and cmd._type == "geometry_msgs/Twist"
    assert String().data == ""
    header = Header()
    assert header.stamp.secs == 0 and header.frame_id == ""
    assert isinstance(Float64MultiArray().data, np.ndarray)


def test_positional_construction_like_rospy():
    assert String("hello").data == "hello"
    from workbench.msgs.beginner_tutorials import AddTwoInts, AddTwoIntsRequest, AddTwoIntsResponse

    assert AddTwoInts.Request is AddTwoIntsRequest
    assert AddTwoIntsResponse(4).sum == 4
    assert AddTwoIntsRequest(1, 3).b == 3
    with pytest.raises(MessageError, match="takes 2 positional values"):
        AddTwoIntsRequest(1)


def test_wire_bytes_are_ros1():
    msg = String(data="hi")
    assert serialize(msg) == b"\x02\x00\x00\x00hi"
    cmd = Twist(linear=Vector3(x=1.0), angular=Vector3(z=-0.5))
    data = serialize(cmd)
    assert len(data) == 48
    assert np.frombuffer(data, dtype="<f8").tolist() == [1.0, 0, 0, 0, 0, -0.5]
    assert deserialize(data, "geometry_msgs/Twist") == cmd
    assert isinstance(deserialize(data, "geometry_msgs/Twist"), Twist)


def test_arrays_and_bytes():
    arr = UInt8MultiArray(data=b"\x01\x02\x03")
    assert arr.data.dtype == np.uint8 and arr.data.tolist() == [1, 2, 3]
    back = deserialize(serialize(arr), "std_msgs/UInt8MultiArray")
    assert back.data.tolist() == [1, 2, 3]
    with pytest.raises(MessageError, match="uint8"):
        UInt8MultiArray(data=[1, 300])
    pose = get_type("geometry_msgs/PoseWithCovariance")()
    with pytest.raises(MessageError, match="exactly 36"):
        pose.covariance = [0.0] * 35


def test_wrong_field_name_and_type_name_the_field():
    with pytest.raises(MessageError, match="geometry_msgs/Twist has no field 'linar'.*linear"):
        Twist(linar=Vector3())
    with pytest.raises(AttributeError):
        Twist().foo = 1
    with pytest.raises(MessageError, match="field 'x' of geometry_msgs/Vector3 is float64"):
        Vector3(x="fast")
    cmd = Twist()
    with pytest.raises(MessageError, match="field 'linear' of geometry_msgs/Twist"):
        cmd.linear = 3.0
    with pytest.raises(MessageError, match="int64"):
        get_type("beginner_tutorials/AddTwoIntsRequest")(a=2**70, b=0)


def test_unknown_type_suggests_close_names():
    with pytest.raises(MessageError, match="unknown message type 'geometry_msgs/Twst'.*Twist"):
        get_type("geometry_msgs/Twst")
    with pytest.raises(MessageError, match="not a message type name"):
        get_type("Twist with spaces")
    with pytest.raises(MessageError):
        from workbench.msgs.geometry_msgs import Twistt  # noqa: F401


def test_bad_bytes_raise_message_error():
    with pytest.raises(MessageError, match="not a valid geometry_msgs/Twist"):
        deserialize(b"\x00" * 10, "geometry_msgs/Twist")
    with pytest.raises(MessageError, match="not a workbench message"):
        serialize("hello")


def test_in_place_change_is_caught_at_serialize():
    msg = get_type("std_msgs/MultiArrayLayout")()
    msg.dim.append("not a dimension")
    with pytest.raises(MessageError, match="dim"):
        serialize(msg)


def test_services_have_request_response_and_md5():
    from workbench.msgs.turtlesim import Spawn, SpawnRequest, SpawnResponse

    assert Spawn.Request is SpawnRequest and Spawn.Response is SpawnResponse
    assert Spawn._type == "turtlesim/Spawn"
    assert SpawnRequest._type == "turtlesim/SpawnRequest"
    req = Spawn.Request(x=1.0, y=2.0, name="t2")
    assert deserialize(serialize(req), "turtlesim/SpawnRequest") == req
    with pytest.raises(MessageError, match="service type"):
        Spawn()
    assert "---" in msgs.service_definition("std_srvs/Trigger")


def test_time_and_duration():
    Time, Duration = msgs.Time, msgs.Duration
    t = Time(1.25)
    assert (t.secs, t.nsecs) == (1, 250_000_000) and t.to_sec() == 1.25
    assert Time(0) == Time(0, 0) and not Time(0)
    d = Time(3) - t
    assert isinstance(d, Duration) and d.to_sec() == 1.75
    assert (t + Duration(0.75)).to_sec() == 2.0
    assert Duration(-0.5).to_nsec() == -500_000_000
    assert Time(1, 2_000_000_000) == Time(3)
    header = Header(stamp=Time(5, 6))
    assert deserialize(serialize(header), "std_msgs/Header").stamp == Time(5, 6)


def test_dicts_lists_and_yaml():
    cmd = from_dict("geometry_msgs/Twist", [[2.0, 0.0, 0.0], [0.0, 0.0, 1.8]])
    assert cmd.linear.x == 2.0 and cmd.angular.z == 1.8
    assert to_dict(cmd)["angular"] == {"x": 0.0, "y": 0.0, "z": 1.8}
    assert from_dict("geometry_msgs/Twist", to_dict(cmd)) == cmd
    assert from_dict("std_msgs/String", "hi").data == "hi"
    with pytest.raises(MessageError, match="at 'linear'"):
        from_dict("geometry_msgs/Twist", {"linear": {"x": "fast"}})
    assert str(String(data="hello world")) == 'data: "hello world"'
    tf = from_dict("tf2_msgs/TFMessage", {"transforms": [{"child_frame_id": "b"}]})
    assert "child_frame_id" in str(tf)


def test_copy_pickle_and_equality():
    cmd = Twist(linear=Vector3(x=3.0))
    assert copy.deepcopy(cmd) == cmd
    assert copy.deepcopy(cmd).linear is not cmd.linear
    assert pickle.loads(pickle.dumps(cmd)) == cmd
    assert cmd != Twist()


def test_definitions_and_listing():
    text = definition("geometry_msgs/Twist")
    assert text.startswith("geometry_msgs/Vector3 linear") and "MSG: geometry_msgs/Vector3" in text
    assert "turtlesim/Pose" in msgs.list_types("turtlesim")
    assert "turtlesim/Spawn" in msgs.list_services("turtlesim")
    assert "sensor_msgs/Image" in msgs.list_types()


def test_register_a_new_type():
    cls = msgs.register_message("lab_msgs/Reading", "Header header\nfloat32[] values\n")
    msg = cls(values=[1.5])
    assert deserialize(serialize(msg), "lab_msgs/Reading").values.tolist() == [1.5]
    with pytest.raises(MessageError, match="cannot register"):
        msgs.register_message("lab_msgs/Reading", "int8 other\n")


def test_package_star_import():
    scope: dict = {}
    exec("from workbench.msgs.beginner_tutorials import *", scope)
    assert {"AddTwoInts", "AddTwoIntsRequest", "AddTwoIntsResponse"} <= set(scope)


def test_package_modules_answer_to_msg_and_srv_as_rospy_scripts_write_them():
    from workbench.msgs import geometry_msgs, turtlesim

    assert turtlesim.msg.Pose is turtlesim.Pose
    assert turtlesim.srv.Spawn is turtlesim.Spawn
    assert geometry_msgs.msg.Twist()._type == "geometry_msgs/Twist"
