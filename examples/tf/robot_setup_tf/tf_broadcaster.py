#!/usr/bin/env python3
# Additional Experiment 2, "Broadcasting a Transform" (robot_setup_tf/src/tf_broadcaster.cpp)
# in Python: base_laser is 10 cm forward and 20 cm above base_link, sent at 100 Hz.
from workbench.compat import rospy
from workbench.compat import tf

if __name__ == "__main__":
    rospy.init_node("robot_tf_publisher")
    r = rospy.Rate(100)
    broadcaster = tf.TransformBroadcaster()
    while not rospy.is_shutdown():
        broadcaster.sendTransform(
            (0.1, 0.0, 0.2), (0.0, 0.0, 0.0, 1.0), rospy.Time.now(), "base_laser", "base_link"
        )
        r.sleep()
