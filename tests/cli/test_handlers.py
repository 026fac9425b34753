"""The command handlers called as typed functions, in-process, on the embedded bus.

Each test joins the process-wide in-process bus (``WORKBENCH_MASTER_URI=inproc``, set
by the suite's conftest) with its own uniquely named nodes and shuts them down.
"""

from __future__ import annotations

import json
import math
import uuid

import pytest

from workbench.bus import Node
from workbench.cli import check, core, node, param, service, setup, show, teleop, tf, topic
from workbench.cli import turtlesim as turtlesim_cli
from workbench.errors import BusError, PlanningError, WorkbenchError
from workbench.msgs.beginner_tutorials import AddTwoInts, AddTwoIntsResponse
from workbench.msgs.std_msgs import String


@pytest.fixture
def talker():
    """A node that latches ``hi`` on a topic of its own; yields (node, topic)."""
    name = f"talker_{uuid.uuid4().hex[:8]}"
    talker_node = Node(name)
    topic_name = f"/{name}/chatter"
    talker_node.create_publisher(topic_name, String, latch=True).publish(String(data="hi"))
    yield talker_node, topic_name
    talker_node.shutdown()


def test_param_set_get_dump_load_delete(capsys, tmp_path):
    key = f"/cli_{uuid.uuid4().hex[:8]}"
    assert param.set_param(f"{key}/gain", "3") == 0
    assert param.get(f"{key}/gain") == 0
    assert capsys.readouterr().out.strip() == "3"
    assert param.list_params(key) == 0
    assert capsys.readouterr().out.split() == [f"{key}/gain"]
    assert param.dump(str(tmp_path / "p.yaml"), key) == 0
    assert param.delete(key) == 0
    with pytest.raises(WorkbenchError):
        param.get(f"{key}/gain")
    assert param.load(str(tmp_path / "p.yaml"), key) == 0
    assert param.get(f"{key}/gain") == 0
    assert capsys.readouterr().out.strip() == "3"
    param.delete(key)


def test_topic_list_type_info_and_echo(capsys, talker):
    _, name = talker
    assert topic.topic_list(verbose=True) == 0
    assert f"{name} [std_msgs/String] 1 publisher" in capsys.readouterr().out
    assert topic.topic_type(name) == 0
    assert capsys.readouterr().out.strip() == "std_msgs/String"
    assert topic.topic_type(f"{name}/data") == 0
    assert capsys.readouterr().out.strip() == "std_msgs/String data"
    assert topic.info(name) == 0
    assert "Publishers: \n * /talker_" in capsys.readouterr().out
    assert topic.echo(name, count=1, timeout=10) == 0
    assert capsys.readouterr().out == 'data: "hi"\n---\n'
    assert topic.echo(f"{name}/data", count=1, timeout=10) == 0
    assert capsys.readouterr().out == '"hi"\n---\n'


def test_topic_pub_once_reaches_a_subscriber(capsys):
    name = f"/pub_{uuid.uuid4().hex[:8]}"
    listener = Node(f"listener_{uuid.uuid4().hex[:8]}")
    heard: list[str] = []
    listener.create_subscription(name, String, lambda msg: heard.append(msg.data))
    try:
        assert topic.pub(["-1", name, "std_msgs/String", "hello"]) == 0
        listener.bus.spin_until(lambda: bool(heard), timeout=5)
    finally:
        listener.shutdown()
    assert heard == ["hello"]
    assert "publishing and latching message for 3.0 seconds" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: topic.echo("/x", count=0), "-n must be at least 1"),
        (lambda: topic.echo("/x", timeout=-1), "--timeout must be positive"),
        (lambda: topic.meter("hz", "/x", window=0), "--window must be 1 to 1,000,000 samples"),
        (lambda: topic.meter("hz", "/x", duration=math.inf), "--duration must be a number of"),
        (lambda: topic.echo("/x", timeout=1e308), "--timeout must be at most 10,000,000 s"),
        (lambda: topic.meter("rate", "/x"), "unknown meter 'rate'"),
        (lambda: topic.plot(["/x/y"], seconds=0), "--seconds must be positive"),
        (lambda: topic.pub(["/x"]), "pub needs a topic and a message type"),
        (lambda: topic.pub(["-r", "0", "/x", "std_msgs/String"]), "-r needs a positive rate"),
    ],
)
def test_topic_rejects_bad_options_before_joining_the_bus(call, message):
    with pytest.raises(BusError, match=message):
        call()


def test_topic_meter_reports_each_second(capsys, talker):
    _, name = talker
    assert topic.meter("bw", name, duration=1.0) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == f"subscribed to [{name}]" and len(out) == 2


def test_node_list_info_ping_graph_and_kill(capsys, talker, tmp_path):
    talker_node, _ = talker
    assert node.list_nodes() == 0
    assert talker_node.name in capsys.readouterr().out.split()
    assert node.info(talker_node.name) == 0
    assert f"Node [{talker_node.name}]" in capsys.readouterr().out
    assert node.ping(talker_node.name) == 0
    assert f"reply from {talker_node.name}" in capsys.readouterr().out
    assert node.graph(out=str(tmp_path / "g.gv")) == 0
    assert talker_node.name.lstrip("/") in (tmp_path / "g.gv").read_text()
    assert node.cleanup() == 0
    with pytest.raises(BusError):
        node.ping("/no_such_node")
    with pytest.raises(BusError, match="--count must be at least 1"):
        node.ping(talker_node.name, count=0)
    assert node.kill([talker_node.name]) == 0
    assert talker_node.bus.is_shutdown or talker_node.name not in talker_node.bus.graph().nodes


