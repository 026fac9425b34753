"""Builds notebooks/10_slam_live.ipynb (run: python notebooks/builders/build_10_slam_live.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = []


def md(text: str) -> None:
    cells.append(new_markdown_cell(text.strip()))


def code(text: str) -> None:
    cells.append(new_code_cell(text.strip()))


md("""
# Experiment 10: map the house live with slam_gmapping

In the lab the TurtleBot3 wanders through a house in Gazebo while slam_gmapping builds the
map, RViz shows it growing, and map_saver writes it to disk. That takes five terminals:

| terminal | ROS | workbench (as processes) | here (section) |
|---|---|---|---|
| 1 | `roslaunch turtlebot3_gazebo turtlebot3_house.launch` | `workbench launch turtlebot3_gazebo turtlebot3_house.launch` | 1: the house, the robot |
| 2 | `roslaunch turtlebot3_slam turtlebot3_slam.launch slam_methods:=gmapping` | `workbench launch turtlebot3_slam turtlebot3_slam.launch` | 1: robot_state_publisher, slam_gmapping; 6: RViz |
| 3 | `roslaunch turtlebot3_gazebo turtlebot3_simulation.launch` (or teleop) | `workbench run turtlebot3_gazebo turtlebot3_drive` | 2: the wander node |
| 4 | `rosrun map_server map_saver -f ~/map` | `workbench run map_server map_saver -f map` | 3: save the map |
| 5 | `rosrun map_server map_server ~/map.yaml` | `workbench run map_server map_server map.yaml` | 4: load it again |

Here all of it runs **inside the notebook**, on one in-process bus: the simulator does not
run on its own clock but is stepped by the notebook as fast as it can, so a few simulated
minutes take much less on the wall and every run drives the same path. Section 5 does what
the lab cannot: it compares the map with the walls the world was built from. The files go
to the output folder printed by the first cell, not next to the notebook.
""")
code("""
import math
import os
import time

import matplotlib.pyplot as plt
import numpy as np
import yaml

from workbench.paths import examples_dir, mapping_dir, notebook_output, urdf_dir

SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"
OUT = notebook_output("10_slam_live")
print("files go to", OUT)
WANDER_SECONDS = 25.0 if SHORT else 240.0  # simulated time the robot wanders
SNAPSHOTS = 3  # maps shown while it grows (besides the last one)
STEP = 0.05  # simulated seconds between two decisions of the wander node
""")

md("""
## 1. Terminals 1 and 2: the house, the TurtleBot3, robot_state_publisher and slam_gmapping

`turtlebot3_house.launch` starts Gazebo with the house world and spawns the burger at the
origin (in the living room) through `/gazebo/spawn_urdf_model`. Its URDF starts the
differential drive (`/cmd_vel` in, `/odom` and `odom → base_footprint` out) and the LDS
lidar (360 beams, 0.12–3.5 m, 5 Hz on `/scan`, frame `base_scan`).
`turtlebot3_slam.launch` adds robot_state_publisher (the fixed frames
`base_footprint → base_link → base_scan`, which slam_gmapping needs to place the laser) and
slam_gmapping with the TurtleBot3's parameters (`turtlebot3_slam/config/gmapping_params.yaml`):
5 cm cells, a map published every 2 s. The simulated clock is on `/clock`
(`use_sim_time`), so every stamp is simulated time.
""")
code("""
from workbench.bus import Bus, Node
from workbench.mapping.gmapping_node import SKIPPED_AT_START, SlamGMapping
from workbench.mapping.gmapping_params import read_params
from workbench.model import load_robot
from workbench.msgs import gazebo_msgs as gm
from workbench.robot_state import RobotStatePublisher
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.gzserver import ServerOptions, build_server

bus = Bus()
bus.params.set("/use_sim_time", True)
world, server, _ = build_server(ServerOptions(world="house", fast=True, view=False), bus)
api = GazeboRosApi(server, Node("gazebo", bus=bus))
me = Node("student", bus=bus)

# terminal 1: spawn the burger at the origin, as spawn_model -urdf -param robot_description
urdf_path = urdf_dir() / "turtlebot3_burger.urdf"
urdf_text = urdf_path.read_text()
me.set_param("/robot_description", urdf_text)
request = gm.SpawnModel.Request(
    model_name="turtlebot3_burger", model_xml=urdf_text, robot_namespace="/"
)
request.initial_pose.orientation.w = 1.0
print(me.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel).call(request).status_message)
for label in server.plugin_labels():
    print("plugin:", label)

