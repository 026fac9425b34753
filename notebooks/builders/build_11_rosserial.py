"""Builds notebooks/11_rosserial.ipynb (run: python notebooks/builders/build_11_rosserial.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 11: an Arduino on the bus (rosserial)\n\n"
        "The lab flashes two sketches onto an Arduino and bridges it with "
        "`rosrun rosserial_python serial_node.py /dev/ttyACM0`: program A publishes "
        '"hello world!" on `chatter`, program B publishes a button on `pushed` and drives a '
        "motor with it. Here both run on **virtual boards**: each sketch, translated line "
        "by line to Python, runs on a simulated Arduino whose serial port is a "
        "pseudo-terminal, and the host node talks to it byte for byte as to a real board "
        "(with a board plugged in, give its port instead).\n\n"
        "| ROS | workbench (terminal) | here |\n|---|---|---|\n"
        "| upload the sketch | `workbench serial virtual hello_world` | `VirtualBoard(...)` |\n"
        "| `rosrun rosserial_python serial_node.py /dev/ttyACM0` | "
        "`workbench serial /dev/ttyACM0` | `BackgroundHost(board.path)` |\n"
        "| `rostopic echo chatter` | `workbench topic echo chatter` | a subscription, `format_echo` |\n"
        "| press the button | Enter in the board's terminal | `board.press()` |\n\n"
        "The plot it draws goes to the output folder printed by the first cell."
    ),
    new_code_cell(
        "import os\n"
        "import time\n\n"
        "import matplotlib\n\n"
        'matplotlib.use("Agg")\n'
        "import matplotlib.pyplot as plt\n"
        "from IPython.display import Image, display\n\n"
        "from workbench.bus import Bus, Node\n"
        "from workbench.introspect.echo import format_echo\n"
        "from workbench.msgs.std_msgs import Bool, String\n"
        "from workbench.paths import notebook_output\n"
        "from workbench.serial.serial_node import BackgroundHost\n"
        "from workbench.serial.virtual import VirtualBoard\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        "MESSAGES = 2 if SHORT else 5\n"
        "PRESSES = 2 if SHORT else 4\n"
        'OUT = notebook_output("11_rosserial")\n'
        'print("files go to", OUT)\n\n\n'
        "def wait_until(condition, timeout=30.0):\n"
        "    deadline = time.monotonic() + timeout\n"
        "    while not condition() and time.monotonic() < deadline:\n"
        "        time.sleep(0.05)\n"
        "    return condition()"
    ),
    new_markdown_cell(
        "## Program A: hello world\n\n"
        "The sketch (`workbench serial virtual --list` shows them all) is the manual's, "
        "line by line: `nh = ros.NodeHandle()`, `chatter = ros.Publisher(\"chatter\", str_msg)`, "
        "`chatter.publish(str_msg)`, `nh.spinOnce()`, `delay(1000)`. The board in the manual "
        "had 200-byte buffers (an Uno's ros_lib has 280), so we give it those."
    ),
    new_code_cell(
        "bus = Bus()\n"
        'board = VirtualBoard("hello_world", buffer=200, bus=bus)\n'
        "board.start()\n"
        'print("the board\'s port:", board.path)'
    ),
    new_markdown_cell(
        "Start the host node on that port. It prints what `serial_node.py` prints: it "
        "connects, waits for the board to boot, asks for its topics and sets up a publisher "
        "for each."
    ),
    new_code_cell(
        "host = BackgroundHost(board.path, bus=bus)\n"
        "chatter = []\n"
        'Node("echo", bus=bus).create_subscription("chatter", String, chatter.append)\n'
        "wait_until(lambda: len(chatter) >= MESSAGES)"
    ),
    new_markdown_cell("What `rostopic echo chatter` shows, one message a second:"),
    new_code_cell("for msg in chatter[:MESSAGES]:\n    print(format_echo(msg), end='')"),
    new_code_cell("host.stop()  # Ctrl-C: the host sends TX_STOP and the board goes quiet\nboard.stop()"),
    new_markdown_cell(
        "## Program B: a button drives a DC motor\n\n"
        "Pin 7 has a push button to ground (its pull-up makes it read HIGH when "
        "released), pin 13 the motor driver. The sketch debounces the button for 50 ms, "
        "switches the motor and publishes the button on `pushed`. The board prints every "
        "change of a wired part."
    ),
    new_code_cell(
        'board = VirtualBoard("button_motor", bus=bus, report=print)\n'
        "board.start()\n"
        "host = BackgroundHost(board.path, bus=bus)\n"
        "pushed = []\n"
        'Node("echo_pushed", bus=bus).create_subscription(\n'
        '    "pushed", Bool, lambda msg: pushed.append((time.monotonic(), msg.data))\n'
        ")\n"
        "wait_until(lambda: host.bridge.publishers)"
    ),
    new_markdown_cell(
        "Press and release the button a few times (in a terminal: Enter in the board's "
        "window, or `workbench topic pub -1 /virtual_arduino/button std_msgs/Bool "
        "\"data: true\"`), and watch `pushed` and the motor."
    ),
    new_code_cell(
        "motor = []\n"
        "start = time.monotonic()\n"
        "for _ in range(PRESSES):\n"
        "    for pressed in (True, False):\n"
        "        board.press(pressed=pressed)\n"
        "        count = len(pushed)\n"
        "        wait_until(lambda: len(pushed) > count)\n"
        '        motor.append((time.monotonic(), board.level("motor")))\n'
        "        time.sleep(0.3)\n"
        "for t, value in pushed:\n"
        "    print(f\"{t - start:5.2f} s  data: {value}\")"
    ),
    new_code_cell(
        "fig, ax = plt.subplots(figsize=(7, 2.5))\n"
        "ax.step([t - start for t, _ in pushed], [int(v) for _, v in pushed], where='post', label='pushed')\n"
        "ax.step([t - start for t, _ in motor], [v - 0.05 for _, v in motor], where='post', label='motor pin 13 (offset)')\n"
        "ax.set_xlabel('time (s)')\n"
        "ax.set_yticks([0, 1], ['LOW / False', 'HIGH / True'])\n"
        "ax.legend(loc='upper right')\n"
        "fig.tight_layout()\n"
        'fig.savefig(OUT / "button_motor.png", dpi=100)\n'
        'display(Image(filename=str(OUT / "button_motor.png")))'
    ),
    new_code_cell("host.stop()\nboard.stop()\nbus.shutdown()"),
]

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "display_name": "Python 3",
    "language": "python",
    "name": "python3",
}
path = Path(__file__).resolve().parent.parent / "11_rosserial.ipynb"
nbformat.write(notebook, path)
print(f"wrote {path}")
