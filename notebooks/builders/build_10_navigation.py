"""Builds notebooks/10_navigation.ipynb (run: python notebooks/builders/build_10_navigation.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = []


def md(text: str) -> None:
    cells.append(new_markdown_cell(text.strip()))


def code(text: str) -> None:
    cells.append(new_code_cell(text.strip()))


md("""
# Experiment 10: navigate the house with AMCL and move_base

With a saved map of the house, the TurtleBot3 can be sent to a place on it: AMCL tells where
the robot is on the map from its laser and odometry, move_base plans a path to the goal
(navfn on the global costmap) and follows it (DWA on the local costmap). In the lab:

| terminal | ROS | workbench (as processes) | here (section) |
|---|---|---|---|
| 1 | `roslaunch turtlebot3_gazebo turtlebot3_house.launch` | `workbench launch turtlebot3_gazebo turtlebot3_house.launch` | 1: the house, the robot |
| 2 | `roslaunch turtlebot3_navigation turtlebot3_navigation.launch map_file:=$HOME/map.yaml` | `workbench launch turtlebot3_navigation turtlebot3_navigation.launch` (the saved house map by default) | 2: map_server, amcl, move_base |
| RViz | **2D Pose Estimate** | the tool's button in the viewer's panel | 3: `rviz.set_pose_estimate` |
| RViz | **2D Nav Goal** (or a script with `SimpleActionClient`) | the tool's button, `workbench topic pub /move_base_simple/goal ...` | 4: `SimpleActionClient` |

Here all of it runs **inside the notebook**, on one in-process bus that the notebook steps:
the simulator runs as fast as it can, and after every physics step the notebook lets each
node handle what arrived, so the nodes keep up as they would at real time and every run
drives the same paths. The plots and the RViz snapshot go to the output folder printed by
the first cell.
""")
code("""
import math
import os
import time

import matplotlib.pyplot as plt
import numpy as np

from workbench.paths import examples_dir, mapping_dir, notebook_output, urdf_dir

SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"
OUT = notebook_output("10_navigation")
print("files go to", OUT)
MAP = mapping_dir() / "house.yaml"  # the house mapped live by slam_gmapping
START = (-2.0, -2.5)  # where the burger is spawned (the living room), m
GUESS = (-1.7, -2.3, math.radians(15.0))  # the 2D Pose Estimate, a little off: x, y m, yaw rad
# three goals (x, y m, yaw rad): the hall, the kitchen (through its door), the living room
GOALS = [(-0.2, 0.0, math.pi / 2), (2.5, -2.0, 0.0), (-2.0, -1.0, math.pi)]
TIME_LIMIT = 120.0  # simulated seconds per goal
""")

md("""
## 1. Terminal 1: the house and the TurtleBot3

`turtlebot3_house.launch` starts the simulator with the house world and spawns the burger
(`x_pos:=-2.0 y_pos:=-2.5` here, not at the origin). One change from the launch file: the
diff drive's odometry comes from the wheel encoders (`<odometrySource>encoder</odometrySource>`),
as on the real robot, so `odom` drifts from the truth and AMCL has something to correct
(the launch file's URDF uses the simulator's exact pose). robot_state_publisher adds the
fixed frames `base_footprint → base_link → base_scan`.
""")
code("""
from workbench.bus import Bus, Node
from workbench.model import load_robot
from workbench.msgs import gazebo_msgs as gm
from workbench.robot_state import RobotStatePublisher
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.gzserver import ServerOptions, build_server

ROBOT = "turtlebot3_burger"
bus = Bus(threaded=False)  # callbacks run when the notebook spins the bus
bus.params.set("/use_sim_time", True)
world, server, _ = build_server(ServerOptions(world="house", fast=True, view=False), bus)
api = GazeboRosApi(server, Node("gazebo", bus=bus))
me = Node("student", bus=bus)

urdf_path = urdf_dir() / f"{ROBOT}.urdf"
urdf_text = urdf_path.read_text().replace(
    "<odometrySource>world</odometrySource>", "<odometrySource>encoder</odometrySource>"
)
request = gm.SpawnModel.Request(model_name=ROBOT, model_xml=urdf_text, robot_namespace="/")
request.initial_pose.position.x, request.initial_pose.position.y = START
request.initial_pose.orientation.w = 1.0
print(me.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel).call(request).status_message)
rsp = RobotStatePublisher(load_robot(urdf_path), Node("robot_state_publisher", bus=bus))
""")

md("""
## 2. Terminal 2: map_server, AMCL and move_base

`turtlebot3_navigation.launch` loads the parameters of its include files: `amcl.launch`
(500–3000 particles, the likelihood-field laser model on 180 of the 360 beams, a
differential-drive motion model) and `move_base.launch` with the burger's YAML files
(costmaps with a 1 m inflation radius, DWAPlannerROS at up to 0.22 m/s). The launcher reads
them here exactly as `workbench launch` would, and the nodes are the same classes the
processes run. AMCL starts where its `initial_pose_*` parameters say: the origin, about
3 m from the robot.
""")
code("""
from workbench.actionlib import SimpleActionClient
from workbench.bus.launch import load_launch
from workbench.mapping.map_server_node import MapServer
from workbench.msgs.geometry_msgs import PoseArray, PoseWithCovarianceStamped
from workbench.msgs.move_base_msgs import MoveBaseAction
from workbench.navigation.amcl_node import Amcl
from workbench.navigation.move_base import MoveBase
from workbench.tf import Buffer, TransformException, TransformListener