# terminal 2: robot_state_publisher and slam_gmapping with the TurtleBot3's parameters
rsp = RobotStatePublisher(load_robot(urdf_path), Node("robot_state_publisher", bus=bus))
config = examples_dir() / "packages" / "turtlebot3_slam" / "config" / "gmapping_params.yaml"
params = yaml.safe_load(config.read_text())
params.update(base_frame="base_footprint", odom_frame="odom", map_frame="map")
for name, value in params.items():
    bus.params.set(f"/slam_gmapping/{name}", value)
slam_node = Node("slam_gmapping", bus=bus)
mapper = SlamGMapping(slam_node, read_params(slam_node))
""")

md("""
## 2. Terminal 3: wander, and watch the map grow

`turtlebot3_drive` is the TurtleBot3's wander node: it looks at three sectors of `/scan`
(ahead, left, right), drives forward at 0.3 m/s while the way is clear and turns 30° away
from anything closer than 0.7 m. Here the same decisions (`Turtlebot3Drive`) get `/scan`
and `/odom` and their commands go to `/cmd_vel`; between two decisions the simulator runs
for 50 simulated ms.

slam_gmapping processes scans on its own thread. Gazebo runs at real time, so the node
keeps up; the notebook's simulator runs faster, so after each step the notebook waits until
the node has taken every scan (otherwise it would drop some, as slam_gmapping drops scans it
cannot keep up with). Every simulated second the notebook also asks Gazebo where the robot
truly is (`/gazebo/get_model_state`) and tf where slam_gmapping puts it
(`map → base_footprint`): section 5 compares the two.
""")
code("""
from workbench.msgs.geometry_msgs import Twist
from workbench.msgs.nav_msgs import OccupancyGrid, Odometry
from workbench.msgs.sensor_msgs import LaserScan
from workbench.teleop.turtlebot3_drive import Turtlebot3Drive
from workbench.tf import Buffer, TransformException, TransformListener

maps = []  # every /map slam_gmapping publishes
me.create_subscription("/map", OccupancyGrid, maps.append, 100, inline=True)
wander = Turtlebot3Drive()
me.create_subscription("/scan", LaserScan, wander.on_scan, 10, inline=True)
me.create_subscription("/odom", Odometry, wander.on_odom, 10, inline=True)
cmd_vel = me.create_publisher("/cmd_vel", Twist, 10)
buffer = Buffer()
TransformListener(buffer, me)
model_state = me.create_client("/gazebo/get_model_state", gm.GetModelState)


def slam_caught_up(timeout=5.0):
    \"\"\"Wait until slam_gmapping has dealt with every scan it was sent.\"\"\"
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        used = max(0, mapper.received - SKIPPED_AT_START)
        if mapper.processed + mapper.dropped >= used:
            return True
        time.sleep(0.002)
    return False


def sample():
    \"\"\"(true x, y, slam x, y): Gazebo's pose of the robot and the map pose tf gives it.\"\"\"
    truth = model_state.call(gm.GetModelState.Request(model_name="turtlebot3_burger")).pose
    try:
        est = buffer.lookup_transform("map", "base_footprint", 0).transform.translation
    except TransformException:
        return None
    return truth.position.x, truth.position.y, est.x, est.y


def occupied(grid):
    return int((np.asarray(grid.data) >= 65).sum())


def show_grid(ax, grid, title):
    \"\"\"An OccupancyGrid as RViz's "map" colours: free white, occupied black, unknown grey.\"\"\"
    info = grid.info
    cells = np.asarray(grid.data, dtype=float).reshape(info.height, info.width)
    image = np.where(cells < 0, 0.7, 1.0 - cells / 100.0)
    x0, y0, res = info.origin.position.x, info.origin.position.y, info.resolution
    extent = (x0, x0 + info.width * res, y0, y0 + info.height * res)
    ax.imshow(image, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent)
    ax.set_xlim(-5.5, 5.5)
    ax.set_ylim(-4.5, 4.5)
    ax.set_title(title)
    ax.set_xlabel("x (m)")


