"""Copies of messages whose class is a subclass adding no fields (rospy.Time, rospy.Duration)."""

from __future__ import annotations

import copy
import pickle

from workbench.compat import rospy
from workbench.msgs.std_msgs import Header


def test_copy_deepcopy_and_pickle_of_rospy_times_keep_their_value():
    header = Header(frame_id="base_link")
    header.stamp = rospy.Time(5, 6)
    for clone in (copy.deepcopy(header), pickle.loads(pickle.dumps(header))):
        assert (clone.stamp.secs, clone.stamp.nsecs) == (5, 6) and clone.frame_id == "base_link"
    assert copy.copy(rospy.Duration(3, 4)).to_nsec() == 3_000_000_004
