"""The ROS 1 ``tf`` Python API on workbench: change ``import tf`` to ``from workbench.compat import tf``.

::

    br = tf.TransformBroadcaster()
    br.sendTransform((x, y, 0), tf.transformations.quaternion_from_euler(0, 0, theta),
                     rospy.Time.now(), "turtle1", "world")
    listener = tf.TransformListener()
    (trans, rot) = listener.lookupTransform("/turtle2", "/turtle1", rospy.Time(0))

Frame names may start with ``/`` as in tf (it is stripped). The exceptions are
tf2's: ``tf.Exception`` is the base of ``tf.LookupException``,
``tf.ConnectivityException`` and ``tf.ExtrapolationException`` (and of the
timeout of ``waitForTransform``).
"""

from __future__ import annotations

from workbench.compat.tf import transformations
from workbench.compat.tf.listener import (
    TransformBroadcaster,
    Transformer,
    TransformerROS,
    TransformListener,
)
from workbench.tf.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    LookupException,
    TimeoutException,
)
from workbench.tf.exceptions import TransformException as Exception  # noqa: A001

__all__ = [
    "ConnectivityException",
    "Exception",
    "ExtrapolationException",
    "LookupException",
    "TimeoutException",
    "TransformBroadcaster",
    "TransformListener",
    "Transformer",
    "TransformerROS",
    "transformations",
]
