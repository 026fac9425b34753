"""gazebo_msgs: ROS's md5sums, wire round trips and a service call on the bus.

Expected md5sums are the ones ROS's own generators wrote into generated code that
is published in public repositories (they were not computed here):

* Primary source, every type below: iZhuoxx/Object-Tracking-for-UAV, commit
  55bf1ba053adb6f624bb9ace49bd32699a3467f8, gennodejs output for the Noetic
  gazebo_msgs, ``devel/share/gennodejs/ros/gazebo_msgs/msg/<Name>.js`` (messages:
  ``static md5sum()``) and ``devel/share/gennodejs/ros/gazebo_msgs/srv/<Name>.js``
  (services: ``md5sum()`` in ``module.exports``; request and response classes:
  their ``static md5sum()``).
* Second source, every type except SetLightProperties: koteshrv/Vargi_Bots_1418,
  commit 6bcf843c7150c93caee2b596e0864749c51b6155,
  ``devel/.private/gazebo_msgs/share/gennodejs/ros/gazebo_msgs/{msg,srv}/<Name>.js``.
  That workspace built gazebo_msgs 2.8.7 (Melodic), whose SetLightProperties
  request had fewer fields (md5sum cd58c48ac21e5165abf13bcaa9c079b4); the Noetic
  value below also appears in roslisp-generated code in the public index.
"""

from __future__ import annotations

import pytest

from workbench.bus import Bus, Node
from workbench.msgs import deserialize, get_type, md5sum, serialize
from workbench.msgs import gazebo_msgs as gz
from workbench.msgs.gazebo_msgs import (
    GetJointProperties,
    GetModelState,
    ModelState,
    SpawnModel,
)
from workbench.msgs.geometry_msgs import Point, Pose, Quaternion, Twist, Vector3

#: message type -> md5sum (primary source: msg/<Name>.js)
MESSAGE_MD5 = {
    "ContactState": "48c0ffb054b8c444f870cecea1ee50d9",
    "ContactsState": "acbcb1601a8e525bf72509f18e6f668d",
    "LinkState": "0818ebbf28ce3a08d48ab1eaa7309ebe",
    "LinkStates": "48c080191eb15c41858319b4d8a609c2",
    "ModelState": "9330fd35f2fcd82d457e54bd54e10593",
    "ModelStates": "48c080191eb15c41858319b4d8a609c2",
    "ODEJointProperties": "1b744c32a920af979f53afe2f9c3511f",
    "ODEPhysics": "667d56ddbd547918c32d1934503dc335",
    "PerformanceMetrics": "884f71fd5037b886ec5e126b83c4425a",
    "SensorPerformanceMetric": "01762ded18cfe9ebc7c8222667c99547",
    "WorldState": "de1a9de3ab7ba97ac0e9ec01a4eb481e",
}

