"""Run the manual's tf scripts with turtlesim as threads of one process; print the outcome.

Used by ``test_lab_scripts.py`` in a subprocess (rospy's shutdown is process-wide)::

    python run_lab_scripts.py SECONDS DRIVE SCRIPT[:ARG,ARG...] ...

turtle1 is driven with a constant Twist when DRIVE is 1. At the end the script
prints one JSON line: the turtles' poses and anything the scripts logged.
"""

from __future__ import annotations

import json
import os
import runpy
import sys
import threading
import time

os.environ["WORKBENCH_MASTER_URI"] = "inproc"

from workbench.bus import Node, default_bus  # noqa: E402
from workbench.msgs.geometry_msgs import Twist, Vector3  # noqa: E402
from workbench.tf.nodes import examples_dir  # noqa: E402
from workbench.turtlesim.node import TurtlesimNode  # noqa: E402


def start_script(bus, script: str, args: list[str], errors: list[str]) -> None:
    path = str(examples_dir() / script)
    name = next((a.split(":=")[1] for a in args if a.startswith("__name:=")), None)
    if name is None:
        name = {
            "fixed_tf_broadcaster.py": "fixed_tf_broadcaster",
            "dynamic_tf_broadcaster.py": "dynamic_tf_broadcaster",
            "robot_setup_tf/tf_broadcaster.py": "robot_tf_publisher",
            "robot_setup_tf/tf_listener.py": "robot_tf_listener",
        }.get(script, "turtle_tf_listener")
    before = set(n.name for n in bus.nodes())
    sys.argv = [path, *args]

    def body() -> None:
        try:
            runpy.run_path(path, run_name="__main__")
        except BaseException as error:  # noqa: BLE001 - reported to the test
            if type(error).__name__ not in ("ROSInterruptException", "SystemExit"):
                errors.append(f"{script}: {type(error).__name__}: {error}")

    threading.Thread(target=body, daemon=True).start()
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:  # init_node has read sys.argv once the node exists
        if any(n.name.endswith(name) for n in bus.nodes() if n.name not in before):
            return
        time.sleep(0.01)
    errors.append(f"{script}: node {name} did not start")


def main() -> int:
    seconds, drive = float(sys.argv[1]), sys.argv[2] == "1"
    specs = sys.argv[3:]
    bus = default_bus()
    sim = TurtlesimNode(Node("turtlesim", bus=bus))
    errors: list[str] = []
    for spec in specs:
        script, _, args = spec.partition(":")
        start_script(bus, script, [a for a in args.split(",") if a], errors)
    driver = Node("driver", bus=bus)
    cmd = driver.create_publisher("/turtle1/cmd_vel", Twist)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if drive:
            cmd.publish(Twist(linear=Vector3(x=1.0), angular=Vector3(z=0.6)))
        time.sleep(0.05)
    poses = {}
    with sim.lock:
        for name in ("turtle1", "turtle2"):
            try:
                p = sim.sim.turtle(name).pose
                poses[name] = [p.x, p.y, p.theta]
            except Exception:  # noqa: BLE001 - not spawned
                pass
    print(json.dumps({"poses": poses, "errors": errors}), flush=True)
    os._exit(0)


if __name__ == "__main__":
    main()