def test_service_list_type_info_and_call(capsys):
    server = Node(f"adder_{uuid.uuid4().hex[:8]}")
    name = f"{server.name}/add"
    server.create_service(name, AddTwoInts, lambda req: AddTwoIntsResponse(req.a + req.b))
    try:
        assert service.list_services() == 0
        assert name in capsys.readouterr().out.split()
        assert service.service_type(name) == 0
        assert capsys.readouterr().out.strip() == "beginner_tutorials/AddTwoInts"
        assert service.info(name) == 0
        assert "Args: a b" in capsys.readouterr().out
        assert service.find("beginner_tutorials/AddTwoInts") == 0
        assert name in capsys.readouterr().out.split()
        assert service.call(name, ["1", "3"]) == 0
        assert capsys.readouterr().out.strip() == "sum: 4"
        with pytest.raises(WorkbenchError, match="takes: a b"):
            service.call(name, ["1", "2", "3"])
    finally:
        server.shutdown()


def test_tf_echo_prints_a_static_transform(capsys):
    from workbench.tf.broadcaster import StaticTransformBroadcaster, make_transform

    child = f"frame_{uuid.uuid4().hex[:8]}"
    broadcaster_node = Node(f"static_{uuid.uuid4().hex[:8]}")
    StaticTransformBroadcaster(broadcaster_node).send_transform(
        make_transform("world", child, (1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0))
    )
    try:
        assert tf.echo("world", child, rate=20, count=1, timeout=10) == 0
    finally:
        broadcaster_node.shutdown()
    assert "- Translation: [1.000, 2.000, 3.000]" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: tf.echo("a", "b", rate=0), "--rate must be positive"),
        (lambda: tf.echo("a", "b", count=0), "--count must be at least 1"),
        (lambda: tf.frames(duration=-1), "--duration must not be negative"),
        (lambda: tf.view(scale=0), "--scale and --rate must be positive"),
        (lambda: tf.view(duration=0), "--duration must be positive"),
        (lambda: tf.view(rate=1e9), "--rate must be a rate from 0.001 to 10,000 Hz"),
        (lambda: tf.frames(duration=math.nan), "--duration must not be negative"),
    ],
)
def test_tf_rejects_bad_numbers(call, message):
    with pytest.raises(WorkbenchError, match=message):
        call()


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"samples": -1}, "--samples must be 0 to 1,000,000"),
        ({"samples": 10**20}, "--samples must be 0 to 1,000,000"),
        ({"seed": -2}, r"--seed must be 0 to 2\^32 - 1"),
        ({"velocity_scaling": 1.5}, r"--velocity-scaling must be in \(0, 1\]"),
        ({"edge_resolution": 0}, "--edge-resolution must be above 0 and at most pi"),
        ({"edge_resolution": math.inf}, "--edge-resolution must be above 0 and at most pi"),
        ({"group": "g" * 5000}, "--group 'ggg.*' has 5,000 characters; at most 256"),
        ({"output": ""}, "-o needs the folder"),
        ({"controller": "pd"}, "unknown controller 'pd'"),
        ({"planner": "RRTfoo"}, "unknown planner 'RRTfoo'"),
    ],
)
def test_setup_checks_its_options_before_sampling(tmp_path, options, message):
    with pytest.raises(PlanningError, match=message):
        setup.setup("robot_arm", **{"output": str(tmp_path / "cfg"), **options})
    assert not (tmp_path / "cfg").exists()


def test_setup_unknown_robot_names_the_available_ones(tmp_path):
    with pytest.raises(WorkbenchError, match="no robot description 'no_such_bot'"):
        setup.setup("no_such_bot", output=str(tmp_path / "cfg"))


def test_check_json_reports_an_unreadable_file(capsys, tmp_path):
    assert check.check(str(tmp_path / "absent.urdf"), as_json=True) == 1
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] is False and report["findings"][0]["code"] == "unreadable"
    assert check.check("arm3", load=False) == 0
    assert capsys.readouterr().out.startswith("robot name is: arm3\n")


def test_core_read_params(tmp_path):
    good = tmp_path / "p.yaml"
    good.write_text("gain: 2\nnames: [a, b]\n")
    assert core.read_params(str(good)) == {"gain": 2, "names": ["a", "b"]}
    bad = tmp_path / "list.yaml"
    bad.write_text("- 1\n- 2\n")
    with pytest.raises(WorkbenchError, match="must hold a YAML mapping"):
        core.read_params(str(bad))
    with pytest.raises(WorkbenchError, match="cannot read parameters"):
        core.read_params(str(tmp_path / "absent.yaml"))


def test_cheap_rejections_of_show_turtlesim_and_teleop(monkeypatch, tmp_path):
    with pytest.raises(WorkbenchError, match="--width and --height must be positive"):
        show.show("arm3", width=0)
    with pytest.raises(WorkbenchError, match="--port must be in 1..65535"):
        show.show("arm3", port=70000)
    with pytest.raises(WorkbenchError, match="--port must be in 0..65535"):
        turtlesim_cli.turtlesim(port=-1)
    with open(tmp_path / "keys", "w+") as not_a_terminal:
        monkeypatch.setattr("sys.stdin", not_a_terminal)
        with pytest.raises(WorkbenchError, match="terminal"):
            teleop.turtle()