#: service type -> (service, request, response) md5sums (primary source: srv/<Name>.js)
SERVICE_MD5 = {
    "ApplyBodyWrench": (
        "585b9f9618aa0581b207e2f2d90866bc",
        "e37e6adf97eba5095baa77dffb71e5bd",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "ApplyJointEffort": (
        "c0039811b8cc919490b3cff748cdf46b",
        "2c3396ab9af67a509ecd2167a8fe41a2",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "BodyRequest": (
        "5eade9afe7f232d78005bd0cafeab755",
        "5eade9afe7f232d78005bd0cafeab755",
        "d41d8cd98f00b204e9800998ecf8427e",
    ),
    "DeleteLight": (
        "ae11ea8100d536d5b92c2b5917abf912",
        "4fb676dfb4741fc866365702a859441c",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "DeleteModel": (
        "9ce56b4e9e54616de25d796dc972a262",
        "ea31c8eab6fc401383cf528a7c0984ba",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "GetJointProperties": (
        "7b30be900f50aa21efec4a0ec92d91c9",
        "0be1351618e1dc030eb7959d9a4902de",
        "cd7b30a39faa372283dc94c5f6457f82",
    ),
    "GetLightProperties": (
        "df2cef87e13e2e6990e81e8aaa454c19",
        "4fb676dfb4741fc866365702a859441c",
        "9a19ddd5aab4c13b7643d1722c709f1f",
    ),
    "GetLinkProperties": (
        "0e06a70386d0ee3fb880c02f23fcd821",
        "7d82d60381f1b66a30f2157f60884345",
        "a8619f92d17cfcc3958c0fd13299443d",
    ),
    "GetLinkState": (
        "09d6c98cce97b35f7ab9bd70300657ab",
        "7551675c30aaa71f7c288d4864552001",
        "8ba55ad34f9c072e75c0de57b089753b",
    ),
    "GetModelProperties": (
        "5717f7bd34ed990fa80e28b3015027a3",
        "ea31c8eab6fc401383cf528a7c0984ba",
        "b7f370938ef77b464b95f1bab3ec5028",
    ),
    "GetModelState": (
        "4c515e936d3319c9610c559c60bfc3d4",
        "19d412713cefe4a67437e17a951e759e",
        "ccd51739bb00f0141629e87b792e92b9",
    ),
    "GetPhysicsProperties": (
        "575a5e74786981b7df2e3afc567693a6",
        "d41d8cd98f00b204e9800998ecf8427e",
        "575a5e74786981b7df2e3afc567693a6",
    ),
    "GetWorldProperties": (
        "36bb0f2eccf4d8be971410c22818ba3f",
        "d41d8cd98f00b204e9800998ecf8427e",
        "36bb0f2eccf4d8be971410c22818ba3f",
    ),
    "JointRequest": (
        "0be1351618e1dc030eb7959d9a4902de",
        "0be1351618e1dc030eb7959d9a4902de",
        "d41d8cd98f00b204e9800998ecf8427e",
    ),
    "SetJointProperties": (
        "15a76e921b1410c698d82782ea5fa370",
        "331fd8f35fd27e3c1421175590258e26",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetJointTrajectory": (
        "88f5c10979e3f9649d5ae87a3b12aa65",
        "649dd2eba5ffd358069238825f9f85ab",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetLightProperties": (
        "e6f13430c57278bb364aca53a1bf5ebf",
        "10d953f2306aec18460eb80dd94fdd47",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetLinkProperties": (
        "d534ce1b36ee99de0ffa806c3a6348f0",
        "68ac74a4be01b165bc305b5ccdc45e91",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetLinkState": (
        "8a5146eb66ae4d26b0860b08f3f271be",
        "22a2c757d56911b6f27868159e9a872d",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetModelConfiguration": (
        "10e3139d3b669c40afc057d38956fff7",
        "160eae60f51fabff255480c70afa289f",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetModelState": (
        "5b3ab0281d4f5445def017e3a2e4a07b",
        "cb042b0e91880f4661b29ea5b6234350",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SetPhysicsProperties": (
        "97e2057080558ce4730434b5fae75c91",
        "abd9f82732b52b92e9d6bb36e6a82452",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
    "SpawnModel": (
        "9ed9c82c96abe1a00c3e8cdaeee24413",
        "6d0eba5753761cd57e6263a056b79930",
        "2ec6f3eff0161f4257b808b12bc830c2",
    ),
}


@pytest.mark.parametrize("name", sorted(MESSAGE_MD5))
def test_message_md5sum_matches_ros(name):
    assert md5sum(f"gazebo_msgs/{name}") == MESSAGE_MD5[name]


@pytest.mark.parametrize("name", sorted(SERVICE_MD5))
def test_service_md5sums_match_ros(name):
    service, request, response = SERVICE_MD5[name]
    assert md5sum(f"gazebo_msgs/{name}") == service
    assert get_type(f"gazebo_msgs/{name}")._md5sum == service
    assert md5sum(f"gazebo_msgs/{name}Request") == request
    assert md5sum(f"gazebo_msgs/{name}Response") == response


def test_every_registered_gazebo_type_has_an_expected_md5sum():
    members = set(gz.__all__)
    services = set(SERVICE_MD5)
    pairs = {f"{name}{part}" for name in services for part in ("Request", "Response")}
    assert members == set(MESSAGE_MD5) | services | pairs


def test_rospy_style_aliases_and_constants():
    assert gz.msg.ModelState is ModelState
    assert gz.srv.SpawnModel is SpawnModel
    assert gz.SpawnModelRequest is SpawnModel.Request
    response = GetJointProperties.Response
    assert (response.REVOLUTE, response.CONTINUOUS, response.PRISMATIC) == (0, 1, 2)
    assert (response.FIXED, response.BALL, response.UNIVERSAL) == (3, 4, 5)


def _box_state() -> ModelState:
    return ModelState(
        model_name="my_object",
        pose=Pose(
            position=Point(x=0.5, y=-1.25, z=1.0),
            orientation=Quaternion(x=0.0, y=0.0, z=0.7071067811865476, w=0.7071067811865476),
        ),
        twist=Twist(linear=Vector3(x=0.1), angular=Vector3(z=-3.5)),
        reference_frame="world",
    )


def test_model_state_round_trip_and_wire_layout():
    state = _box_state()
    data = serialize(state)
    # two length-prefixed strings around 13 float64s (pose 7, twist 6)
    assert len(data) == (4 + len("my_object")) + 13 * 8 + (4 + len("world"))
    assert data.startswith(b"\x09\x00\x00\x00my_object")
    assert data.endswith(b"\x05\x00\x00\x00world")
    back = deserialize(data, "gazebo_msgs/ModelState")
    assert isinstance(back, ModelState) and back == state
    assert back.pose.position.y == -1.25 and back.twist.angular.z == -3.5


def test_spawn_model_request_round_trip():
    request = SpawnModel.Request(
        model_name="my_object",
        model_xml='<robot name="simple_box"><link name="my_box"/></robot>',
        robot_namespace="/boxes",
        initial_pose=Pose(position=Point(z=1.0), orientation=Quaternion(w=1.0)),
        reference_frame="world",
    )
    back = deserialize(serialize(request), "gazebo_msgs/SpawnModelRequest")
    assert back == request
    assert back.model_xml.startswith('<robot name="simple_box">')
    assert back.initial_pose.position.z == 1.0 and back.initial_pose.orientation.w == 1.0


@pytest.fixture
def bus():
    bus = Bus(threaded=False)
    yield bus
    bus.shutdown()


def test_spawn_and_get_model_state_services_on_the_bus(bus):
    server, caller = Node("gazebo", bus=bus), Node("spawner", bus=bus)
    models: dict[str, Pose] = {}

    def spawn(req):
        if req.model_name in models:
            return SpawnModel.Response(success=False, status_message="name in use")
        models[req.model_name] = req.initial_pose
        return SpawnModel.Response(success=True, status_message="spawned")

    def get_state(req):
        pose = models.get(req.model_name)
        if pose is None:
            return GetModelState.Response(success=False, status_message="no such model")
        return GetModelState.Response(pose=pose, success=True, status_message="got")

    server.create_service("/gazebo/spawn_urdf_model", SpawnModel, spawn)
    server.create_service("/gazebo/get_model_state", GetModelState, get_state)
    spawn_client = caller.create_client("/gazebo/spawn_urdf_model", SpawnModel)
    state_client = caller.create_client("/gazebo/get_model_state", GetModelState)
    spawn_client.wait_for_service(timeout=1.0)

    pose = Pose(position=Point(z=1.0), orientation=Quaternion(w=1.0))
    first = spawn_client.call(SpawnModel.Request(model_name="my_object", initial_pose=pose))
    assert isinstance(first, SpawnModel.Response)
    assert first.success and first.status_message == "spawned"
    again = spawn_client.call(model_name="my_object", initial_pose=pose)
    assert not again.success and again.status_message == "name in use"

    state = state_client.call(GetModelState.Request(model_name="my_object"))
    assert state.success and state.pose.position.z == 1.0
    missing = state_client.call(model_name="ghost")
    assert not missing.success and missing.status_message == "no such model"
