"""``workbench plan --execute`` moves the robot for the other processes on the bus, as MoveIt's
fake execution does: ``/joint_states`` at wall-clock pace with wall-time stamps, and no
``/clock`` (issue 14, item 18)."""

from __future__ import annotations

import time

from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.msgs.rosgraph_msgs import Clock
from workbench.msgs.sensor_msgs import JointState


def test_execute_publishes_joint_states_in_real_time(procs):
    with Bus.connect(procs.uri) as bus:
        node = Node("watcher", bus=bus)
        states: list[tuple[float, JointState]] = []
        clocks: list[Clock] = []
        node.create_subscription(
            "/joint_states", JointState, lambda m: states.append((time.time(), m))
        )
        node.create_subscription("/clock", Clock, clocks.append)
        plan = procs.start(
            "-m", "workbench", "plan", "robot_arm", "--to", "home", "--seed", "1", "--execute",
            name="plan",
        )  # fmt: skip
        assert plan.wait(120) == 0, procs.output(plan)
        out = procs.output(plan)
        assert "publishing /joint_states on" in out
        assert wait_for(lambda: len(states) > 50), out
        received = [t for t, _ in states]
        stamps = [m.header.stamp.secs + 1e-9 * m.header.stamp.nsecs for _, m in states]
        motion = float(out.split("executed ", 1)[1].split(" s", 1)[0])
        # paced by the wall clock: the messages span about the motion's duration
        assert received[-1] - received[0] > 0.8 * motion
        # stamped with wall time, not simulated time from 0
        assert abs(stamps[-1] - received[-1]) < 5.0
        assert clocks == []
        last = states[-1][1]
        arm = [p for n, p in zip(last.name, last.position, strict=True) if "finger" not in n]
        assert max(abs(v) for v in arm) < 0.01  # home is all zeros for robot_arm
