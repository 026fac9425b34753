"""Builds notebooks/07_sensors_worlds.ipynb (run: python notebooks/builders/build_07_sensors_worlds.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = []


def md(text: str) -> None:
    cells.append(new_markdown_cell(text.strip()))


def code(text: str) -> None:
    cells.append(new_code_cell(text.strip()))


md("""
# Experiment 7: worlds, a robot with a laser, and what its sensors see

The lab builds a world in Gazebo's building editor (Experiment 7.1), spawns `custom_bot` with
its laser scanner, drives it and looks at the laser in RViz (Experiment 7.2), then adds blocks
in front of the robot to see them in the scan. workbench does the same without ROS or Gazebo:

| ROS / Gazebo | workbench |
|---|---|
| Edit → Building Editor, draw walls, doors, windows | a plan file (YAML), `load_plan` / `plan_from_dict` |
| Building Editor → Import (a floor-plan image) | `plan_from_image` (a picture or a map_server map) |
| File → Save World As | `plan.save("my.world")`, or `workbench world build PLAN -o my.world` |
| `roslaunch gazebo_ros empty_world.launch world_name:=my.world` | `workbench sim my.world` |
| `rosrun gazebo_ros spawn_model -file custom_bot.urdf -urdf -model custom_bot` | the same with `workbench run gazebo_ros spawn_model ...` |
| `rostopic pub /cmd_vel geometry_msgs/Twist ...`, `rostopic echo /odom` | `workbench topic pub` / `echo` |
| RViz, Add → LaserScan / PointCloud2 | `RViz(displays=["LaserScan", "PointCloud2"])` |
| `rosbag record /scan /odom /tf` | `workbench bag record /scan /odom /tf` |

Here everything runs **inside the notebook**: one process, an in-process bus, and the
simulator stepped cell by cell as fast as it can (`server.run(until=...)`), so every number
below is the same on every run. The files it writes (the plan, the world, the RViz snapshot,
the bag) go to the output folder printed by the first cell, not next to the notebook.
""")
code("""
import math
import os
import time

import matplotlib.pyplot as plt
import numpy as np

from workbench.paths import mapping_dir, notebook_output, urdf_dir

SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"
OUT = notebook_output("07_sensors_worlds")
print("files go to", OUT)
np.random.seed(0)
DRIVE_SECONDS = 2.0 if SHORT else 4.0  # simulated time spent driving
IMAGE = (80, 60) if SHORT else (320, 240)  # the depth camera's width and height, pixels
""")

md("""
## 1. Experiment 7.1: build a world in the building editor

The building editor draws walls on a grid, cuts doors and windows into them and saves the
building as a model in a world. A workbench plan is the same drawing written as text: two
rooms side by side (5 m × 3 m in all, walls 1 m high and 10 cm thick), a door in the wall
between them and a window in the far wall. The laser of `custom_bot` is 16.5 cm above
the floor: it passes through the door but not through the window, whose sill is at 40 cm.
""")
code('''
import yaml

from workbench.sim.building import load_plan, plan_from_dict, plan_from_image

PLAN = """
name: two_rooms
description: Two rooms, a door between them and a window in the east wall.
height: 1.0
thickness: 0.1
walls:
  - name: outline            # a closed chain of walls; 'at' runs along the whole chain
    points: [[-2, -1.5], [3, -1.5], [3, 1.5], [-2, 1.5]]
    closed: true
    windows: [{name: window, at: 6.5, width: 1.0, height: 0.4, sill: 0.4}]
  - name: partition
    start: [1.5, -1.5]
    end: [1.5, 1.5]
    doors: [{name: door, at: 1.5, width: 0.8, height: 0.9}]
"""
plan = plan_from_dict(yaml.safe_load(PLAN))  # checked: a wrong plan names its element
print(plan.summary())
plan_file = OUT / "two_rooms.yaml"
plan_file.write_text(PLAN)
same = load_plan(plan_file).pieces() == plan.pieces()
print("read back from", plan_file.name, "- the same walls:", same)
world_file = plan.save(OUT / "two_rooms.world")[0]
print("saved", world_file)


def draw_plan(ax, plan, title):
    """The building seen from above: every wall piece as a rectangle."""
    for piece in plan.pieces():
        x, y, _, yaw = piece.pose
        sx, sy = piece.size[0], piece.size[1]
        corners = np.array([[-sx, -sy], [sx, -sy], [sx, sy], [-sx, sy], [-sx, -sy]]) / 2
        c, s = math.cos(yaw), math.sin(yaw)
        xs = x + c * corners[:, 0] - s * corners[:, 1]
        ax.fill(xs, y + s * corners[:, 0] + c * corners[:, 1], "0.4")
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
''')

md("""
The building editor can also **import a floor plan**: a picture of the walls, traced at a
given resolution. A map_server map (a PGM and its YAML) carries its own resolution and
origin, so `plan_from_image` needs nothing else; every dark pixel becomes part of a wall.
""")
code("""
traced = plan_from_image(mapping_dir() / "demo_rooms.yaml", height=1.0)
print(traced.summary())
traced.save(OUT / "demo_rooms.world")
fig, axes = plt.subplots(1, 2, figsize=(11, 4))
draw_plan(axes[0], plan, "two_rooms.yaml (written)")
draw_plan(axes[1], traced, "demo_rooms.pgm (imported)")
plt.show()
""")

md("""
## 2. Start the simulator with that world and spawn `custom_bot`

