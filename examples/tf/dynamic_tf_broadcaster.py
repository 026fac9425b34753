#!/usr/bin/env python3
# Experiment 4, 4c "Broadcasting a moving frame": carrot1 circles turtle1.
# Only the imports differ from the manual.
import math

from workbench.compat import rospy
from workbench.compat import tf

if __name__ == "__main__":
    rospy.init_node("dynamic_tf_broadcaster")
    br = tf.TransformBroadcaster()
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        t = rospy.Time.now().to_sec() * math.pi
        br.sendTransform(
            (2.0 * math.sin(t), 2.0 * math.cos(t), 0.0),
            (0.0, 0.0, 0.0, 1.0),
            rospy.Time.now(),
            "carrot1",
            "turtle1",
        )
        rate.sleep()