begin, wall = world.time, time.monotonic()
snapshot_times = [begin + WANDER_SECONDS * (k + 1) / (SNAPSHOTS + 1) for k in range(SNAPSHOTS)]
snapshots, track = [], []
next_sample = begin + 1.0
while world.time - begin < WANDER_SECONDS:
    command = wander.step()
    if command is not None:
        cmd_vel.publish(command.to_twist())
    server.run(until=world.time + STEP)
    slam_caught_up()
    if world.time >= next_sample:
        next_sample += 1.0
        if (pair := sample()) is not None:
            track.append(pair)
    if snapshot_times and world.time >= snapshot_times[0] and maps:
        snapshot_times.pop(0)
        snapshots.append((world.time - begin, maps[-1]))
cmd_vel.publish(Twist())
server.run(until=world.time + 0.5)
slam_caught_up()
mapper.update_map()  # publish the map of the last scan now, not at the next interval
snapshots.append((world.time - begin, maps[-1]))
print(f"wandered {world.time - begin:.1f} simulated s in {time.monotonic() - wall:.1f} s wall")
print(
    f"slam_gmapping: {mapper.received} scans received, {mapper.processed} processed, "
    f"{mapper.dropped} dropped; {len(maps)} maps published"
)
for t, grid in snapshots:
    print(
        f"map at t = {t:5.1f} s: {grid.info.width} x {grid.info.height} cells, "
        f"{occupied(grid)} occupied"
    )
fig, axes = plt.subplots(1, len(snapshots), figsize=(4 * len(snapshots), 3.6))
for ax, (t, grid) in zip(axes, snapshots, strict=True):
    show_grid(ax, grid, f"/map at {t:.0f} s")
path = np.array(track)
axes[-1].plot(path[:, 2], path[:, 3], "r-", lw=1)
plt.tight_layout()
plt.show()
""")

md("""
## 3. Terminal 4: `map_saver -f map`

map_saver waits for one message on `/map` (latched, so the last one published arrives at
once), writes the picture `map.pgm` (free white, occupied black, unknown grey) and
`map.yaml` (resolution, origin, thresholds), and exits. `MapSaver` is that node.
""")
code("""
from workbench.mapping.map_saver_node import MapSaver

saver = MapSaver(Node("map_saver", bus=bus), mapname=str(OUT / "map"))
print("saved:", saver.wait(timeout=10.0))
if saver.error is not None:
    print(saver.error)
for file in saver.files:
    print(f"{file.name}: {file.stat().st_size} bytes")
print((OUT / "map.yaml").read_text())
""")

md("""
## 4. Terminal 5: `map_server map.yaml`

map_server reads the YAML and the picture and publishes the map, latched, on `/map` (and
serves it on `static_map`). slam_gmapping still publishes `/map` here, so the map server's
topics are remapped to `/saved_map` (`map:=/saved_map`). What comes back is the saved map:
every cell is 100, 0 or -1, as the thresholds wrote them.
""")
code("""
from workbench.mapping.map_server_node import MapServer

server_node = Node(
    "map_server", bus=bus, argv=["map:=/saved_map", "map_metadata:=/saved_map_metadata"]
)
map_server = MapServer(server_node, str(OUT / "map.yaml"))
reloaded = []
me.create_subscription("/saved_map", OccupancyGrid, reloaded.append, 1, inline=True)
bus.spin_until(lambda: bool(reloaded), 10.0)
saved = reloaded[-1]
live = np.asarray(snapshots[-1][1].data)
back = np.asarray(saved.data)
thresholded = np.where(live >= 65, 100, np.where((live >= 0) & (live <= 25), 0, -1))
print(
    f"reloaded: {saved.info.width} x {saved.info.height} cells @ {saved.info.resolution:.3f} m, "
    f"origin ({saved.info.origin.position.x:.2f}, {saved.info.origin.position.y:.2f})"
)
print("the same cells as the live map, thresholded:", bool(np.array_equal(thresholded, back)))
fig, ax = plt.subplots(figsize=(5, 4))
show_grid(ax, saved, "map.yaml through map_server")
plt.show()
""")

md("""
## 5. The map against the house's true walls

The house world was built from a plan (`mapping/plans/house.yaml`), so the walls and the
furniture the laser can see at its height (18.2 cm) are known exactly. Two numbers say how
good the map is, counted on the saved map's cells with one cell (5 cm) of tolerance:

* **precision**: of the cells the map calls occupied, the share that are truly walls or
  furniture;
* **recall**: of the true wall faces next to space the map saw free, the share the map marks
  occupied.

