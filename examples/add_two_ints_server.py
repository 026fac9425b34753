#!/usr/bin/env python3
# The manual's add_two_ints_server.py; only the import lines differ.
# ruff: noqa: F841
# fmt: off

from __future__ import print_function

from workbench.msgs.beginner_tutorials import AddTwoInts,AddTwoIntsResponse
from workbench.compat import rospy

def handle_add_two_ints(req):
    print("Returning [%s + %s = %s]"%(req.a, req.b, (req.a + req.b)))
    return AddTwoIntsResponse(req.a + req.b)

def add_two_ints_server():
    rospy.init_node('add_two_ints_server')
    s = rospy.Service('add_two_ints', AddTwoInts, handle_add_two_ints)
    print("Ready to add two ints.")
    rospy.spin()

if __name__ == "__main__":
    add_two_ints_server()