`build_server` loads the world file as `gzserver` does; the Gazebo ROS API answers the
`/gazebo/...` services on the bus; `fast=True` (`workbench sim --fast`) steps as fast as it
can instead of at real time. `spawn_model -z 0.1` (the wheels start just above the floor) sends `urdf/custom_bot.urdf` to
`/gazebo/spawn_urdf_model` with its own namespace `/` (so the drive listens on `/cmd_vel`),
then, for `-J front_caster_of_wheel_joint 3.1416`, turns the caster behind its pivot with
`/gazebo/set_model_configuration`. The URDF's `<gazebo>` blocks start three plugins: the
differential drive, the joint state publisher and the laser. A robot state publisher puts the
robot's fixed frames (`base_link → laser_scanner`) on tf, as `robot_state_publisher` does.
""")
code("""
from workbench.bus import Bus, Node
from workbench.model import load_robot
from workbench.msgs import gazebo_msgs as gm
from workbench.robot_state import RobotStatePublisher
from workbench.sim.gazebo_ros import GazeboRosApi
from workbench.sim.gzserver import ServerOptions, build_server

bus = Bus()
world, server, _ = build_server(ServerOptions(world=str(world_file), fast=True, view=False), bus)
api = GazeboRosApi(server, Node("gazebo", bus=bus))
me = Node("student", bus=bus)
print("models:", world.model_names())

urdf_text = (urdf_dir() / "custom_bot.urdf").read_text()
request = gm.SpawnModel.Request(model_name="custom_bot", model_xml=urdf_text, robot_namespace="/")
request.initial_pose.position.x, request.initial_pose.position.z = -1.0, 0.1
request.initial_pose.orientation.w = 1.0
print(me.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel).call(request).status_message)
configure = gm.SetModelConfiguration.Request(
    model_name="custom_bot",
    joint_names=["front_caster_of_wheel_joint"],
    joint_positions=[math.pi],
)
set_configuration = me.create_client("/gazebo/set_model_configuration", gm.SetModelConfiguration)
print(set_configuration.call(configure).status_message)
me.set_param("/robot_description", urdf_text)
robot = load_robot(urdf_dir() / "custom_bot.urdf")
rsp = RobotStatePublisher(robot, Node("robot_state_publisher", bus=bus))
for label in server.plugin_labels():
    print("plugin:", label)
""")

md("""
## 3. Drive it: `/cmd_vel` in, `/odom` out

A recording of `/scan`, `/odom` and `/tf` starts first (section 6 reads it back). Then a
`geometry_msgs/Twist` on `/cmd_vel` asks for 0.25 m/s forward and a slight turn; the drive
plugin turns the wheels and publishes `nav_msgs/Odometry` on `/odom` 100 times a simulated
second (with `odom → base_link` on tf).
""")
code("""
from workbench.bag.record import Recorder
from workbench.msgs.geometry_msgs import Twist
from workbench.msgs.nav_msgs import Odometry

odometry = []
me.create_subscription("/odom", Odometry, odometry.append, inline=True)
cmd_vel = me.create_publisher("/cmd_vel", Twist)
recorder = Recorder(Node("record", bus=bus), OUT / "sensors.bag", topics=["/scan", "/odom", "/tf"])
server.run(until=world.time + 0.1)  # the plugins publish once, so the recorder knows the topics
print("recording:", recorder.poll_topics())


drive_plugin = next(p for p in server.plugins if type(p).__name__ == "GazeboRosDiffDrive")


def drive(forward, turn, seconds):
    twist = Twist()
    twist.linear.x, twist.angular.z = forward, turn
    cmd_vel.publish(twist)
    deadline = time.monotonic() + 5.0
    while drive_plugin.command != (forward, turn) and time.monotonic() < deadline:
        time.sleep(0.01)  # the drive's subscription runs on the bus's threads: wait for it
    server.run(until=world.time + seconds)