The **trajectory error** is the distance between where Gazebo has the robot and where
slam_gmapping puts it (`map → base_footprint`), once a simulated second.
""")
code("""
from workbench.mapping import load_map
from workbench.sim.building import blocked_cells, load_plan

SCAN_HEIGHT = 0.182  # the burger's base_scan above the floor, m
plan = load_plan(mapping_dir() / "plans" / "house.yaml")


def true_obstacles(xs, ys):
    \"\"\"Cells (rows along y) where the house has something at the scan's height.\"\"\"
    return blocked_cells(plan.pieces(), xs, ys, (SCAN_HEIGHT, SCAN_HEIGHT))


def dilate(mask, cells=1):
    out = mask.copy()
    for dy in range(-cells, cells + 1):
        for dx in range(-cells, cells + 1):
            out |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return out


grid = load_map(OUT / "map.yaml")
height, width = grid.data.shape
xs = grid.origin[0] + (np.arange(width) + 0.5) * grid.resolution
ys = grid.origin[1] + (np.arange(height) + 0.5) * grid.resolution
truth = true_obstacles(xs, ys)
surface = truth & dilate(~truth)  # the faces a laser can see
mapped = grid.data >= 65
free = (grid.data >= 0) & (grid.data <= 25)
precision = (mapped & dilate(truth)).sum() / max(mapped.sum(), 1)
seen = surface & dilate(free)
recall = (seen & dilate(mapped)).sum() / max(seen.sum(), 1)
print(f"occupied cells: {mapped.sum()}; true wall faces seen: {seen.sum()}")
print(f"precision {precision:.3f}  recall {recall:.3f}  (within one cell)")
errors = np.hypot(path[:, 0] - path[:, 2], path[:, 1] - path[:, 3])
print(
    f"trajectory error: RMS {np.sqrt(np.mean(errors**2)):.3f} m, max {errors.max():.3f} m "
    f"over {len(errors)} samples"
)

fig, axes = plt.subplots(1, 2, figsize=(11, 4))
axes[0].imshow(truth, cmap="Greys", origin="lower", extent=(xs[0], xs[-1], ys[0], ys[-1]))
ok = mapped & dilate(truth)
axes[0].contour(xs, ys, mapped & ~ok, levels=[0.5], colors="r")
axes[0].imshow(
    np.ma.masked_where(~ok, ok),
    cmap="winter",
    origin="lower",
    extent=(xs[0], xs[-1], ys[0], ys[-1]),
    alpha=0.8,
)
axes[0].set_xlim(-5.5, 5.5)
axes[0].set_ylim(-4.5, 4.5)
axes[0].set_title("true walls (grey), mapped on them (blue), wrong (red)")
axes[1].plot(path[:, 0], path[:, 1], "k-", label="Gazebo (truth)")
axes[1].plot(path[:, 2], path[:, 3], "r--", label="slam_gmapping (map)")
axes[1].set_aspect("equal")
axes[1].legend()
axes[1].set_title("the robot's path")
plt.show()
""")

md("""
## 6. RViz: Map, RobotModel and LaserScan in the `map` frame

`turtlebot3_slam.launch` opens RViz with the map, the robot and the laser scan, the fixed
frame `map`. Here RViz runs in the browser; `save_html` writes a snapshot that opens
without the notebook.
""")
code("""
from workbench.rviz import RViz

rviz = RViz(bus, fixed_frame="map", displays=["Grid", "Map", "RobotModel"])
rviz.add_display("LaserScan", topic="/scan")
mapper.update_map()  # a fresh /map for the new subscriber
for _ in range(5):  # let the simulation go on a little while RViz draws
    server.run(until=world.time + 0.2)
    rviz.spin(0.1 if SHORT else 0.4)
for name, status in rviz.statuses().items():
    print(f"{name:12s}", status)
print("snapshot:", rviz.save_html(OUT / "slam_rviz.html"))
rviz
""")

md("""
Everything stops with the bus (in the lab: Ctrl-C in the five terminals).
""")
code("""
rviz.close()
mapper.close()
bus.shutdown()
print("stopped")
""")

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "name": "python3",
    "display_name": "Python 3",
    "language": "python",
}
path = Path(__file__).resolve().parents[1] / "10_slam_live.ipynb"
nbformat.write(notebook, path)
print("wrote", path)
