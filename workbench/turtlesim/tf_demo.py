"""Experiment 4's turtle demo in one process, stepped by hand on simulated time.

The same pieces as the lab scripts -- a broadcaster per turtle (``world ->
turtleN`` from ``turtleN/pose``), an optional ``carrot1`` frame (fixed or
moving), a listener steering turtle2 with ``angular = 4 atan2(y, x)``,
``linear = 0.5 sqrt(x^2 + y^2)`` at 10 Hz -- written with the library API
on a stepped bus, so a notebook or a test gets the same result every run::

    demo = TurtleTfDemo()
    demo.run(10.0, follow="turtle1")          # turtle2 follows turtle1
    demo.add_carrot(moving=False)             # carrot1 2 m left of turtle1
    demo.run(10.0, follow="carrot1")
    demo.run(10.0, follow="turtle1", delay=5.0, fixed_frame="world")  # time travel
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from workbench.tf.broadcaster import TransformBroadcaster, make_transform
from workbench.tf.buffer import Buffer
from workbench.tf.exceptions import TransformException
from workbench.tf.listener import TransformListener
from workbench.tf.transformations import quaternion_from_euler

#: turtlesim's update period (s); the listener acts every 6 updates (about 10 Hz).
STEP = 0.016
CONTROL_EVERY = 6


class TurtleTfDemo:
    """turtlesim, two turtle broadcasters, a listener and (optionally) a carrot.

    Args:
        start_time: Simulated time of the first step, seconds.
        turtle1_cmd: ``(linear m/s, angular rad/s)`` sent to turtle1 every step
            (the keyboard teleop of the lab); ``(0, 0)`` leaves it standing.
    """

    def __init__(self, start_time: float = 100.0, turtle1_cmd: tuple[float, float] = (1.0, 0.5)):
        from workbench.bus import Bus, Node
        from workbench.msgs.geometry_msgs import Twist
        from workbench.msgs.turtlesim import Pose, Spawn
        from workbench.turtlesim.node import TurtlesimNode

        self.bus = Bus(threaded=False)
        self.bus.clock.use_sim_time(True)
        self._t_ns = round(start_time * 1e9)
        self.bus.clock.set_time(self._t_ns)
        self.sim = TurtlesimNode(Node("sim", bus=self.bus), start_timer=False)
        self.turtle1_cmd = turtle1_cmd
        self._twist = Twist
        self.broadcasters = {}
        for name in ("turtle1", "turtle2"):
            node = Node(f"{name}_tf_broadcaster", bus=self.bus)
            br = TransformBroadcaster(node)
            node.create_subscription(
                f"/{name}/pose", Pose, self._broadcast, callback_args=(br, name)
            )
            self.broadcasters[name] = br
        listener_node = Node("listener", bus=self.bus)
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, listener_node)
        listener_node.create_client("spawn", Spawn).call(
            Spawn.Request(x=4.0, y=2.0, theta=0.0, name="turtle2")
        )
        self.cmd1 = Node("teleop", bus=self.bus).create_publisher("turtle1/cmd_vel", Twist)
        self.cmd2 = listener_node.create_publisher("turtle2/cmd_vel", Twist)
        self.carrot: TransformBroadcaster | None = None
        self.carrot_moving = False
        self.steps = 0
        self.history: list[tuple[float, float, float, float, float]] = []  # t, x1, y1, x2, y2
        self.errors: list[str] = []

    # --- the lab's nodes ---------------------------------------------------------------

    def _broadcast(self, msg: Any, args: tuple[TransformBroadcaster, str]) -> None:
        br, name = args
        q = quaternion_from_euler(0, 0, msg.theta)
        br.send_transform(make_transform("world", name, (msg.x, msg.y, 0.0), q, self.now()))

    def add_carrot(self, moving: bool = False) -> None:
        """Broadcast ``carrot1`` on turtle1: 2 m to its left, or circling it (4a / 4c)."""
        from workbench.bus import Node

        if self.carrot is None:
            self.carrot = TransformBroadcaster(Node("broadcaster_carrot", bus=self.bus))
        self.carrot_moving = moving

    def _send_carrot(self, carrot: TransformBroadcaster) -> None:
        t = self.now()
        if self.carrot_moving:
            a = t * math.pi
            xyz = (2.0 * math.sin(a), 2.0 * math.cos(a), 0.0)
        else:
            xyz = (0.0, 2.0, 0.0)
        carrot.send_transform(make_transform("turtle1", "carrot1", xyz, (0, 0, 0, 1), t))

    def now(self) -> float:
        """Simulated time, seconds."""
        return self._t_ns / 1e9

    def _drain(self) -> None:
        while self.bus.spin_once(0.0):
            pass

    def _control(self, follow: str, delay: float, fixed_frame: str | None) -> None:
        now = self.now()
        try:
            if delay and fixed_frame:
                st = self.buffer.lookup_full("turtle2", now, follow, now - delay, fixed_frame)
            else:
                st = self.buffer.lookup("turtle2", follow, now - delay if delay else 0)
        except TransformException as exc:
            self.errors.append(f"{now:.3f}: {type(exc).__name__}")
            return
        x, y = st.translation[0], st.translation[1]
        cmd = self._twist()
        cmd.linear.x = 0.5 * math.sqrt(x * x + y * y)
        cmd.angular.z = 4 * math.atan2(y, x)
        self.cmd2.publish(cmd)

    def run(
        self,
        seconds: float,
        follow: str = "turtle1",
        delay: float = 0.0,
        fixed_frame: str | None = None,
    ) -> np.ndarray:
        """Simulate ``seconds``; turtle2 steers to ``follow`` (``delay`` s ago, via ``fixed_frame``).

        Returns:
            The recorded ``(t, x1, y1, x2, y2)`` rows of this run.
        """
        start = len(self.history)
        for _ in range(max(1, round(seconds / STEP))):
            self._t_ns += round(STEP * 1e9)
            self.bus.clock.set_time(self._t_ns)
            lin, ang = self.turtle1_cmd
            self.cmd1.publish(self._twist(linear={"x": lin}, angular={"z": ang}))
            self._drain()
            self.sim.step()
            if self.carrot is not None:
                self._send_carrot(self.carrot)
            self._drain()
            if self.steps % CONTROL_EVERY == 0:
                self._control(follow, delay, fixed_frame)
                self._drain()
            self.steps += 1
            p1, p2 = self.pose("turtle1"), self.pose("turtle2")
            self.history.append((self.now(), p1[0], p1[1], p2[0], p2[1]))
        return np.array(self.history[start:])

    def pose(self, name: str) -> tuple[float, float, float]:
        """``(x, y, theta)`` of a turtle in the world (m, rad)."""
        with self.sim.lock:
            p = self.sim.sim.turtle(name).pose
        return p.x, p.y, p.theta

    def close(self) -> None:
        self.bus.shutdown()
