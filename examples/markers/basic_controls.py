#!/usr/bin/env python
"""Experiment 3, "Interactive Markers: Basic Controls": every kind of control on a grey box.

    workbench run using_markers basic_controls.py
    workbench rviz -f base_link

Markers, from left to right along y: 6-DOF (fixed and inheriting
orientation), 3D move/rotate/move-rotate, random DOF, view facing,
quadrocopter, chess piece (snaps to a 1 m grid on release), pan/tilt, a
context menu, a button, a moving marker (its frame turns) and a mesh.
The feedback of every control is logged, as in the tutorial.
"""

import math
import random

from workbench.compat import rospy
from workbench.compat.interactive_markers.interactive_marker_server import InteractiveMarkerServer
from workbench.compat.interactive_markers.menu_handler import MenuHandler
from workbench.compat.tf import TransformBroadcaster
from workbench.msgs.visualization_msgs import (
    InteractiveMarker,
    InteractiveMarkerControl,
    InteractiveMarkerFeedback,
    Marker,
)

server = None
menu_handler = MenuHandler()
counter = 0
br = None


def process_feedback(feedback):
    s = f"Feedback from marker '{feedback.marker_name}' / control '{feedback.control_name}'"
    if feedback.event_type == InteractiveMarkerFeedback.BUTTON_CLICK:
        rospy.loginfo(s + ": button click.")
    elif feedback.event_type == InteractiveMarkerFeedback.MENU_SELECT:
        rospy.loginfo(s + f": menu item {feedback.menu_entry_id} clicked.")
    elif feedback.event_type == InteractiveMarkerFeedback.POSE_UPDATE:
        p = feedback.pose.position
        rospy.loginfo(s + f": pose changed to {p.x:.2f}, {p.y:.2f}, {p.z:.2f}")
    elif feedback.event_type == InteractiveMarkerFeedback.MOUSE_DOWN:
        rospy.loginfo(s + ": mouse down.")
    elif feedback.event_type == InteractiveMarkerFeedback.MOUSE_UP:
        rospy.loginfo(s + ": mouse up.")
    server.applyChanges()


def align_marker(feedback):
    """The chess piece: snap to the grid when released."""
    pose = feedback.pose
    pose.position.x = round(pose.position.x - 0.5) + 0.5
    pose.position.y = round(pose.position.y - 0.5) + 0.5
    rospy.loginfo(
        f"{feedback.marker_name}: aligning to {pose.position.x:.1f}, {pose.position.y:.1f}"
    )
    server.setPose(feedback.marker_name, pose)
    server.applyChanges()


def make_box(msg):
    marker = Marker()
    marker.type = Marker.CUBE
    marker.scale.x = marker.scale.y = marker.scale.z = msg.scale * 0.45
    marker.color.r = marker.color.g = marker.color.b = 0.5
    marker.color.a = 1.0
    marker.pose.orientation.w = 1.0
    return marker


def make_box_control(msg):
    control = InteractiveMarkerControl()
    control.always_visible = True
    control.markers.append(make_box(msg))
    msg.controls.append(control)
    return control


def axis_control(name, mode, x, y, z, fixed=False):
    control = InteractiveMarkerControl()
    control.orientation.w, control.orientation.x = 1.0, x
    control.orientation.y, control.orientation.z = y, z
    norm = math.sqrt(1.0 + x * x + y * y + z * z)
    control.orientation.w /= norm
    control.orientation.x, control.orientation.y, control.orientation.z = (
        x / norm,
        y / norm,
        z / norm,
    )
    control.name = name
    control.interaction_mode = mode
    if fixed:
        control.orientation_mode = InteractiveMarkerControl.FIXED
    return control


def new_marker(name, description, y, frame="base_link"):
    marker = InteractiveMarker()
    marker.header.frame_id = frame
    marker.pose.position.y = y
    marker.pose.orientation.w = 1.0
    marker.scale = 1.0
    marker.name = name
    marker.description = description
    make_box_control(marker)
    return marker


def make_6dof(fixed, mode, y, show_6dof=True):
    names = {
        InteractiveMarkerControl.NONE: "simple_6dof",
        InteractiveMarkerControl.MOVE_3D: "simple_6dof_MOVE_3D",
        InteractiveMarkerControl.ROTATE_3D: "simple_6dof_ROTATE_3D",
        InteractiveMarkerControl.MOVE_ROTATE_3D: "simple_6dof_MOVE_ROTATE_3D",
    }
    name = names[mode] + ("_fixed" if fixed else "")
    marker = new_marker(name, "Simple 6-DOF Control", y)
    marker.controls[0].interaction_mode = mode
    if show_6dof:
        for axis, (x, y_, z) in (("x", (1, 0, 0)), ("z", (0, 1, 0)), ("y", (0, 0, 1))):
            marker.controls.append(
                axis_control(
                    f"rotate_{axis}", InteractiveMarkerControl.ROTATE_AXIS, x, y_, z, fixed
                )
            )
            marker.controls.append(
                axis_control(f"move_{axis}", InteractiveMarkerControl.MOVE_AXIS, x, y_, z, fixed)
            )
    server.insert(marker, process_feedback)
    menu_handler.apply(server, marker.name)


def make_random_dof(y):
    marker = new_marker("6dof_random_axes", "6-DOF\n(Arbitrary Axes)", y)
    rng = random.Random(1)
    for i in range(3):
        x, y_, z = (rng.uniform(-1, 1) for _ in range(3))
        marker.controls.append(
            axis_control(f"rotate_{i}", InteractiveMarkerControl.ROTATE_AXIS, x, y_, z)
        )
        marker.controls.append(
            axis_control(f"move_{i}", InteractiveMarkerControl.MOVE_AXIS, x, y_, z)
        )
    server.insert(marker, process_feedback)


