"""Builds notebooks/02_turtlesim.ipynb (run: python notebooks/builders/build_02_turtlesim.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 2: getting started with turtlesim\n\n"
        "The lab opens six terminals: `roscore`, `turtlesim_node`, `turtle_teleop_key`, "
        "`rqt_graph`, `rqt_plot` and a shell for `rosnode`/`rostopic`/`rosservice`/`rosparam`/"
        "`rosbag`. Here the whole experiment runs **in this notebook**, on one in-process bus "
        "that we step by hand (so every run gives the same pictures).\n\n"
        "| ROS | workbench (terminal) | here |\n|---|---|---|\n"
        "| `rosrun turtlesim turtlesim_node` | `workbench turtlesim --view` | `TurtlesimNode(...)` |\n"
        "| `rosnode info /turtlesim` | `workbench node info /turtlesim` | `graphtext.node_info` |\n"
        "| `rostopic pub -1 ...` | `workbench topic pub -1 ...` | `pub.publish(...)` |\n"
        "| `rosservice call /spawn 2 2 0.2 turtle2` | `workbench service call /spawn 2 2 0.2 turtle2` "
        "| `client.call(...)` |\n"
        "| `rosparam set /turtlesim/background_r 150` | `workbench param set ...` | `node.set_param` |\n"
        "| `rosbag record/info/play` | `workbench bag record/info/play` | `Recorder`, `format_info`, `play` |\n"
        "| `rqt_plot /turtle1/pose/x` | `workbench topic plot /turtle1/pose/x` | `plot_series` |\n"
        "| `rqt_graph` | `workbench node graph` | `graph_to_dot` |\n\n"
        "The files it writes (the bag, the plot, the graph) go to the output folder "
        "printed by the first cell, not next to the notebook."
    ),
    new_code_cell(
        "import os\n\n"
        "from IPython.display import SVG, Image, display\n\n"
        "from workbench.bus import Bus, Node\n"
        "from workbench.msgs.geometry_msgs import Twist\n"
        "from workbench.msgs.std_srvs import Empty\n"
        "from workbench.msgs.turtlesim import Pose, SetPen, Spawn, TeleportAbsolute\n"
        "from workbench.paths import notebook_output\n"
        "from workbench.turtlesim.node import TurtlesimNode\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        "DRIVE_SECONDS = 1.0 if SHORT else 4.0\n"
        'OUT = notebook_output("02_turtlesim")\n'
        'print("files go to", OUT)'
    ),
    new_markdown_cell(
        "## 1. Start turtlesim\n\n"
        "`turtle1` appears in the middle of an 11.09 m square world (500 x 500 pixels, 45 pixels "
        "per metre), exactly where ROS puts it: x = y = 5.544445."
    ),
    new_code_cell(
        "bus = Bus(threaded=False)  # we step it ourselves\n"
        "bus.clock.use_sim_time()  # and its clock follows the simulation (stamps in sim seconds)\n"
        'sim = TurtlesimNode(Node("turtlesim", bus=bus), seed=0, start_timer=False)\n'
        'me = Node("student", bus=bus)\n'
        "display(sim.sim.render().resize((250, 250)))"
    ),
    new_markdown_cell("## 2. Nodes and topics (`rosnode`, `rostopic`)"),
    new_code_cell(
        "from workbench.introspect import graphtext\n\n"
        'print(graphtext.node_info(bus.graph(), "/turtlesim"))\n'
        "print(graphtext.topic_list(bus.graph(), verbose=True))"
    ),
    new_markdown_cell(
        "## 3. Drive the turtle (`rostopic pub`)\n\n"
        "`rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- '[2.0, 0.0, 0.0]' "
        "'[0.0, 0.0, 1.8]'` sends one command; turtlesim obeys it for 1 s and then stops, so "
        "we send it again every second (`-r 1`). We also listen to the pose, as `rostopic echo` "
        "and `rqt_plot` do."
    ),
    new_code_cell(
        "from workbench.introspect.args import message_from_args\n"
        "from workbench.introspect.echo import format_echo\n\n"
        "poses = []\n"
        'me.create_subscription("/turtle1/pose", Pose, lambda m: poses.append((sim.sim.time, m)))\n'
        'cmd_vel = me.create_publisher("/turtle1/cmd_vel", Twist)\n'
        'command = message_from_args("geometry_msgs/Twist", ["[2.0, 0.0, 0.0]", "[0.0, 0.0, 1.8]"])\n'
        "for _ in range(int(DRIVE_SECONDS)):\n"
        "    cmd_vel.publish(command)\n"
        "    sim.advance(1.0)\n"
        "print(format_echo(poses[-1][1]))\n"
        "display(sim.sim.render().resize((250, 250)))"
    ),
    new_markdown_cell("## 4. Services (`rosservice call`)"),
    new_code_cell(
        'spawn = me.create_client("/spawn", Spawn)\n'
        'print(spawn.call(Spawn.Request(x=2, y=2, theta=0.2, name="")))  # -> name: "turtle2"\n'
        'me.create_client("/turtle1/set_pen", SetPen).call(SetPen.Request(r=255, g=0, b=255, width=3))\n'
        'me.create_client("/turtle1/teleport_absolute", TeleportAbsolute).call(\n'
        "    TeleportAbsolute.Request(x=1, y=1, theta=0)\n"
        ")\n"
        "sim.advance(0.1)\n"
        "try:\n"
        '    spawn.call(Spawn.Request(x=1, y=1, theta=0, name="turtle2"))\n'
        "except Exception as error:\n"
        '    print("as in ROS, a taken name fails:", error)\n'
        "display(sim.sim.render().resize((250, 250)))"
    ),
    new_markdown_cell(
        "## 5. Parameters (`rosparam`): a new background\n\n"
        "Setting `background_r` changes nothing until `/clear` re-reads the parameters."
    ),
    new_code_cell(
        'me.set_param("/turtlesim/background_r", 150)\n'
        'print(me.get_param("/turtlesim"))\n'
        'me.create_client("/clear", Empty).call(Empty.Request())\n'
        "sim.advance(0.05)\n"
        "display(sim.sim.render().resize((250, 250)))"
    ),
    new_markdown_cell(
        "## 6. Record, inspect and replay a bag (`rosbag record/info/play`)\n\n"
        "The bag, `turtle.bag` in the output folder, is a real ROS 1 bag (v2.0): ROS, "
        "Foxglove and `rosbags` open it."
    ),
    new_code_cell(
        "from workbench.bag import format_info, play, read_messages, summarize\n"
        "from workbench.bag.record import Recorder\n\n"
        'me.create_client("/reset", Empty).call(Empty.Request())\n'
        "recorder = Recorder(\n"
        '    Node("record", bus=bus), OUT / "turtle.bag", topics=["/turtle1/cmd_vel", "/turtle1/pose"]\n'
        ")\n"
        "recorder.poll_topics()\n"
        "for _ in range(int(DRIVE_SECONDS)):\n"
        '    cmd_vel.publish(message_from_args("geometry_msgs/Twist", ["[2.0, 0, 0]", "[0, 0, -1.8]"]))\n'
        "    sim.advance(1.0)\n"
        "bag_path = recorder.close()\n"
        "print(format_info(summarize(bag_path)))"
    ),
    new_code_cell(
        "# Replay the recorded commands into a fresh turtlesim: it draws the same path.\n"
        "bus2 = Bus(threaded=False)\n"
        "bus2.clock.use_sim_time()\n"
        'replay_sim = TurtlesimNode(Node("turtlesim", bus=bus2), start_timer=False)\n'
        'player = Node("play", bus=bus2)\n'
        "publishers = {}\n\n\n"
        "def publish(topic, typename, msg):\n"
        '    if topic == "/turtle1/cmd_vel":\n'
        "        publishers.setdefault(topic, player.create_publisher(topic, Twist)).publish(msg)\n\n\n"
        'clock = {"t": 0.0}\n\n\n'
        "def sleep(seconds):  # bag time drives the simulation instead of the wall clock\n"
        "    replay_sim.advance(seconds)\n"
        '    clock["t"] += seconds\n\n\n'
        'report = play(bag_path, publish, delay=0.0, sleep=sleep, now=lambda: clock["t"])\n'
        "replay_sim.advance(0.016)\n"
        'recorded_end = [m.msg for m in read_messages(bag_path, ["/turtle1/pose"])][-1]\n'
        'replayed_end = replay_sim.sim.turtle("turtle1").pose\n'
        'print(f"published {report.published} messages")\n'
        'print(f"recorded end  x={recorded_end.x:.3f} y={recorded_end.y:.3f}")\n'
        'print(f"replayed end  x={replayed_end.x:.3f} y={replayed_end.y:.3f}")\n'
        "display(replay_sim.sim.render().resize((250, 250)))"
    ),
    new_markdown_cell(
        "## 7. Plot the pose (`rqt_plot /turtle1/pose/x /turtle1/pose/y /turtle1/pose/theta`)"
    ),
    new_code_cell(
        "from workbench.introspect.plot import FieldSeries, plot_series\n\n"
        'series = [FieldSeries(f"/turtle1/pose/{f}", "/turtle1/pose", [f]) for f in ("x", "y", "theta")]\n'
        "for t, msg in poses:\n"
        "    for s in series:\n"
        "        s.add(t, msg)\n"
        'display(Image(filename=str(plot_series(series, OUT / "pose.png"))))'
    ),
    new_markdown_cell(
        "## 8. The graph (`rqt_graph`)\n\n"
        "Nodes are ellipses, topics boxes; like rqt_graph, only topics with both a publisher "
        "and a subscriber are drawn. Drawing needs graphviz's `dot`."
    ),
    new_code_cell(
        "from workbench.introspect.graphview import graph_to_dot, write_graph\n"
        "from workbench.optional import find_program\n\n"
        "dot = graph_to_dot(bus.graph())\n"
        'if find_program("dot"):\n'
        '    display(SVG(filename=str(write_graph(dot, OUT / "rosgraph.svg"))))\n'
        "else:\n"
        "    print(dot.to_string())"
    ),
    new_code_cell("bus.shutdown()\nbus2.shutdown()"),
]

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "display_name": "Python 3",
    "language": "python",
    "name": "python3",
}
path = Path(__file__).resolve().parent.parent / "02_turtlesim.ipynb"
nbformat.write(notebook, path)
print(f"wrote {path}")