launch = examples_dir() / "packages" / "turtlebot3_navigation" / "launch"
plan = load_launch(
    launch / "turtlebot3_navigation.launch", {"open_rviz": "false", "map_file": str(MAP)}
)
for key, value in plan.params.items():
    if key != "/robot_description":  # the spawned robot's (encoder odometry) stays
        bus.params.set(key, value)
print("nodes in the launch file:", ", ".join(n.name for n in plan.nodes))

map_server = MapServer(Node("map_server", bus=bus), str(MAP))
amcl = Amcl(Node("amcl", bus=bus))
buffer = Buffer(cache_time=10.0)
TransformListener(buffer, me)
clouds = []  # AMCL's particle clouds
me.create_subscription("/particlecloud", PoseArray, clouds.append, 10, inline=True)
amcl_poses = []
me.create_subscription("/amcl_pose", PoseWithCovarianceStamped, amcl_poses.append, 10, inline=True)
last_scan = [None]
me.create_subscription("/scan", "sensor_msgs/LaserScan", lambda m: last_scan.__setitem__(0, m.header.stamp), 10, inline=True)


def spin_nodes():
    \"\"\"Run every callback due on the bus, then let AMCL take the scans it can place.\"\"\"
    while True:
        while bus.spin_once(0.0):
            pass
        if not amcl.busy:
            return
        if last_scan[0] is not None and not amcl.buffer.can_transform(
            "odom", "base_footprint", last_scan[0]
        ):
            return  # a scan waits for odometry the simulator has not produced yet
        amcl.wait_idle()


server.hooks.append(lambda _server: spin_nodes())  # after every physics chunk
spin_nodes()
amcl.wait_idle()
mb_node = Node("move_base", bus=bus)
mb_buffer = Buffer(cache_time=10.0)
TransformListener(mb_buffer, mb_node)
move_base = MoveBase(mb_node, mb_buffer)
client = SimpleActionClient("move_base", MoveBaseAction, me)
server.run(until=world.time + 1.0)


def truth():
    \"\"\"The simulator's pose of the robot: x, y (m), yaw (rad).\"\"\"
    X = world.get_model_pose(ROBOT)
    R = X.rotation().matrix()
    return X.translation()[0], X.translation()[1], math.atan2(R[1, 0], R[0, 0])


def estimate():
    \"\"\"Where AMCL puts the robot: map -> base_footprint on tf (x, y m, yaw rad).\"\"\"
    try:
        t = buffer.lookup_transform("map", "base_footprint", 0).transform
    except TransformException:
        return None
    q = t.rotation
    return t.translation.x, t.translation.y, 2 * math.atan2(q.z, q.w)


def report(when):
    x, y, _ = truth()
    ex, ey, _ = estimate()
    print(f"{when}: true ({x:5.2f}, {y:5.2f}), AMCL ({ex:5.2f}, {ey:5.2f}), "
          f"off by {math.hypot(ex - x, ey - y):.2f} m; {len(clouds[-1].poses)} particles")


report("AMCL at its initial pose")
""")

md("""
## 3. RViz's "2D Pose Estimate": tell AMCL roughly where the robot is

In RViz you click where the robot is and drag its heading; RViz sends the pose on
`/initialpose` with standard deviations of 0.5 m and 15°, and AMCL spreads its particles
there (`Setting pose ...`). The estimate here is 0.36 m and 15° off, as a click would be.
Once the robot moves (AMCL updates after `update_min_d` 0.2 m or `update_min_a` 0.2 rad),
the laser pulls the particles onto the true pose.
""")
code("""
from workbench.rviz import RViz

rviz = RViz(bus, fixed_frame="map", displays=["Grid", "Map", "PoseArray", "Path", "RobotModel"])
rviz.add_display("Map", name="Global costmap", topic="/move_base/global_costmap/costmap",
                 color_scheme="costmap")
rviz.add_display("Path", name="Global plan", topic="/move_base/NavfnROS/plan")
rviz.set_pose_estimate(*GUESS)
server.run(until=world.time + 1.0)  # AMCL takes it, then re-sends map -> odom with a scan
report("after the 2D Pose Estimate")
spread_after_estimate = clouds[-1]
""")

md("""
## 4. Three goals through the `move_base` action

A script sends goals as RViz's "2D Nav Goal" does, through actionlib: `SimpleActionClient`
on `move_base` with a `move_base_msgs/MoveBaseGoal` in the `map` frame, then waits for the
result (`SUCCEEDED` is 3). While the robot drives, the notebook records every 0.2 simulated
seconds where it truly is and where AMCL puts it.
""")
code("""
from workbench.actionlib import SUCCEEDED
from workbench.actionlib.client import SIMPLE_DONE
from workbench.msgs.move_base_msgs import MoveBaseGoal

