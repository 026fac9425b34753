#!/usr/bin/env python3
# Additional Experiment 2, "Using a Transform" (robot_setup_tf/src/tf_listener.cpp) in
# Python: once a second, transform a point from base_laser into base_link and print
#   base_laser: (1.00, 0.20, 0.00) -----> base_link: (1.10, 0.20, 0.20) at time ...
from workbench.compat import rospy
from workbench.compat import tf
from workbench.msgs import geometry_msgs


def transform_point(listener):
    # a point in the base_laser frame that we'd like to transform to the base_link frame
    laser_point = geometry_msgs.PointStamped()
    laser_point.header.frame_id = "base_laser"
    # the most recent transform available
    laser_point.header.stamp = rospy.Time()
    # just an arbitrary point in space
    laser_point.point.x = 1.0
    laser_point.point.y = 0.2
    laser_point.point.z = 0.0
    try:
        base_point = listener.transformPoint("base_link", laser_point)
        rospy.loginfo(
            "base_laser: (%.2f, %.2f, %.2f) -----> base_link: (%.2f, %.2f, %.2f) at time %.2f",
            laser_point.point.x,
            laser_point.point.y,
            laser_point.point.z,
            base_point.point.x,
            base_point.point.y,
            base_point.point.z,
            base_point.header.stamp.to_sec(),
        )
    except tf.Exception as ex:
        rospy.logerr(
            'Received an exception trying to transform a point from "base_laser" to "base_link": %s',
            ex,
        )


if __name__ == "__main__":
    rospy.init_node("robot_tf_listener")
    listener = tf.TransformListener(cache_time=rospy.Duration(10))
    # transform a point once every second
    rospy.Timer(rospy.Duration(1.0), lambda event: transform_point(listener))
    rospy.spin()