def show(odom):
    p, v = odom.pose.pose.position, odom.twist.twist
    yaw = 2 * math.atan2(odom.pose.pose.orientation.z, odom.pose.pose.orientation.w)
    print(
        f"t = {odom.header.stamp.to_sec():.2f} s  odom: x = {p.x:.3f} m, y = {p.y:.3f} m, "
        f"yaw = {math.degrees(yaw):.1f} deg, v = {v.linear.x:.3f} m/s, w = {v.angular.z:.3f} rad/s"
    )


show(odometry[0])
drive(0.25, 0.05, DRIVE_SECONDS)
show(odometry[-1])
drive(0.0, 0.0, 0.5)  # stop and settle
show(odometry[-1])
start, end = odometry[0].pose.pose.position, odometry[-1].pose.pose.position
print(f"drove {math.hypot(end.x - start.x, end.y - start.y):.2f} m; {len(odometry)} /odom messages")
xs = [m.pose.pose.position.x for m in odometry]
ys = [m.pose.pose.position.y for m in odometry]
plt.figure(figsize=(4, 3))
plt.plot(xs, ys)
plt.axis("equal")
plt.title("/odom")
plt.xlabel("x (m)")
plt.ylabel("y (m)")
plt.show()
""")

md("""
## 4. Experiment 7.2: the laser scan, and blocks in front of the robot

The laser (`gpu_ray`, 720 beams over ±90.4°, 0.1–30 m, 40 Hz) publishes
`sensor_msgs/LaserScan` on `/scan`; `sensor_plugin(server, "laser")` is the plugin itself,
whose `latest_message` is the last scan. Plotted in the laser's frame (x ahead, y to the
left) the scan is the outline of the room, with a gap where the door is and the far room
seen through it.

Then, as in the lab, a block goes in front of the robot: a 30 cm cube spawned 1 m ahead of
the laser. The next scan sees its face 1 m − 15 cm = 0.85 m away.
""")
code('''
from workbench.sim.sensors import sensor_plugin

laser = sensor_plugin(server, "laser")


def scan_points(scan):
    ranges = np.asarray(scan.ranges, dtype=float)
    angles = scan.angle_min + scan.angle_increment * np.arange(len(ranges))
    return angles, ranges


def ahead(scan, degrees=3.0):
    """The shortest reading within ``degrees`` of straight ahead."""
    angles, ranges = scan_points(scan)
    return float(np.min(ranges[np.abs(angles) <= math.radians(degrees)]))


before = laser.latest_message
angles, ranges = scan_points(before)
low, high = math.degrees(before.angle_min), math.degrees(before.angle_max)
print(f"beams: {len(ranges)}, from {low:.1f} to {high:.1f} deg")
print(f"straight ahead before: {ahead(before):.3f} m")

X_WS, _ = laser.sensor_pose()  # the laser's frame in the world now
heading = X_WS.rotation().matrix()[:, 0]
centre = X_WS.translation() + 1.0 * heading
BLOCK = """<robot name="block"><link name="block">
  <inertial><mass value="2"/><inertia ixx="0.03" iyy="0.03" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial>
  <visual><geometry><box size="0.3 0.3 0.3"/></geometry></visual>
  <collision><geometry><box size="0.3 0.3 0.3"/></geometry></collision>
</link></robot>"""
block = gm.SpawnModel.Request(model_name="block", model_xml=BLOCK)
block.initial_pose.position.x, block.initial_pose.position.y = centre[0], centre[1]
block.initial_pose.position.z = 0.15
yaw_now = math.atan2(heading[1], heading[0])
block.initial_pose.orientation.z = math.sin(yaw_now / 2)
block.initial_pose.orientation.w = math.cos(yaw_now / 2)
print(me.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel).call(block).status_message)
server.run(until=world.time + 0.1)
after = laser.latest_message
print(f"straight ahead after: {ahead(after):.3f} m (the block's face: {1.0 - 0.15:.3f} m)")

fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
for ax, scan, title in ((axes[0], before, "before"), (axes[1], after, "a block 1 m ahead")):
    a, r = scan_points(scan)
    seen = np.isfinite(r)
    ax.scatter(r[seen] * np.cos(a[seen]), r[seen] * np.sin(a[seen]), s=2)
    ax.plot(0, 0, "r^")
    ax.set_aspect("equal")
    ax.set_title(f"/scan, {title}")
    ax.set_xlabel("x ahead (m)")
    ax.set_ylabel("y left (m)")
plt.show()
''')

md("""
## 5. A depth camera and its point cloud in RViz