true_path, amcl_path, results = [truth()[:2]], [estimate()[:2]], []
wall = time.monotonic()
begin = world.time
for gx, gy, gyaw in GOALS:
    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = "map"
    goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = gx, gy
    goal.target_pose.pose.orientation.z = math.sin(gyaw / 2)
    goal.target_pose.pose.orientation.w = math.cos(gyaw / 2)
    t0 = world.time
    client.send_goal(goal)
    while client.simple_state != SIMPLE_DONE and world.time - t0 < TIME_LIMIT:
        server.run(until=world.time + 0.2)
        true_path.append(truth()[:2])
        amcl_path.append(estimate()[:2])
    x, y, _ = truth()
    state = client.get_state()
    results.append((gx, gy, state, world.time - t0, math.hypot(x - gx, y - gy)))
    print(f"goal ({gx:5.2f}, {gy:5.2f}): state {state} "
          f"({'SUCCEEDED' if state == SUCCEEDED else client.get_goal_status_text()}) "
          f"after {world.time - t0:5.1f} s, the robot {math.hypot(x - gx, y - gy):.3f} m from it")
print(f"{world.time - begin:.1f} simulated s in {time.monotonic() - wall:.1f} s wall")
report("at the end")
""")

md("""
## 5. The paths on the map

The saved map (free white, walls black, unknown grey) with the path the robot truly drove
(from the simulator) and the path AMCL saw. At the start they differ by the initial
guess's error; after a metre or so of driving AMCL is on the true path. The second plot
shows AMCL's particles right after the 2D Pose Estimate and at the end.
""")
code("""
from workbench.mapping import load_map

grid = load_map(MAP)
height, width = grid.data.shape
extent = (grid.origin[0], grid.origin[0] + width * grid.resolution,
          grid.origin[1], grid.origin[1] + height * grid.resolution)
image = np.where(grid.data < 0, 0.7, 1.0 - grid.data / 100.0)
true_xy, amcl_xy = np.array(true_path), np.array(amcl_path)
errors = np.hypot(*(amcl_xy - true_xy).T)

fig, axes = plt.subplots(1, 2, figsize=(13, 5))
for ax in axes:
    ax.imshow(image, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent)
    ax.set_xlim(-5.5, 5.5)
    ax.set_ylim(-4.5, 4.5)
    ax.set_xlabel("x (m)")
axes[0].plot(true_xy[:, 0], true_xy[:, 1], "k-", lw=2, label="true (simulator)")
axes[0].plot(amcl_xy[:, 0], amcl_xy[:, 1], "r--", lw=1.5, label="AMCL (map → base_footprint)")
axes[0].plot(*START, "ko", label="start")
axes[0].arrow(GUESS[0], GUESS[1], 0.4 * math.cos(GUESS[2]), 0.4 * math.sin(GUESS[2]),
              color="tab:orange", width=0.04, label="2D Pose Estimate")
for i, (gx, gy, *_rest) in enumerate(results):
    axes[0].plot(gx, gy, "g*", ms=14)
    axes[0].annotate(f"goal {i + 1}", (gx, gy), textcoords="offset points", xytext=(6, 6))
axes[0].legend(loc="lower right", fontsize=8)
axes[0].set_title("the robot's paths on the saved map")
for cloud, colour, label in ((spread_after_estimate, "tab:orange", "after the estimate"),
                             (clouds[-1], "tab:blue", "at the end")):
    xy = np.array([(p.position.x, p.position.y) for p in cloud.poses])
    axes[1].plot(xy[:, 0], xy[:, 1], ".", ms=2, color=colour, label=f"{label}: {len(xy)}")
axes[1].legend(loc="lower right", fontsize=8)
axes[1].set_title("AMCL's particles")
plt.tight_layout()
fig.savefig(OUT / "navigation_paths.png", dpi=80)
plt.show()
after = errors[len(errors) // 4:]
print(f"AMCL error: first sample {errors[0]:.2f} m, over the last three quarters "
      f"median {np.median(after):.3f} m, max {after.max():.3f} m")
""")

md("""
## 6. RViz: the map, the global costmap and plan, the particles

`turtlebot3_navigation.launch` opens RViz with the navigation view; here RViz runs in the
browser and `save_html` writes a snapshot that opens without the notebook.
""")
code("""
for _ in range(3):
    server.run(until=world.time + 0.2)
    rviz.spin(0.1 if SHORT else 0.4)
for name, status in rviz.statuses().items():
    print(f"{name:16s}", status)
print("snapshot:", rviz.save_html(OUT / "navigation_rviz.html"))
rviz
""")

md("""
Everything stops with the bus (in the lab: Ctrl-C in the two terminals).
""")
code("""
rviz.close()
move_base.shutdown()
amcl.close()
api.close()
server.stop()
bus.shutdown()
print("stopped")
""")

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "name": "python3",
    "display_name": "Python 3",
    "language": "python",
}
path = Path(__file__).resolve().parents[1] / "10_navigation.ipynb"
nbformat.write(notebook, path)
print("wrote", path)
