"""The ``move_base move_base`` node as a process: a client in another process gets its goal
ABORTED (no robot pose: "Unable to get starting pose of robot, unable to create global
plan"), and SIGINT stops the node cleanly."""

from __future__ import annotations

import signal
import textwrap

import pytest
from process_helpers import Processes, private_core

CLIENT = textwrap.dedent(
    """
    from workbench.compat import actionlib, rospy
    from workbench.msgs.move_base_msgs import MoveBaseAction, MoveBaseGoal

    rospy.init_node("send_goal")
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    print("server", client.wait_for_server(rospy.Duration(30)), flush=True)
    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = "map"
    goal.target_pose.pose.position.x = 1.0
    goal.target_pose.pose.orientation.w = 1.0
    client.send_goal(goal)
    print("done", client.wait_for_result(rospy.Duration(30)), flush=True)
    print("state", client.get_state(), client.get_goal_status_text(), flush=True)
    """
)


@pytest.mark.multiprocess
def test_goal_from_another_process_and_clean_stop(tmp_path) -> None:
    with private_core(tmp_path) as uri:
        procs = Processes(uri, tmp_path)
        try:
            node = procs.start(
                "-m", "workbench", "run", "move_base", "move_base",
                "_planner_patience:=0.5", "_recovery_behavior_enabled:=false", name="move_base",
            )  # fmt: skip
            procs.wait_output(node, "Sim period is set to 0.05")
            client = procs.start("-c", CLIENT, name="client")
            assert client.wait(60) == 0, procs.output(client)
            out = procs.output(client)
            assert "server True" in out and "done True" in out
            assert (
                "state 4 Failed to find a valid plan. Even after executing recovery behaviors."
                in out
            )
            assert (
                "Unable to get starting pose of robot, unable to create global plan"
                in procs.output(node)
            )
            node.send_signal(signal.SIGINT)
            assert node.wait(15) == 130
            assert "Traceback" not in procs.output(node)
        finally:
            procs.stop_all()
