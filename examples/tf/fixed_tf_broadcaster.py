#!/usr/bin/env python3
# Experiment 4, 4a "How to add a fixed frame": carrot1 two metres to the left of turtle1.
# Only the imports differ from the manual.
from workbench.compat import rospy
from workbench.compat import tf

if __name__ == "__main__":
    rospy.init_node("fixed_tf_broadcaster")
    br = tf.TransformBroadcaster()
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        br.sendTransform(
            (0.0, 2.0, 0.0), (0.0, 0.0, 0.0, 1.0), rospy.Time.now(), "carrot1", "turtle1"
        )
        rate.sleep()
