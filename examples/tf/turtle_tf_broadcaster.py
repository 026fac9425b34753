#!/usr/bin/env python3
# Experiment 4, "How to broadcast transforms" (learning_tf/nodes/turtle_tf_broadcaster.py).
# Only the imports differ from the manual: roslib.load_manifest is not needed, and
# message packages are modules of workbench.msgs.
from workbench.compat import rospy
from workbench.compat import tf
from workbench.msgs import turtlesim


def handle_turtle_pose(msg, turtlename):
    br = tf.TransformBroadcaster()
    br.sendTransform(
        (msg.x, msg.y, 0),
        tf.transformations.quaternion_from_euler(0, 0, msg.theta),
        rospy.Time.now(),
        turtlename,
        "world",
    )


if __name__ == "__main__":
    rospy.init_node("turtle_tf_broadcaster")
    turtlename = rospy.get_param("~turtle")
    rospy.Subscriber("/%s/pose" % turtlename, turtlesim.msg.Pose, handle_turtle_pose, turtlename)
    rospy.spin()