def make_view_facing(y):
    marker = new_marker("view_facing", "View Facing 6-DOF", y)
    control = InteractiveMarkerControl()
    control.orientation_mode = InteractiveMarkerControl.VIEW_FACING
    control.interaction_mode = InteractiveMarkerControl.MOVE_ROTATE_3D
    control.name = "move_rotate_3d"
    marker.controls.append(control)
    server.insert(marker, process_feedback)


def make_quadrocopter(y):
    marker = new_marker("quadrocopter", "Quadrocopter", y)
    marker.controls.append(
        axis_control("move_rotate", InteractiveMarkerControl.MOVE_ROTATE, 0, 1, 0)
    )
    marker.controls.append(axis_control("move_z", InteractiveMarkerControl.MOVE_AXIS, 0, 1, 0))
    server.insert(marker, process_feedback)


def make_chess_piece(y):
    marker = new_marker("chess_piece", "Chess Piece\n(2D Move + Alignment)", y)
    marker.controls.append(axis_control("move_plane", InteractiveMarkerControl.MOVE_PLANE, 0, 1, 0))
    server.insert(marker, process_feedback)
    server.setCallback(marker.name, align_marker, InteractiveMarkerFeedback.POSE_UPDATE)


def make_pan_tilt(y):
    marker = new_marker("pan_tilt", "Pan / Tilt", y)
    marker.controls.append(
        axis_control("pan", InteractiveMarkerControl.ROTATE_AXIS, 0, 1, 0, fixed=True)
    )
    marker.controls.append(axis_control("tilt", InteractiveMarkerControl.ROTATE_AXIS, 0, 0, 1))
    server.insert(marker, process_feedback)


def make_menu(y):
    marker = new_marker("context_menu", "Context Menu\n(Right Click)", y)
    marker.controls[0].interaction_mode = InteractiveMarkerControl.MENU
    marker.controls[0].name = "menu_only_control"
    server.insert(marker, process_feedback)
    menu_handler.apply(server, marker.name)


def make_button(y):
    marker = new_marker("button", "Button\n(Left Click)", y)
    marker.controls[0].interaction_mode = InteractiveMarkerControl.BUTTON
    marker.controls[0].name = "button_control"
    server.insert(marker, process_feedback)


def make_moving(y):
    marker = new_marker("moving", "Marker Attached to a\nMoving Frame", y, frame="moving_frame")
    marker.controls.append(axis_control("rotate_x", InteractiveMarkerControl.ROTATE_AXIS, 1, 0, 0))
    marker.controls[0].interaction_mode = InteractiveMarkerControl.MOVE_PLANE
    server.insert(marker, process_feedback)


def make_mesh(y):
    marker = InteractiveMarker()
    marker.header.frame_id = "base_link"
    marker.pose.position.y = y
    marker.pose.orientation.w = 1.0
    marker.scale = 1.0
    marker.name = "mesh"
    marker.description = "Mesh"
    mesh = Marker(
        type=Marker.MESH_RESOURCE, mesh_resource="package://workbench_urdf/meshes/l_finger.obj"
    )
    mesh.scale.x = mesh.scale.y = mesh.scale.z = 10.0
    mesh.color.r, mesh.color.g, mesh.color.b, mesh.color.a = 0.2, 0.6, 0.9, 1.0
    mesh.pose.orientation.w = 1.0
    control = InteractiveMarkerControl(
        interaction_mode=InteractiveMarkerControl.BUTTON, always_visible=True
    )
    control.name = "mesh_button"
    control.markers.append(mesh)
    marker.controls.append(control)
    server.insert(marker, process_feedback)


def frame_callback(event):
    global counter
    counter += 1
    angle = counter / 140.0
    br.sendTransform(
        (0, 0, math.sin(counter / 140.0) * 2.0),
        (0, 0, 0, 1),
        rospy.Time.now(),
        "moving_frame",
        "base_link",
    )
    del angle


def main():
    global server, br
    rospy.init_node("basic_controls")
    br = TransformBroadcaster()
    rospy.Timer(rospy.Duration(0.01), frame_callback)
    server = InteractiveMarkerServer("basic_controls")

    menu_handler.insert("First Entry", callback=process_feedback)
    menu_handler.insert("Second Entry", callback=process_feedback)
    sub_menu = menu_handler.insert("Submenu")
    menu_handler.insert("First Entry", parent=sub_menu, callback=process_feedback)
    menu_handler.insert("Second Entry", parent=sub_menu, callback=process_feedback)

    make_6dof(False, InteractiveMarkerControl.NONE, -9.0, True)
    make_6dof(True, InteractiveMarkerControl.NONE, -6.0, True)
    make_6dof(False, InteractiveMarkerControl.MOVE_3D, -3.0, False)
    make_6dof(False, InteractiveMarkerControl.ROTATE_3D, 0.0, False)
    make_6dof(False, InteractiveMarkerControl.MOVE_ROTATE_3D, 3.0, False)
    make_random_dof(6.0)
    make_view_facing(9.0)
    make_quadrocopter(12.0)
    make_chess_piece(15.0)
    make_pan_tilt(18.0)
    make_menu(21.0)
    make_button(24.0)
    make_moving(27.0)
    make_mesh(30.0)
    server.applyChanges()
    rospy.spin()


if __name__ == "__main__":
    main()
