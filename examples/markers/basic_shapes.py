#!/usr/bin/env python
"""Experiment 3, "Markers: Sending Basic Shapes": a shape that changes every second.

Publishes a ``visualization_msgs/Marker`` on ``visualization_marker`` once a
second, cycling cube -> sphere -> arrow -> cylinder, one metre on each side,
in the frame ``my_frame``. Run it next to ``workbench rviz --fixed-frame my_frame``:

    workbench run using_markers basic_shapes.py

Until a viewer subscribes it warns once a second, as the tutorial does.
"""

from workbench.compat import rospy
from workbench.msgs.visualization_msgs import Marker

SHAPES = [Marker.CUBE, Marker.SPHERE, Marker.ARROW, Marker.CYLINDER]


def main():
    rospy.init_node("basic_shapes")
    publisher = rospy.Publisher("visualization_marker", Marker, queue_size=1)
    rate = rospy.Rate(1)
    index = 0
    while not rospy.is_shutdown():
        marker = Marker()
        marker.header.frame_id = "my_frame"
        marker.header.stamp = rospy.Time.now()
        # ns and id make the marker unique: a later one with the same pair replaces it
        marker.ns = "basic_shapes"
        marker.id = 0
        marker.type = SHAPES[index % len(SHAPES)]
        marker.action = Marker.ADD
        marker.pose.orientation.w = 1.0
        marker.scale.x = marker.scale.y = marker.scale.z = 1.0
        marker.color.g = 1.0
        marker.color.a = 1.0
        marker.lifetime = rospy.Duration()
        while publisher.get_num_connections() < 1 and not rospy.is_shutdown():
            rospy.logwarn_once("Please create a subscriber to the marker")
            rospy.sleep(1)
        publisher.publish(marker)
        index += 1
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
