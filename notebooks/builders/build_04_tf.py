"""Builds notebooks/04_tf.ipynb (run: python notebooks/builders/build_04_tf.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = []


def md(text: str) -> None:
    cells.append(new_markdown_cell(text.strip()))


def code(text: str) -> None:
    cells.append(new_code_cell(text.strip()))


md("""
# Experiment 4 — tf: frames over time

The lab's turtle demo in one process, stepped on simulated time so every run gives the same
result: two turtle broadcasters (`world → turtle1`, `world → turtle2`), a listener that steers
turtle2, a fixed and a moving `carrot1` frame, and time travel. Then Additional Experiment 2
(`base_link → base_laser`) and the robot state publisher.

The lab's own scripts (`examples/tf/*.py`) run the same demo across processes with
`workbench launch examples/tf/start_demo.launch`.

The files this notebook writes (the frame tree, the plots, a snapshot) go to the output
folder printed by the first cell, not next to the notebook.
""")
code("""
import math
import os

from workbench.paths import notebook_output
from workbench.tf import Buffer, TransformListener
from workbench.turtlesim.tf_demo import TurtleTfDemo

SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"
SECONDS = 4.0 if SHORT else 12.0  # simulated seconds per step of the lab
OUT = notebook_output("04_tf")
print("files go to", OUT)
""")
md("""
## 1. Broadcast the turtles, listen, follow

