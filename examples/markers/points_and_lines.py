#!/usr/bin/env python
"""Experiment 3, "Points and Lines": a sine wave as points, a line strip and a line list.

Publishes three markers on ``visualization_marker`` 30 times a second in
``my_frame``: green points and a blue line strip along a moving sine wave, and
red vertical lines (a line list) at every point.

    workbench run using_markers points_and_lines.py
"""

import math

from workbench.compat import rospy
from workbench.msgs.geometry_msgs import Point
from workbench.msgs.visualization_msgs import Marker


def make(marker_id, kind, r, g, b):
    marker = Marker()
    marker.header.frame_id = "my_frame"
    marker.header.stamp = rospy.Time.now()
    marker.ns = "points_and_lines"
    marker.id = marker_id
    marker.type = kind
    marker.action = Marker.ADD
    marker.pose.orientation.w = 1.0
    marker.color.r, marker.color.g, marker.color.b, marker.color.a = r, g, b, 1.0
    return marker


def main():
    rospy.init_node("points_and_lines")
    publisher = rospy.Publisher("visualization_marker", Marker, queue_size=10)
    rate = rospy.Rate(30)
    phase = 0.0
    while not rospy.is_shutdown():
        points = make(0, Marker.POINTS, 0.0, 1.0, 0.0)
        points.scale.x = points.scale.y = 0.2
        strip = make(1, Marker.LINE_STRIP, 0.0, 0.0, 1.0)
        strip.scale.x = 0.1
        lines = make(2, Marker.LINE_LIST, 1.0, 0.0, 0.0)
        lines.scale.x = 0.1
        for i in range(100):
            y = 5 * math.sin(phase + i / 100.0 * 2 * math.pi)
            z = 5 * math.cos(phase + i / 100.0 * 2 * math.pi)
            p = Point(x=i - 50.0, y=y, z=z)
            points.points.append(p)
            strip.points.append(p)
            lines.points.append(p)
            lines.points.append(Point(x=p.x, y=p.y, z=p.z + 1.0))
        for marker in (points, strip, lines):
            publisher.publish(marker)
        rate.sleep()
        phase += 0.04


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