A depth camera (an SDF `<sensor type="depth">`, Gazebo's Kinect) 6 cm in front of the laser
renders the world from the robot's pose: each pixel is the distance along the optical axis.
`Camera.points` turns the depth image into points in the camera's optical frame (x right,
y down, z forward), which go out as a `sensor_msgs/PointCloud2`, with that frame on tf.

RViz, in the browser, shows the robot, tf, the laser scan (red) and the cloud, in the
`odom` frame; `rviz.save_html` writes a snapshot you can open without the notebook.
""")
code('''
from workbench.msgs.geometry_msgs import TransformStamped
from workbench.msgs.sensor_msgs import PointCloud2
from workbench.sim.sensors import Camera, parse_sensor
from workbench.sim.sensors.messages import point_cloud
from workbench.tf import StaticTransformBroadcaster

width, height = IMAGE
DEPTH = f"""<sensor type="depth" name="depth_camera">
  <pose>0.06 0 0 0 0 0</pose>
  <camera><horizontal_fov>1.2</horizontal_fov>
    <image><width>{width}</width><height>{height}</height><format>R8G8B8</format></image>
    <clip><near>0.05</near><far>10</far></clip></camera>
</sensor>"""
camera = Camera(parse_sensor(DEPTH, model="custom_bot", link="laser_scanner"))
X_WC = laser.sensor_pose()[0].multiply(camera.spec.pose())
frame = camera.capture(world, X_WC)
depth = frame.depth
middle = depth[height // 2, width // 2]
print(f"depth image {depth.shape[1]} x {depth.shape[0]}, centre pixel {middle:.3f} m")

fig, axes = plt.subplots(1, 2, figsize=(11, 3.5))
axes[0].imshow(frame.color)
axes[0].set_title("colour")
shown = axes[1].imshow(np.where(np.isfinite(depth), depth, np.nan), cmap="viridis")
axes[1].set_title("depth (m)")
fig.colorbar(shown, ax=axes[1])
plt.show()

# the optical frame on tf: 6 cm ahead of the laser, rotated rpy(-pi/2, 0, -pi/2)
optical = TransformStamped()
optical.header.frame_id, optical.child_frame_id = "laser_scanner", "depth_optical_frame"
optical.transform.translation.x = 0.06
optical.transform.rotation.x, optical.transform.rotation.y = -0.5, 0.5
optical.transform.rotation.z, optical.transform.rotation.w = -0.5, 0.5
StaticTransformBroadcaster(me).send_transform(optical)
cloud_publisher = me.create_publisher("/depth_camera/points", PointCloud2, latch=True)
cloud = point_cloud(camera.points(depth), frame.color, "depth_optical_frame", world.time)
print(f"point cloud: {cloud.width * cloud.height} points")
''')
code("""
from workbench.rviz import RViz

rviz = RViz(bus, fixed_frame="odom", displays=["Grid", "TF", "RobotModel"])
scan_display = rviz.add_display("LaserScan", topic="/scan")
cloud_display = rviz.add_display("PointCloud2", topic="/depth_camera/points", size=0.02)
server.run(until=world.time + 0.1)  # fresh scans and tf for the new subscribers
cloud.header.stamp = laser.latest_message.header.stamp
cloud_publisher.publish(cloud)
rviz.spin(0.5 if SHORT else 2.0)
for name, status in rviz.statuses().items():
    print(f"{name:12s} {status}")
print(f"drawn: {scan_display.drawn} scans, {cloud_display.drawn} point cloud(s)")
print("snapshot:", rviz.save_html(OUT / "sensors_rviz.html"))
rviz
""")

md("""
## 6. The recording: `rosbag record /scan /odom /tf`, read back

`Recorder` wrote everything the three topics carried since section 3 into a ROS 1 bag
(v2.0), `sensors.bag` in the output folder; ROS, Foxglove and `rosbags` open it.
`read_messages` gives the messages back, here counted per topic.
""")
code("""
from collections import Counter

from workbench.bag import format_info, read_messages, summarize

bag_path = recorder.close()
print(format_info(summarize(bag_path)))
counts = Counter(message.topic for message in read_messages(bag_path))
for topic in ("/scan", "/odom", "/tf"):
    print(f"bag: {topic} {counts[topic]} messages")
last_scan = [m.msg for m in read_messages(bag_path, ["/scan"])][-1]
print(f"last recorded scan: {len(last_scan.ranges)} beams, straight ahead {ahead(last_scan):.3f} m")
""")
code("""
rviz.close()
api.close()
server.stop()
bus.shutdown()
""")

nb = new_notebook(cells=cells)
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbformat.write(nb, Path(__file__).resolve().parents[1] / "07_sensors_worlds.ipynb")