`TurtleTfDemo` starts turtlesim, a broadcaster per turtle (the manual's `turtle_tf_broadcaster.py`),
and a listener that every 0.1 s looks up turtle1 in turtle2's frame and drives turtle2 with
`angular = 4·atan2(y, x)`, `linear = 0.5·√(x² + y²)`. turtle1 drives a circle (the teleop).
""")
code("""
demo = TurtleTfDemo(turtle1_cmd=(1.0, 0.5))
follow = demo.run(SECONDS, follow="turtle1")
(x1, y1), (x2, y2) = demo.pose("turtle1")[:2], demo.pose("turtle2")[:2]
print(f"turtle1 at ({x1:.2f}, {y1:.2f}), turtle2 at ({x2:.2f}, {y2:.2f})")
""")
md("""
## 2. tf tools: `tf_echo` and the frame tree

`workbench tf echo world turtle1` prints the same block as `rosrun tf tf_echo world turtle1`;
`workbench tf frames` draws what `rqt_tf_tree` / `view_frames` show.
""")
code("""
from workbench.cli.tf import format_echo

print(format_echo(demo.buffer.lookup("world", "turtle1", 0)))
print(format_echo(demo.buffer.lookup("turtle1", "turtle2", 0)))
print(demo.buffer.all_frames_as_yaml())
""")
code("""
from workbench.optional import find_program
from workbench.tf.frames import frames_dot, write_frames

dot_source = frames_dot(demo.buffer.frames_info(), recorded_at=demo.now())
if find_program("dot"):
    from IPython.display import SVG, display

    display(SVG(filename=str(write_frames(dot_source, OUT / "frames.svg"))))
else:
    print(dot_source)
""")
md("""
## 3. Adding a frame: a fixed carrot, then a moving one

`carrot1` is 2 m to the left of turtle1 (`fixed_tf_broadcaster.py`); the listener now follows
`carrot1`. Then the carrot circles turtle1 (`dynamic_tf_broadcaster.py`).
""")
code("""
demo.add_carrot(moving=False)
carrot = demo.run(SECONDS, follow="carrot1")
print(
    "carrot1 in world:",
    [round(v, 2) for v in demo.buffer.lookup("world", "carrot1", 0).translation],
)
print("turtle2:         ", [round(v, 2) for v in demo.pose("turtle2")[:2]])

demo.add_carrot(moving=True)
moving = demo.run(SECONDS, follow="carrot1")
st = demo.buffer.lookup("turtle1", "carrot1", 0)
x, y = st.translation[:2]
print(f"moving carrot1 in turtle1: ({x:.2f}, {y:.2f}), radius {math.hypot(x, y):.2f}")
""")
md("""
## 4. Wait for transform and time travel

The manual asks for turtle1 *5 seconds ago* relative to turtle2 *5 seconds ago*
(`lookupTransform("/turtle2", "/turtle1", now - 5 s)`). What it means is turtle1 5 s ago relative
to turtle2 **now**: `lookupTransformFull("/turtle2", now, "/turtle1", now - 5 s, "/world")`,
going through the fixed frame `world`.
""")
code("""
from workbench.tf import ExtrapolationException

try:
    demo.buffer.lookup("turtle2", "turtle1", demo.now() - 30.0)
except ExtrapolationException as error:
    print("30 s ago is older than the 10 s cache:\\n ", error)

travel = demo.run(SECONDS, follow="turtle1", delay=5.0, fixed_frame="world")
rows = travel[-1]
print(f"turtle2 at ({rows[3]:.2f}, {rows[4]:.2f}); turtle1 now at ({rows[1]:.2f}, {rows[2]:.2f})")
""")
code("""
import matplotlib.pyplot as plt

fig, axes = plt.subplots(1, 3, figsize=(12, 4))
for ax, rows, title in zip(
    axes,
    (follow, carrot, travel),
    ("follow turtle1", "follow carrot1", "turtle1 5 s ago"),
    strict=True,
):
    ax.plot(rows[:, 1], rows[:, 2], label="turtle1")
    ax.plot(rows[:, 3], rows[:, 4], label="turtle2")
    ax.set_title(title)
    ax.set_aspect("equal")
    ax.set_xlim(0, 11.1)
    ax.set_ylim(0, 11.1)
axes[0].legend()
fig.savefig(OUT / "turtles.png", dpi=80)
print("plot:", OUT / "turtles.png")
demo.close()
""")
md("""
## 5. Additional Experiment 2: setting up a robot with tf

The laser is 10 cm forward and 20 cm above the base: `base_link → base_laser` is
(0.1, 0, 0.2). A point seen by the laser is transformed into the base frame.
""")
code("""
from workbench.msgs.geometry_msgs import PointStamped
from workbench.tf.broadcaster import make_transform

buffer = Buffer()
buffer.set_transform(
    make_transform("base_link", "base_laser", (0.1, 0.0, 0.2), (0, 0, 0, 1), 1.0),
    "robot_tf_publisher",
)
laser_point = PointStamped()
laser_point.header.frame_id = "base_laser"
laser_point.point.x, laser_point.point.y, laser_point.point.z = 1.0, 0.2, 0.0
base_point = buffer.transform(laser_point, "base_link")
laser, base = laser_point.point, base_point.point
print(
    f"base_laser: ({laser.x:.2f}, {laser.y:.2f}, {laser.z:.2f}) -----> "
    f"base_link: ({base.x:.2f}, {base.y:.2f}, {base.z:.2f}) "
    f"at time {base_point.header.stamp.to_sec():.2f}"
)
""")
md("""
## 6. The robot state publisher, and frames in the viewer

`joint_state_publisher` → `/joint_states` → `robot_state_publisher` (Drake forward kinematics)
→ `/tf`, `/tf_static` → a listener's buffer → the robot and its frames (triads) in Meshcat,
like RViz's RobotModel and TF displays.
""")
code("""
from workbench.bus import Bus, Node
from workbench.model import load_robot
from workbench.robot_state import JointStatePublisher, RobotModelDisplay, RobotStatePublisher
from workbench.viz import Viewer
from workbench.viz.frames import TfDisplay

bus = Bus(threaded=False)
robot = load_robot("robot_arm")
arm_buffer = Buffer()
TransformListener(arm_buffer, Node("rviz", bus=bus))
rsp = RobotStatePublisher(robot, Node("robot_state_publisher", bus=bus))
jsp = JointStatePublisher(robot, Node("joint_state_publisher", bus=bus), rate=0)
jsp.set_position("shoulder_pitch_joint", 0.6)
jsp.set_position("elbow_pitch_joint", 0.9)
jsp.publish()
while bus.spin_once(0.0):
    pass
print(arm_buffer.all_frames_as_string())

viewer = Viewer.instance()
model = RobotModelDisplay(robot, arm_buffer, viewer)
print("links not placed:", model.update())
frames = TfDisplay(arm_buffer, viewer, fixed_frame="base_link", scale=0.08)
print("frames not placed:", frames.update())
viewer.frame_robot(robot, robot.positions_from(jsp.positions))
print("snapshot:", viewer.save_html(OUT / "robot_tf.html"))
bus.shutdown()
""")

nb = new_notebook(cells=cells)
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbformat.write(nb, Path(__file__).resolve().parents[1] / "04_tf.ipynb")
