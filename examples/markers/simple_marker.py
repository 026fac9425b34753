#!/usr/bin/env python
"""Experiment 3, "Writing a Simple Interactive Marker Server": a grey box you can move along x.

    workbench run using_markers simple_marker.py
    workbench rviz -f base_link        # the "my_marker: move_x" slider moves it

Every feedback the viewer sends is printed, as in the tutorial.
"""

from workbench.compat import rospy
from workbench.compat.interactive_markers.interactive_marker_server import InteractiveMarkerServer
from workbench.msgs.visualization_msgs import InteractiveMarker, InteractiveMarkerControl, Marker


def process_feedback(feedback):
    p = feedback.pose.position
    print(f"{feedback.marker_name} is now at {p.x}, {p.y}, {p.z}")


def main():
    rospy.init_node("simple_marker")
    server = InteractiveMarkerServer("simple_marker")

    int_marker = InteractiveMarker()
    int_marker.header.frame_id = "base_link"
    int_marker.header.stamp = rospy.Time.now()
    int_marker.name = "my_marker"
    int_marker.description = "Simple 1-DOF Control"

    box = Marker()
    box.type = Marker.CUBE
    box.scale.x = box.scale.y = box.scale.z = 0.45
    box.color.r = box.color.g = box.color.b = 0.5
    box.color.a = 1.0
    box.pose.orientation.w = 1.0

    box_control = InteractiveMarkerControl()
    box_control.always_visible = True
    box_control.markers.append(box)
    int_marker.controls.append(box_control)

    rotate_control = InteractiveMarkerControl()
    rotate_control.name = "move_x"
    rotate_control.orientation.w = 1.0
    rotate_control.orientation.x = 1.0
    rotate_control.interaction_mode = InteractiveMarkerControl.MOVE_AXIS
    int_marker.controls.append(rotate_control)

    server.insert(int_marker, process_feedback)
    server.applyChanges()
    rospy.spin()


if __name__ == "__main__":
    main()
