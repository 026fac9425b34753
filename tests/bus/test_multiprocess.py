"""Several processes on one core: the lab's scripts, topics, services, params, liveliness."""

from __future__ import annotations

import signal
import subprocess
import sys

import pytest
from process_helpers import REPO, free_port, wait_for

from workbench.bus import AnyMsg, Bus, CoreError, Node, ServiceError, TopicTypeError
from workbench.msgs.beginner_tutorials import AddTwoInts
from workbench.msgs.std_msgs import Int32, String

pytestmark = pytest.mark.multiprocess
EXAMPLES = REPO / "examples"


def test_lab_scripts_as_separate_processes(procs):
    talker = procs.start(str(EXAMPLES / "talker.py"), name="talker")
    listener = procs.start(str(EXAMPLES / "listener.py"), name="listener")
    server = procs.start(str(EXAMPLES / "add_two_ints_server.py"), name="server")
    procs.wait_output(server, "Ready to add two ints.")
    client = subprocess.run(
        [sys.executable, str(EXAMPLES / "add_two_ints_client.py"), "1", "3"],
        env=procs.env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert client.returncode == 0, client.stderr
    assert client.stdout.splitlines() == ["Requesting 1+3", "1 + 3 = 4"]
    assert "Returning [1 + 3 = 4]" in procs.wait_output(server, "Returning")
    out = procs.wait_output(listener, "I heard hello world")
    assert "[INFO] [" in out and "/listener_" in out
    assert "]: hello world" in procs.wait_output(talker, "hello world")
    for popen in (talker, listener, server):  # Ctrl-C stops each cleanly
        popen.send_signal(signal.SIGINT)
    for popen in (talker, listener, server):
        assert popen.wait(10) == 0
        assert "Traceback" not in procs.output(popen)


def test_topics_remapping_graph_and_liveliness(procs):
    talker = procs.start(
        str(EXAMPLES / "talker.py"), "chatter:=/speech", "__name:=speaker", name="talker"
    )
    with Bus.connect(procs.uri) as bus:
        node = Node("observer", bus=bus)
        heard, anything = [], []
        node.create_subscription("/speech", String, lambda m: heard.append(m.data))
        node.create_subscription("/speech", AnyMsg, anything.append)
        assert wait_for(lambda: len(heard) >= 2 and anything), procs.output(talker)
        assert heard[0] == "hello world"
        assert isinstance(anything[0], String)  # decoded with the publisher's type
        graph = bus.graph()
        assert "/speaker" in graph.nodes and not graph.nodes["/speaker"].local
        assert graph.topics["/speech"].publishers == ["/speaker"]
        assert graph.topics["/speech"].type == "std_msgs/String"
        assert "/observer" in graph.topics["/speech"].subscribers
        with pytest.raises(TopicTypeError, match="std_msgs/String"):
            node.create_subscription("/speech", Int32, print)
        talker.kill()  # no clean shutdown: liveliness must still remove it
        talker.wait()
        assert wait_for(lambda: "/speaker" not in bus.graph().nodes, timeout=20)


def test_services_params_and_reliability_between_processes(procs):
    server = procs.start(str(EXAMPLES / "add_two_ints_server.py"), name="server")
    procs.wait_output(server, "Ready")
    with Bus.connect(procs.uri) as one, Bus.connect(procs.uri) as two:
        a, b = Node("a", bus=one), Node("b", bus=two, namespace="lab")
        client = a.create_client("add_two_ints", AddTwoInts)
        client.wait_for_service(timeout=10)
        assert client.call(AddTwoInts.Request(a=20, b=22)).sum == 42

        def broken(request):
            raise ValueError("no adding today")

        b.create_service("/broken", AddTwoInts, broken)
        remote = a.create_client("/broken", AddTwoInts)
        remote.wait_for_service(timeout=10)
        with pytest.raises(ServiceError, match="error processing request: no adding today"):
            remote.call(AddTwoInts.Request())
        with pytest.raises(ServiceError, match="unavailable"):
            a.create_client("/nobody", AddTwoInts).call(AddTwoInts.Request())
        assert client.call(AddTwoInts.Request(a=1, b=1)).sum == 2
        a.set_param("/lab/gains", {"p": 2.0, "i": [1, 2]})
        assert b.get_param("/lab/gains/i") == [1, 2]
        assert b.search_param("gains") == "/lab/gains"
        assert "/lab/gains/p" in two.params.names()
        b.delete_param("/lab")
        assert not a.has_param("/lab/gains")
        got = []
        b.create_subscription("/count", Int32, lambda m: got.append(m.data), queue_size=0)
        pub = a.create_publisher("/count", Int32)
        assert wait_for(lambda: pub.get_num_connections() == 1)
        for i in range(3000):
            pub.publish(Int32(data=i))
        assert wait_for(lambda: len(got) == 3000, timeout=30), len(got)
        assert got == list(range(3000))


def test_same_name_shuts_the_older_node_down(procs):
    listener = procs.start(str(EXAMPLES / "listener.py"), "__name:=twin", name="twin")
    with Bus.connect(procs.uri) as bus:
        # wait until its subscriber is up (the script is past init_node)
        assert wait_for(
            lambda: "/twin" in getattr(bus.graph().topics.get("/chatter"), "subscribers", [])
        )
        Node("twin", bus=bus)
        assert listener.wait(15) == 0
    assert "new node registered with same name" in procs.output(listener)


def test_latched_topic_across_processes(procs):
    with Bus.connect(procs.uri) as one:
        Node("mapper", bus=one).create_publisher("map_name", String, latch=True).publish("lab")
        with Bus.connect(procs.uri) as two:
            got = []
            Node("late", bus=two).create_subscription(
                "map_name", String, lambda m: got.append(m.data)
            )
            assert wait_for(lambda: got == ["lab"])


def test_core_unreachable_and_port_in_use(core_uri, run_cli):
    with pytest.raises(CoreError, match="no workbench core at tcp/127.0.0.1"):
        Bus.connect(f"tcp/127.0.0.1:{free_port()}")
    with pytest.raises(CoreError, match="not a core address"):
        Bus.connect("http://localhost")
    result = run_cli("core", "--uri", core_uri, timeout=60)
    assert result.returncode == 1
    assert "workbench core: error: port" in result.stderr and "already in use" in result.stderr
    assert "Traceback" not in result.stderr


def test_launch_starts_a_core_and_stops_everything(tmp_path):
    port = free_port()
    uri = f"tcp/127.0.0.1:{port}"
    launch = tmp_path / "demo.launch"
    launch.write_text(
        """<launch>
  <arg name="greeting" default="hi"/>
  <param name="greeting" value="$(arg greeting)"/>
  <node pkg="beginner_tutorials" type="add_two_ints_server.py" name="adder" output="screen">
    <param name="offset" type="int" value="3"/>
  </node>
  <node pkg="beginner_tutorials" type="listener.py" name="ear"/>
</launch>
"""
    )
    env = dict(__import__("os").environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    log = open(tmp_path / "launch.log", "wb")  # noqa: SIM115
    launcher = subprocess.Popen(
        [sys.executable, "-m", "workbench", "launch", str(launch), "greeting:=hello"],
        env=env,
        stdout=log,
        stderr=subprocess.STDOUT,
        cwd=tmp_path,
    )
    log.close()
    try:
        assert wait_for(lambda: "started with pid" in (tmp_path / "launch.log").read_text(), 30)
        with Bus.connect(uri) as bus:
            node = Node("checker", bus=bus)
            client = node.create_client("add_two_ints", AddTwoInts)
            client.wait_for_service(timeout=20)
            assert client.call(AddTwoInts.Request(a=1, b=3)).sum == 4
            assert node.get_param("/greeting") == "hello"
            assert node.get_param("/adder/offset") == 3
            assert wait_for(lambda: {"/adder", "/ear"} <= set(bus.graph().nodes))
        launcher.send_signal(signal.SIGINT)
        assert launcher.wait(20) == 130  # stopped by SIGINT, cleanly (128 + 2)
    finally:
        if launcher.poll() is None:
            launcher.kill()
            launcher.wait()
    text = (tmp_path / "launch.log").read_text()
    assert "started core service" in text
    pids = [
        int(line.split("[")[-1].split("]")[0])
        for line in text.splitlines()
        if "started with pid" in line
    ]
    assert len(pids) == 2
    for pid in pids:  # no node is left behind
        assert not __import__("os").path.exists(f"/proc/{pid}") or _zombie(pid)


def _zombie(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().split()[2] == "Z"
    except OSError:
        return True
