"""Builds notebooks/06_gazebo.ipynb (run: python notebooks/builders/build_06_gazebo.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 6 and Additional Experiment 1: simulation with the Gazebo ROS API\n\n"
        "The lab starts Gazebo, spawns URDF objects into an empty world, builds a robot in "
        "the model editor and writes plugins. workbench's simulator is a Drake physics server "
        "that speaks the same `gazebo_ros` API. In a terminal you would type:\n\n"
        "| ROS / Gazebo | workbench |\n|---|---|\n"
        "| `roslaunch gazebo_worlds empty_world.launch` | `workbench launch gazebo_worlds "
        "empty_world.launch` (or `workbench sim`) |\n"
        "| `rosrun gazebo spawn_model -file $PWD/object.urdf -urdf -z 1 -model my_object` | "
        "`workbench run gazebo spawn_model -file $PWD/object.urdf -urdf -z 1 -model my_object` |\n"
        "| `roslaunch gazebo_worlds table.launch` | `workbench launch gazebo_worlds table.launch` |\n"
        "| `rosservice call /gazebo/get_model_state ...` | `workbench service call "
        '/gazebo/get_model_state "model_name: my_object"` |\n\n'
        "Here the same server runs **inside the notebook**: one process, an in-process bus, "
        "and the simulation advanced cell by cell (`server.run(until=...)`), so every number "
        "below is reproducible. The files it writes (the robot you build, the recording) go "
        "to the output folder printed by the first cell, not next to the notebook."
    ),
    new_code_cell(
        "import math\n"
        "import os\n"
        "import time\n\n"
        "import numpy as np\n\n"
        "from workbench.bus import Bus, Node\n"
        "from workbench.msgs import gazebo_msgs as gm\n"
        "from workbench.paths import notebook_output\n"
        "from workbench.sim.gazebo_ros import GazeboRosApi\n"
        "from workbench.sim.gzserver import ServerOptions, build_server\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        'OUT = notebook_output("06_gazebo")\n'
        'print("files go to", OUT)\n\n'
        "bus = Bus()\n"
        'world, server, view = build_server(ServerOptions(world="empty", fast=True, record=True), bus)\n'
        'api = GazeboRosApi(server, Node("gazebo", bus=bus))\n'
        'me = Node("student", bus=bus)\n'
        'print("Meshcat:", view.meshcat.web_url())\n'
        'print("models:", world.model_names(), "time step:", world.time_step, "s")'
    ),
    new_markdown_cell(
        "## 1. Spawn the simple box at z = 1 (Additional Experiment 1)\n\n"
        "`spawn_model` reads the URDF and calls `/gazebo/spawn_urdf_model`. The manual's box "
        "has an inertia no real body has (iyy = 100 > ixx + izz): Gazebo simulates it anyway; "
        "workbench raises the two small moments just enough and says so in one line."
    ),
    new_code_cell(
        "from workbench.paths import urdf_dir\n\n\n"
        'def spawn(name, xml, x=0.0, y=0.0, z=0.0, service="/gazebo/spawn_urdf_model"):\n'
        "    request = gm.SpawnModel.Request(model_name=name, model_xml=xml)\n"
        "    request.initial_pose.position.x = x\n"
        "    request.initial_pose.position.y = y\n"
        "    request.initial_pose.position.z = z\n"
        "    request.initial_pose.orientation.w = 1.0\n"
        "    reply = me.create_client(service, gm.SpawnModel).call(request)\n"
        '    print(name, "->", reply.status_message)\n'
        "    return reply\n\n\n"
        'get_state = me.create_client("/gazebo/get_model_state", gm.GetModelState)\n\n'
        'spawn("my_object", (urdf_dir() / "simple_box.urdf").read_text(), z=1.0)\n'
        "server.run(until=world.time + 2.0)\n"
        'state = get_state.call(gm.GetModelState.Request(model_name="my_object"))\n'
        "z = state.pose.position.z\n"
        'print(f"resting at z = {z:.4f} m (the link frame is the bottom of the box)")\n'
        'spawn("my_object", (urdf_dir() / "simple_box.urdf").read_text(), z=3.0)  # name in use'
    ),
    new_markdown_cell(
        "## 2. The table from xacro, a coffee cup, a ball and some boxes\n\n"
        "`table.launch` expands `table.urdf.xacro` into a parameter and spawns it at z = 0.01 "
        "as `table_model`; the cup lands on the 0.55 m table top."
    ),
    new_code_cell(
        "from workbench.model import RobotDescription\n\n"
        'table = RobotDescription.load(urdf_dir() / "table.urdf.xacro").text\n'
        'spawn("table_model", table, x=3.0, z=0.01)\n'
        'spawn("coffee_cup", (urdf_dir() / "coffee_cup.urdf").read_text(), x=3.2, y=0.3, z=0.62)\n'
        'spawn("ball", (urdf_dir() / "ball.urdf").read_text(), x=2.9, y=-0.5, z=1.5)\n'
        "for i in range(2 if SHORT else 6):\n"
        "    spawn(\n"
        '        f"box_{i}",\n'
        '        (urdf_dir() / "small_box.urdf").read_text(),\n'
        "        x=2.8 + 0.15 * (i % 3),\n"
        "        y=-0.2 + 0.3 * (i // 3),\n"
        "        z=1.0 + 0.2 * i,\n"
        "    )\n"
        "server.run(until=world.time + 2.0)\n"
        'for name in ["table_model", "coffee_cup", "ball", "box_0"]:\n'
        "    z = get_state.call(gm.GetModelState.Request(model_name=name)).pose.position.z\n"
        '    print(f"{name:12s} z = {z:.3f} m")'
    ),
    new_markdown_cell(
        "## 3. Simulate a spinning top\n\n"
        "Spawned tilted by 0.2 rad with its tip on the floor, then given 150 rad/s about its "
        "own axis with `/gazebo/set_model_state`, the top precesses. The gyroscopic "
        "approximation predicts the rate Ω ≈ m g l / (I₃ ω) = 0.21 · 9.81 · 0.05 / "
        "(2.6e-4 · 150) ≈ 2.64 rad/s."
    ),
    new_code_cell(
        "from scipy.spatial.transform import Rotation\n\n"
        'tilt = Rotation.from_euler("x", 0.2)\n'
        "axis = tilt.apply([0, 0, 1])\n"
        'spawn("top", (urdf_dir() / "spinning_top.urdf").read_text(), x=-2.0, z=0.001)\n'
        'state = gm.ModelState(model_name="top")\n'
        "state.pose.position.x, state.pose.position.z = -2.0, 0.001\n"
        "qx, qy, qz, qw = tilt.as_quat()\n"
        "state.pose.orientation.x, state.pose.orientation.y = qx, qy\n"
        "state.pose.orientation.z, state.pose.orientation.w = qz, qw\n"
        "state.twist.angular.x, state.twist.angular.y, state.twist.angular.z = 150 * axis\n"
        "print(\n"
        '    me.create_client("/gazebo/set_model_state", gm.SetModelState)\n'
        "    .call(gm.SetModelState.Request(model_state=state))\n"
        "    .status_message\n"
        ")\n"
        "times, azimuth = [], []\n"
        "start = world.time\n"
        "for k in range(1, 201):\n"
        "    server.run(until=start + 0.01 * k)\n"
        '    pose = get_state.call(gm.GetModelState.Request(model_name="top")).pose\n'
        "    q = pose.orientation\n"
        "    a = Rotation.from_quat([q.x, q.y, q.z, q.w]).apply([0, 0, 1])\n"
        "    times.append(world.time)\n"
        "    azimuth.append(math.atan2(a[1], a[0]))\n"
        "rate = np.polyfit(times, np.unwrap(azimuth), 1)[0]\n"
        "predicted = 0.21 * 9.81 * 0.05 / (0.00026 * 150)\n"
        "print(\n"
        '    f"precession {rate:.3f} rad/s, predicted {predicted:.3f} rad/s "\n'
        '    f"({100 * (rate / predicted - 1):+.1f} %)"\n'
        ")"
    ),
    new_markdown_cell(
        "## 4. Build the two-wheeled robot (the model editor's steps)\n\n"
        "`ModelBuilder` does what the model editor does: a 2 × 1 × 0.15 m box at z = 0.4, two "
        "cylinders (r 0.3, 0.25 long) rolled 90° about x and aligned to the chassis's max x, "
        "max/min y (reversed) and centre z on revolute joints about their z, a ball caster "
        "(r 0.2) aligned min x, centre y, max z. Instead of the manual's follower plugin, each "
        "wheel gets the ROS-talking velocity controller, so the robot drives on commands. "
        "The model is saved as `simple_bot.sdf` and `simple_bot.urdf` in the output folder."
    ),
    new_code_cell(
        "from workbench.model import ModelBuilder, check_robot\n\n"
        'robot = ModelBuilder("simple_bot")\n'
        'robot.add_link("chassis", pose=(0, 0, 0.4, 0, 0, 0), mass=20.0)\n'
        'robot.add_box("chassis", (2.0, 1.0, 0.15), color=(0.2, 0.4, 0.8))\n'
        'for wheel, side in (("wheel_1", "max"), ("wheel_2", "min")):\n'
        "    robot.add_link(wheel, pose=(0, 0, 0.4, math.pi / 2, 0, 0), mass=2.0)\n"
        "    robot.add_cylinder(wheel, radius=0.3, length=0.25, color=(0.1, 0.1, 0.1))\n"
        '    robot.align(wheel, "chassis", x="max", y=side, z="center", reverse="y")\n'
        '    robot.add_joint(f"{wheel}_joint", "continuous", "chassis", wheel, axis="z", frame="child")\n'
        "    robot.add_plugin(\n"
        '        f"{wheel}_control",\n'
        '        "velocity_controller.py",\n'
        '        joint=f"{wheel}_joint",\n'
        '        topic=f"/simple_bot/{wheel}_cmd",\n'
        "        p_gain=20.0,\n"
        "        i_gain=20.0,\n"
        "    )\n"
        'robot.add_link("caster", pose=(0, 0, 0.4, 0, 0, 0), mass=1.0)\n'
        'robot.add_sphere("caster", radius=0.2)\n'
        'robot.align("caster", "chassis", x="min", y="center", z="max")\n'
        'robot.add_joint("caster_joint", "ball", "chassis", "caster")\n'
        'path = robot.save(OUT / "simple_bot.sdf")\n'
        'print("saved", path)\n'
        'print(check_robot(robot.save(OUT / "simple_bot.urdf")).format().splitlines()[-1])'
    ),
    new_code_cell(
        "from workbench.msgs.std_msgs import Float32\n\n"
        'spawn("simple_bot", path.read_text(), x=-4.0, z=-0.075, service="/gazebo/spawn_sdf_model")\n'
        "server.run(until=world.time + 0.5)\n"
        'left = me.create_publisher("/simple_bot/wheel_1_cmd", Float32)\n'
        'right = me.create_publisher("/simple_bot/wheel_2_cmd", Float32)\n'
        "left.publish(Float32(data=-1.0))  # wheel axes point along -y: negative drives +x\n"
        "right.publish(Float32(data=-1.0))\n"
        "time.sleep(0.2)  # the plugins' subscriptions run on the bus's threads\n"
        'before = get_state.call(gm.GetModelState.Request(model_name="simple_bot")).pose.position.x\n'
        "server.run(until=world.time + (2.0 if SHORT else 5.0))\n"
        'after = get_state.call(gm.GetModelState.Request(model_name="simple_bot"))\n'
        "print(\n"
        '    f"drove {after.pose.position.x - before:.2f} m, now at "\n'
        '    f"{after.twist.linear.x:.2f} m/s (wheel speed 1 rad/s x r 0.3 m = 0.3 m/s)"\n'
        ")"
    ),
    new_markdown_cell(
        "## 5. A model plugin from a URDF `<gazebo>` block\n\n"
        "`urdf/push_box.urdf` carries Gazebo's first plugin tutorial, `model_push.py` "
        "(`examples/gazebo/plugins/`): before every step it sets the model's velocity along x. "
        "A plugin that raises is reported with its file and line and switched off; the "
        "simulation goes on."
    ),
    new_code_cell(
        'spawn("push_box", (urdf_dir() / "push_box.urdf").read_text(), y=4.0)\n'
        'x0 = get_state.call(gm.GetModelState.Request(model_name="push_box")).pose.position.x\n'
        "server.run(until=world.time + 2.0)\n"
        'x1 = get_state.call(gm.GetModelState.Request(model_name="push_box")).pose.position.x\n'
        'print(f"the plugin pushed the box {x1 - x0:.2f} m in 2 s")\n'
        'print("plugins:", server.plugin_labels())'
    ),
    new_markdown_cell(
        "## 6. Delete a model and save a recording\n\n"
        "Deleting rebuilds the Drake diagram; every other model keeps its state. The "
        "recording (`--html` on the command line) is a self-contained animated HTML file, "
        "`gazebo_lab.html` in the output folder."
    ),
    new_code_cell(
        "print(\n"
        '    me.create_client("/gazebo/delete_model", gm.DeleteModel)\n'
        '    .call(gm.DeleteModel.Request(model_name="my_object"))\n'
        "    .status_message\n"
        ")\n"
        "print(\n"
        '    "models:",\n'
        '    me.create_client("/gazebo/get_world_properties", gm.GetWorldProperties)\n'
        "    .call(gm.GetWorldProperties.Request())\n"
        "    .model_names,\n"
        ")\n"
        'print("recording:", view.save_html(OUT / "gazebo_lab.html"))\n'
        "api.close()\n"
        "server.stop()\n"
        "bus.shutdown()"
    ),
]

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "name": "python3",
    "display_name": "Python 3",
    "language": "python",
}
out = Path(__file__).resolve().parents[1] / "06_gazebo.ipynb"
nbformat.write(notebook, out)
print(f"wrote {out}")
