"""rosnode/rostopic/rosservice text and the rqt_graph picture, on an in-process turtlesim.

Layouts as in ROS 1 Noetic: ``rosnode info`` (dashed rule, ``Node [/turtlesim]``,
``Publications:`` ... `` * /turtle1/pose [turtlesim/Pose]``), ``rostopic list -v``
(``Published topics:`` with ``N publisher(s)``), ``rostopic info`` (``Type:``,
``Publishers:``, ``Subscribers:``), ``rosservice list``/``type``/``find``.
"""

from __future__ import annotations

import pytest

from workbench.bus import Bus, Node
from workbench.errors import BusError
from workbench.introspect import graphtext
from workbench.introspect.graphview import graph_to_dot, write_graph
from workbench.msgs.geometry_msgs import Twist
from workbench.turtlesim.node import TurtlesimNode


@pytest.fixture(scope="module")
def graph():
    bus = Bus(threaded=False)
    TurtlesimNode(Node("turtlesim", bus=bus), start_timer=False)
    teleop = Node("teleop_turtle", bus=bus)
    teleop.create_publisher("/turtle1/cmd_vel", Twist)
    yield bus.graph()
    bus.shutdown()


def test_node_list_and_info(graph):
    assert graphtext.node_list(graph).splitlines() == ["/teleop_turtle", "/turtlesim"]
    lines = graphtext.node_info(graph, "/turtlesim").splitlines()
    assert lines[:8] == [
        "-" * 80,
        "Node [/turtlesim]",
        "Publications: ",
        " * /rosout [rosgraph_msgs/Log]",
        " * /turtle1/color_sensor [turtlesim/Color]",
        " * /turtle1/pose [turtlesim/Pose]",
        "",
        "Subscriptions: ",
    ]
    assert " * /turtle1/cmd_vel [geometry_msgs/Twist]" in lines
    services = lines[lines.index("Services: ") + 1 :]
    assert services[:4] == [" * /clear", " * /kill", " * /reset", " * /spawn"]
    assert " * topic: /turtle1/cmd_vel" in lines and "    * direction: inbound" in lines
    with pytest.raises(BusError, match=r"unknown node \[/nobody\].*running nodes: /teleop_turtle"):
        graphtext.node_info(graph, "nobody")


def test_topic_list_verbose_and_info(graph):
    assert "/turtle1/pose" in graphtext.topic_list(graph).splitlines()
    text = graphtext.topic_list(graph, verbose=True)
    assert " * /turtle1/pose [turtlesim/Pose] 1 publisher" in text
    assert " * /rosout [rosgraph_msgs/Log] 2 publishers" in text
    assert "Subscribed topics:\n * /turtle1/cmd_vel [geometry_msgs/Twist] 1 subscriber" in text
    info = graphtext.topic_info(graph, "/turtle1/cmd_vel").splitlines()
    assert info[0] == "Type: geometry_msgs/Twist"
    assert info[2] == "Publishers: "
    assert info[3].startswith(" * /teleop_turtle (this process")
    with pytest.raises(BusError, match="unknown topic /turtle9/pose"):
        graphtext.topic_info(graph, "/turtle9/pose")


def test_services(graph):
    names = graphtext.service_list(graph).splitlines()
    assert names[:4] == ["/clear", "/kill", "/reset", "/spawn"]
    assert graphtext.require_service(graph, "/clear").type == "std_srvs/Empty"
    assert graphtext.service_find(graph, "turtlesim/Spawn") == "/spawn"
    assert "Args: x y theta name" in graphtext.service_info(graph, "/spawn")
    with pytest.raises(BusError, match="service /nope does not exist"):
        graphtext.require_service(graph, "/nope")


def test_graph_picture(graph, tmp_path, require_program):
    dot = graph_to_dot(graph)
    text = dot.to_string()
    assert '"n:/teleop_turtle" -> "t:/turtle1/cmd_vel"' in text
    assert '"t:/turtle1/cmd_vel" -> "n:/turtlesim"' in text
    assert "/rosout" not in text  # hidden like rqt_graph's debug filter
    assert "/turtle1/pose" not in text  # nobody subscribes: not an active topic
    assert "/turtle1/pose" in graph_to_dot(graph, all_topics=True).to_string()
    gv = write_graph(dot, tmp_path / "g.gv")
    assert gv.read_text().startswith("digraph")
    require_program("dot")
    svg = write_graph(dot, tmp_path / "g.svg")
    assert "<svg" in svg.read_text()
