"""Builds notebooks/01_pubsub_services.ipynb (run: python notebooks/builders/build_01_pubsub_services.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 1: publisher/subscriber, service/client, parameters\n\n"
        "The lab runs `roscore`, a talker, a listener, an `add_two_ints` server and its client "
        "in separate terminals. Here we do the same twice: first **inside this notebook** "
        "(one process, no daemon), then **across processes** with a `workbench core`.\n\n"
        "| ROS | workbench (terminal) | here |\n|---|---|---|\n"
        "| `roscore` | `workbench core` | `Core(uri)` |\n"
        "| `rosrun beginner_tutorials talker.py` | `workbench run beginner_tutorials talker.py` "
        "| `node.create_publisher(...)` |\n"
        "| `rospy.Subscriber(...)` | (in your script) | `node.create_subscription(...)` |\n"
        "| `rospy.Service` / `rospy.ServiceProxy` | (in your script) "
        "| `node.create_service(...)` / `node.create_client(...)` |\n"
        "| `rosparam get /` | `workbench param get /` | `bus.params.get('/')` |"
    ),
    new_code_cell(
        "import os\n"
        "import time\n\n"
        "from workbench.bus import Bus, Node\n"
        "from workbench.msgs.beginner_tutorials import AddTwoInts\n"
        "from workbench.msgs.std_msgs import String\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        "SECONDS = 0.5 if SHORT else 2.0"
    ),
    new_markdown_cell(
        "## 1. Talker and listener in one process\n\n"
        "A `Bus()` is an in-process graph. The talker publishes `hello world` at 10 Hz from a "
        "timer; the listener's callback runs on the bus's executor threads, as rospy's do."
    ),
    new_code_cell(
        "bus = Bus()\n"
        'talker = Node("talker", bus=bus, anonymous=True)\n'
        'listener = Node("listener", bus=bus, anonymous=True)\n'
        'pub = talker.create_publisher("chatter", String, queue_size=10)\n'
        "heard = []\n\n\n"
        "def callback(msg):\n"
        "    heard.append(msg.data)\n"
        '    listener.get_logger().info(listener.name + "I heard %s", msg.data)\n\n\n'
        'listener.create_subscription("chatter", String, callback)\n'
        'timer = talker.create_timer(0.1, lambda event: pub.publish(String(data="hello world")))\n'
        "time.sleep(SECONDS)\n"
        "timer.shutdown()\n"
        'print(len(heard), "messages heard")'
    ),
    new_markdown_cell(
        "## 2. The add_two_ints service\n\n"
        "The handler returns the sum; the client's call blocks until the response comes back."
    ),
    new_code_cell(
        'server = Node("add_two_ints_server", bus=bus)\n\n\n'
        "def handle_add_two_ints(req):\n"
        '    print(f"Returning [{req.a} + {req.b} = {req.a + req.b}]")\n'
        "    return AddTwoInts.Response(sum=req.a + req.b)\n\n\n"
        'server.create_service("add_two_ints", AddTwoInts, handle_add_two_ints)\n'
        'client = listener.create_client("add_two_ints", AddTwoInts)\n'
        "client.wait_for_service(timeout=5.0)\n"
        'print("Requesting 1+3")\n'
        'print("1 + 3 =", client.call(AddTwoInts.Request(a=1, b=3)).sum)'
    ),
    new_markdown_cell(
        "## 3. Parameters and the graph\n\n"
        "Parameters follow ROS's names: global (`/background_r`), relative (resolved in the "
        "node's namespace) and private (`~rate`, under the node's name)."
    ),
    new_code_cell(
        'server.set_param("/turtlesim/background_r", 150)\n'
        'server.set_param("~offset", 0)\n'
        'print(bus.params.get("/"))\n'
        'print("search:", server.search_param("turtlesim"))\n'
        "graph = bus.graph()\n"
        "for name, topic in graph.topics.items():\n"
        '    print(f"{name:12} {topic.type:20} pubs={topic.publishers} subs={topic.subscribers}")\n'
        'print("services:", list(graph.services))'
    ),
    new_markdown_cell(
        "## 4. Stepping by hand\n\n"
        "With `Bus(threaded=False)` nothing runs until you step the executor: useful for "
        "deterministic tests."
    ),
    new_code_cell(
        "stepped = Bus(threaded=False)\n"
        'a, b = Node("a", bus=stepped), Node("b", bus=stepped)\n'
        "got = []\n"
        'b.create_subscription("numbers", "std_msgs/Int32", lambda m: got.append(m.data), queue_size=3)\n'
        'numbers = a.create_publisher("numbers", "std_msgs/Int32")\n'
        "for i in range(5):\n"
        "    numbers.publish(data=i)\n"
        'print("before spinning:", got)\n'
        "stepped.spin_until(lambda: len(got) == 3, timeout=1.0)\n"
        'print("after spinning (queue_size=3 keeps the newest):", got)\n'
        "stepped.shutdown()\n"
        "bus.shutdown()"
    ),
    new_markdown_cell(
        "## 5. Across processes, as in the lab\n\n"
        "Now the manual's own scripts (in `examples/`, only their imports changed) run as "
        "separate processes. A core on a free port plays `roscore`; the scripts find it through "
        "`WORKBENCH_MASTER_URI`. In a terminal you would type:\n\n"
        "```\nworkbench core\n"
        "workbench run beginner_tutorials talker.py\n"
        "workbench run beginner_tutorials listener.py\n"
        "workbench run beginner_tutorials add_two_ints_server.py\n"
        "workbench run beginner_tutorials add_two_ints_client.py 1 3\n```"
    ),
    new_code_cell(
        "import signal\n"
        "import socket\n"
        "import subprocess\n"
        "import sys\n\n"
        "from workbench.bus.core import Core\n"
        "from workbench.paths import project_root\n\n"
        "with socket.socket() as s:\n"
        '    s.bind(("127.0.0.1", 0))\n'
        "    port = s.getsockname()[1]\n"
        'uri = f"tcp/127.0.0.1:{port}"\n'
        "core = Core(uri)\n"
        'env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")\n'
        'examples = project_root() / "examples"\n'
        "children = [\n"
        "    subprocess.Popen(\n"
        "        [sys.executable, str(examples / name)],\n"
        "        env=env,\n"
        "        stdout=subprocess.DEVNULL,\n"
        "        stderr=subprocess.DEVNULL,\n"
        "    )\n"
        '    for name in ("talker.py", "add_two_ints_server.py")\n'
        "]\n"
        'print("core at", uri, "- started", [c.pid for c in children])'
    ),
    new_code_cell(
        "remote = Bus.connect(uri)\n"
        'me = Node("notebook", bus=remote, anonymous=True)\n'
        "heard_remote = []\n"
        'me.create_subscription("chatter", String, lambda m: heard_remote.append(m.data))\n'
        "remote.spin_until(lambda: len(heard_remote) >= 3, timeout=15)\n"
        'print("heard from the talker process:", heard_remote[:3])\n'
        "client = subprocess.run(\n"
        '    [sys.executable, str(examples / "add_two_ints_client.py"), "1", "3"],\n'
        "    env=env,\n"
        "    capture_output=True,\n"
        "    text=True,\n"
        "    timeout=60,\n"
        ")\n"
        "print(client.stdout)\n"
        'print("nodes:", sorted(remote.graph().nodes))'
    ),
    new_markdown_cell("Ctrl-C (SIGINT) stops each script cleanly; then we close the core."),
    new_code_cell(
        "for child in children:\n"
        "    child.send_signal(signal.SIGINT)\n"
        'print("exit codes:", [child.wait(10) for child in children])\n'
        "remote.shutdown()\n"
        "core.close()"
    ),
]

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "name": "python3",
    "display_name": "Python 3",
    "language": "python",
}
out = Path(__file__).resolve().parents[1] / "01_pubsub_services.ipynb"
nbformat.write(notebook, out)
print(f"wrote {out}")
