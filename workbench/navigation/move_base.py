"""move_base: the navigation executive (``move_base/src/move_base.cpp``, Noetic).

:class:`MoveBase` lives on a host node (``/move_base``) with a tf buffer. It holds the
``global_costmap`` and ``local_costmap`` (:class:`CostmapROS`), the global planner
(``navfn/NavfnROS``), the local planner (``base_local_planner/TrajectoryPlannerROS`` or
``dwa_local_planner/DWAPlannerROS``) and the recovery behaviours, and offers:

* the ``move_base`` action (``move_base_msgs/MoveBaseAction``, a SimpleActionServer: a
  newer goal preempts the current one), with feedback ``base_position`` every cycle;
* ``move_base_simple/goal`` (``geometry_msgs/PoseStamped``), re-sent as an action goal;
* ``~make_plan`` (``nav_msgs/GetPlan``, only while no goal is active, searching outwards
  within the request's tolerance when the exact goal has no plan) and ``~clear_costmaps``
  (``std_srvs/Empty``);
* ``cmd_vel`` (``geometry_msgs/Twist``; zero when a goal ends), ``~current_goal`` and
  ``~recovery_status`` (``move_base_msgs/RecoveryStatus``).

Every 1/``controller_frequency`` s a cycle runs move_base's state machine: PLANNING (plan
until ``planner_patience`` runs out), CONTROLLING (drive until the local planner reports
the goal reached; ``controller_patience`` without a valid command, or no progress of
``oscillation_distance`` within ``oscillation_timeout``, leads to clearing) and CLEARING
(the next recovery behaviour, then back to planning; when all have run the goal is aborted
with move_base's message). The global planner runs inside the cycle (move_base runs it in
its own thread), at most once per cycle while planning and every 1/``planner_frequency`` s
while controlling. A goal whose frame has no transform into the global frame stays in its
frame (move_base's warning), so planning fails and the goal ends ABORTED after the
recoveries; the node keeps running.
"""

from __future__ import annotations

import math
import threading
from typing import Any

from workbench.actionlib import SimpleActionServer
from workbench.navigation import local_planner_plan as lp
from workbench.navigation.move_base_params import MoveBaseError, read_params
from workbench.navigation.recovery import RECOVERY_TYPES

PLANNING, CONTROLLING, CLEARING = "PLANNING", "CONTROLLING", "CLEARING"
PLANNING_R, CONTROLLING_R, OSCILLATION_R = "PLANNING_R", "CONTROLLING_R", "OSCILLATION_R"

#: recovery trigger -> (log line, result text) when every recovery has run
ABORTS = {
    CONTROLLING_R: (
        "Aborting because a valid control could not be found. Even after executing all recovery behaviors",
        "Failed to find a valid control. Even after executing recovery behaviors.",
    ),
    PLANNING_R: (
        "Aborting because a valid plan could not be found. Even after executing all recovery behaviors",
        "Failed to find a valid plan. Even after executing recovery behaviors.",
    ),
    OSCILLATION_R: (
        "Aborting because the robot appears to be oscillating over and over. Even after executing all "
        "recovery behaviors",
        "Robot is oscillating. Even after executing recovery behaviors.",
    ),
}


def quaternion_problem(q: Any) -> str | None:
    """move_base's ``isQuaternionValid``: the error line, or None for a usable goal heading."""
    values = (q.x, q.y, q.z, q.w)
    if not all(math.isfinite(v) for v in values):
        return "Quaternion has nans or infs... discarding as a navigation goal"
    norm2 = sum(v * v for v in values)
    if norm2 < 1e-6:
        return "Quaternion has length close to zero... discarding as navigation goal"
    n = math.sqrt(norm2)
    x, y = q.x / n, q.y / n
    up_z = 1.0 - 2.0 * (x * x + y * y)  # the rotated z-axis' z component
    if abs(up_z - 1.0) > 1e-3:
        return "Quaternion is invalid... for navigation the z-axis of the quaternion must be close to vertical."
    return None


def make_local_planner(kind: str, node: Any, costmap: Any, tf_buffer: Any) -> Any:
    """The local planner object for a ``package/Class`` name."""
    if kind == "dwa_local_planner/DWAPlannerROS":
        from workbench.navigation.dwa_planner_ros import DWAPlannerROS

        return DWAPlannerROS(node, "DWAPlannerROS", costmap, tf_buffer)
    from workbench.navigation.local_planner_ros import TrajectoryPlannerROS

    return TrajectoryPlannerROS(node, "TrajectoryPlannerROS", costmap, tf_buffer)


class MoveBase:
    """move_base on ``node`` (see the module docstring).

    Args:
        node: The host node, normally ``/move_base``.
        tf_buffer: A tf buffer filled from the bus.
        start_timers: Run the control loop and the costmaps' timers on the bus clock.

    Raises:
        MoveBaseError, CostmapError, PlannerParameterError: A bad parameter (one line naming it).
    """

    def __init__(self, node: Any, tf_buffer: Any, *, start_timers: bool = True) -> None:
        from workbench.msgs.geometry_msgs import PoseStamped, Twist
        from workbench.msgs.move_base_msgs import MoveBaseAction, MoveBaseActionGoal, RecoveryStatus
        from workbench.msgs.nav_msgs import GetPlan
        from workbench.msgs.std_srvs import Empty
        from workbench.navigation.costmap_ros import CostmapROS
        from workbench.navigation.navfn import NavfnROS

        self.node = node
        self.tf = tf_buffer
        self.log = node.get_logger()
        self.lock = threading.RLock()
        self.p = read_params(node)
        self.global_costmap = CostmapROS(
            node, "global_costmap", tf_buffer, start_timers=start_timers
        )
        self.local_costmap = CostmapROS(node, "local_costmap", tf_buffer, start_timers=start_timers)
        self.planner = NavfnROS(node, "NavfnROS", self.global_costmap)
        self.controller = make_local_planner(
            self.p.base_local_planner, node, self.local_costmap, tf_buffer
        )
        self.recoveries = [
            (name, RECOVERY_TYPES[kind](node, name, self.global_costmap, self.local_costmap))
            for name, kind in self.p.recovery_behaviors
        ]
        self.cmd_pub = node.create_publisher("cmd_vel", Twist, 1)
        self.current_goal_pub = node.create_publisher("~current_goal", PoseStamped, 0)
        self.recovery_pub = node.create_publisher("~recovery_status", RecoveryStatus, 1)
        self.action_goal_pub = node.create_publisher("move_base/goal", MoveBaseActionGoal, 1)
        node.create_subscription("move_base_simple/goal", PoseStamped, self._on_simple_goal, 1)
        node.create_service("~make_plan", GetPlan, self._on_make_plan)
        node.create_service("~clear_costmaps", Empty, self._on_clear_costmaps)
        self.server = SimpleActionServer(node, "move_base", MoveBaseAction, auto_start=False)
        self.goal: Any = None
        self.plan: list[Any] = []
        self._reset_fields()
        self.timer = None
        if start_timers:
            self.timer = node.create_timer(
                1.0 / self.p.controller_frequency, lambda event: self.cycle()
            )
        self.server.start()

    # --- state ---------------------------------------------------------------------------

    def _now(self) -> float:
        return self.node.bus.clock.now_ns() / 1e9

    def _reset_fields(self) -> None:
        self.state = PLANNING
        self.recovery_index = 0
        self.recovery_trigger = PLANNING_R
        self.run_planner = False
        self.new_plan = False
        self.active_recovery: Any = None
        self.next_plan_time = 0.0

    def reset_state(self) -> None:
        """move_base's ``resetState``: stop planning, forget recoveries, command zero."""
        self._reset_fields()
        self.publish_zero_velocity()
        if self.p.shutdown_costmaps:
            self.log.debug("Stopping costmaps")

    def publish_zero_velocity(self) -> None:
        self.publish_velocity((0.0, 0.0, 0.0))

    def publish_velocity(self, v: tuple[float, float, float]) -> None:
        from workbench.msgs.geometry_msgs import Twist

        cmd = Twist()
        cmd.linear.x, cmd.linear.y, cmd.angular.z = (float(c) for c in v)
        self.cmd_pub.publish(cmd)

    # --- goals -----------------------------------------------------------------------------

    def _on_simple_goal(self, msg: Any) -> None:
        from workbench.msgs.move_base_msgs import MoveBaseActionGoal

        self.log.debug(
            "In ROS goal callback, wrapping the PoseStamped in the action message and re-sending to the server."
        )
        action_goal = MoveBaseActionGoal()
        action_goal.header.stamp = self.node.now()
        action_goal.goal.target_pose = msg
        self.action_goal_pub.publish(action_goal)

    def goal_to_global_frame(self, pose: Any) -> Any:
        """``pose`` in the global costmap's frame (unchanged, with a warning, if tf cannot)."""
        from workbench.msgs.geometry_msgs import PoseStamped

        frame = self.global_costmap.global_frame
        source = pose.header.frame_id.lstrip("/")
        try:
            tf2d = lp.planar_transform(self.tf, frame, source or frame)
        except Exception as error:  # tf's exceptions, as move_base catches tf2::TransformException
            self.log.warn(
                f"Failed to transform the goal pose from {pose.header.frame_id} into the {frame} frame: "
                f"{getattr(error, 'message', error)}"
            )
            return pose
        x, y, yaw = lp.apply(tf2d, lp.poses_array([pose]))[0]
        out = PoseStamped()
        out.header.frame_id = frame
        out.header.stamp = self.node.now()
        out.pose.position.x, out.pose.position.y = float(x), float(y)
        out.pose.position.z = float(pose.pose.position.z)
        out.pose.orientation = lp.quaternion_msg(float(yaw))
        return out

    def _start_goal(self, goal: Any) -> bool:
        problem = quaternion_problem(goal.target_pose.pose.orientation)
        if problem is not None:
            self.log.error(problem)
            self.server.set_aborted(
                None, "Aborting on goal because it was sent with an invalid quaternion"
            )
            return False
        self.goal = self.goal_to_global_frame(goal.target_pose)
        self.current_goal_pub.publish(self.goal)
        now = self._now()
        self.state = PLANNING
        self.recovery_index = 0
        self.recovery_trigger = PLANNING_R
        self.active_recovery = None
        self.run_planner = True
        self.new_plan = False
        self.next_plan_time = now
        self.last_valid_control = self.last_valid_plan = self.last_oscillation_reset = now
        self.planning_retries = 0
        pose = self.global_costmap.robot_pose()
        self.oscillation_pose = pose[:2] if pose is not None else (math.inf, math.inf)
        return True

    # --- the control loop -----------------------------------------------------------------

    def cycle(self) -> None:
        """One control cycle (called by the timer at ``controller_frequency``)."""
        with self.lock:
            server = self.server
            if server.is_new_goal_available():
                goal = server.accept_new_goal()
                if not self._start_goal(goal):
                    self.reset_state()
                    return
            elif server.is_preempt_requested() and server.is_active():
                self.log.debug("Move base preempting the current goal")
                self.reset_state()
                server.set_preempted()
                return
            if not server.is_active():
                return
            if self.goal.header.frame_id.lstrip("/") != self.global_costmap.global_frame:
                self.goal = self.goal_to_global_frame(self.goal)
            self._execute_cycle()

    def _feedback(self) -> tuple[float, float, float] | None:
        from workbench.msgs.geometry_msgs import PoseStamped
        from workbench.msgs.move_base_msgs import MoveBaseFeedback

        pose = self.global_costmap.robot_pose()
        if pose is None:
            return None
        feedback = MoveBaseFeedback()
        feedback.base_position = PoseStamped()
        feedback.base_position.header.frame_id = self.global_costmap.global_frame
        feedback.base_position.header.stamp = self.node.now()
        feedback.base_position.pose.position.x, feedback.base_position.pose.position.y = (
            pose[0],
            pose[1],
        )
        feedback.base_position.pose.orientation = lp.quaternion_msg(pose[2])
        self.server.publish_feedback(feedback)
        return pose

    def _execute_cycle(self) -> None:
        now = self._now()
        pose = self._feedback()
        if (
            pose is not None
            and math.dist(pose[:2], self.oscillation_pose) >= self.p.oscillation_distance
        ):
            self.last_oscillation_reset = now
            self.oscillation_pose = pose[:2]
            if self.recovery_trigger == OSCILLATION_R:
                self.recovery_index = 0
        if not self.local_costmap.is_current():
            self.log.warn(
                f"[{self.node.name}]:Sensor data is out of date, we're not going to allow commanding of the "
                "base for safety"
            )
            self.publish_zero_velocity()
            return
        if self.run_planner and (self.state == PLANNING or now >= self.next_plan_time):
            self._plan_once(now, pose)
        if self.new_plan:
            self.new_plan = False
            self.log.debug("Got a new plan...swap pointers")
            self.controller.set_plan(self.plan)
            if self.recovery_trigger == PLANNING_R:
                self.recovery_index = 0
        if self.state == PLANNING:
            self.run_planner = True
        elif self.state == CONTROLLING:
            self._control(now)
        else:
            self._clear(now, pose)

    def _plan_once(self, now: float, pose: tuple[float, float, float] | None) -> None:
        """One global planning attempt (move_base's planner thread, one loop)."""
        if self.p.planner_frequency > 0:
            self.next_plan_time = now + 1.0 / self.p.planner_frequency
        plan: list[Any] = []
        if pose is None:
            self.log.warn("Unable to get starting pose of robot, unable to create global plan")
        else:
            plan = self.planner.make_plan(self._pose_stamped(pose), self.goal)
            if not plan:
                self.log.debug(
                    f"Failed to find a  plan to point ({self.goal.pose.position.x:.2f}, "
                    f"{self.goal.pose.position.y:.2f})"
                )
        if plan:
            self.log.debug(f"Got Plan with {len(plan)} points!")
            self.plan = plan
            self.last_valid_plan = now
            self.planning_retries = 0
            self.new_plan = True
            if self.run_planner:
                self.state = CONTROLLING
            if self.p.planner_frequency <= 0:
                self.run_planner = False
        elif self.state == PLANNING:
            self.log.debug("No Plan...")
            self.planning_retries += 1
            out_of_tries = 0 <= self.p.max_planning_retries < self.planning_retries
            if self.run_planner and (
                now > self.last_valid_plan + self.p.planner_patience or out_of_tries
            ):
                self.state = CLEARING
                self.run_planner = False
                self.publish_zero_velocity()
                self.recovery_trigger = PLANNING_R

    def _pose_stamped(self, pose: tuple[float, float, float]) -> Any:
        from workbench.msgs.geometry_msgs import PoseStamped

        msg = PoseStamped()
        msg.header.frame_id = self.global_costmap.global_frame
        msg.header.stamp = self.node.now()
        msg.pose.position.x, msg.pose.position.y = float(pose[0]), float(pose[1])
        msg.pose.orientation = lp.quaternion_msg(float(pose[2]))
        return msg

    def _control(self, now: float) -> None:
        if self.controller.is_goal_reached():
            self.log.debug("Goal reached!")
            self.reset_state()
            self.server.set_succeeded(None, "Goal reached.")
            return
        if (
            self.p.oscillation_timeout > 0
            and self.last_oscillation_reset + self.p.oscillation_timeout < now
        ):
            self.publish_zero_velocity()
            self.state = CLEARING
            self.recovery_trigger = OSCILLATION_R
        ok, cmd = self.controller.compute_velocity_commands()
        if ok:
            self.log.debug(
                f"Got a valid command from the local planner: {cmd[0]:.3f}, {cmd[1]:.3f}, {cmd[2]:.3f}"
            )
            self.last_valid_control = now
            self.publish_velocity(cmd)
            if self.recovery_trigger == CONTROLLING_R:
                self.recovery_index = 0
            return
        self.log.debug("The local planner could not find a valid plan.")
        if now > self.last_valid_control + self.p.controller_patience:
            self.publish_zero_velocity()
            self.state = CLEARING
            self.recovery_trigger = CONTROLLING_R
        else:
            self.last_valid_plan = now
            self.planning_retries = 0
            self.state = PLANNING
            self.publish_zero_velocity()
            self.run_planner = True

    def _clear(self, now: float, pose: tuple[float, float, float] | None) -> None:
        if self.active_recovery is None:
            if not (
                self.p.recovery_behavior_enabled and self.recovery_index < len(self.recoveries)
            ):
                self.log.debug(
                    "All recovery behaviors have failed, locking the planner and disabling it."
                )
                line, text = ABORTS[self.recovery_trigger]
                self.log.error(line)
                self.reset_state()
                self.server.set_aborted(None, text)
                return
            name, behaviour = self.recoveries[self.recovery_index]
            self.log.debug(
                f"Executing behavior {self.recovery_index + 1} of {len(self.recoveries)}"
            )
            self._publish_recovery_status(name, pose)
            behaviour.start()
            self.active_recovery = behaviour
        done, cmd = self.active_recovery.step()
        if cmd is not None:
            self.publish_velocity(cmd)
        if done:
            self.active_recovery = None
            self.last_oscillation_reset = now
            self.log.debug("Going back to planning state")
            self.last_valid_plan = now
            self.planning_retries = 0
            self.state = PLANNING
            self.run_planner = True
            self.recovery_index += 1

    def _publish_recovery_status(self, name: str, pose: tuple[float, float, float] | None) -> None:
        from workbench.msgs.move_base_msgs import RecoveryStatus

        msg = RecoveryStatus()
        if pose is not None:
            msg.pose_stamped = self._pose_stamped(pose)
        msg.current_recovery_number = self.recovery_index
        msg.total_number_of_recoveries = len(self.recoveries)
        msg.recovery_behavior_name = name
        self.recovery_pub.publish(msg)

    # --- services ---------------------------------------------------------------------------

    def _on_clear_costmaps(self, request: Any) -> Any:
        from workbench.msgs.std_srvs import Empty

        with self.lock:
            self.global_costmap.reset_layers()
            self.local_costmap.reset_layers()
        return Empty.Response()

    def _on_make_plan(self, request: Any) -> Any:
        from workbench.msgs.nav_msgs import GetPlan

        with self.lock:
            if self.server.is_active():
                self.log.error(
                    "move_base must be in an inactive state to make a plan for an external user"
                )
                raise MoveBaseError(
                    "move_base must be in an inactive state to make a plan for an external user"
                )
            start = request.start
            if not start.header.frame_id:
                pose = self.global_costmap.robot_pose()
                if pose is None:
                    text = "move_base cannot make a plan for you because it could not get the start pose of the robot"
                    self.log.error(text)
                    raise MoveBaseError(text)
                start = self._pose_stamped(pose)
            plan = self.planner.make_plan(start, request.goal)
            if not plan:
                plan = self._plan_within_tolerance(start, request.goal, float(request.tolerance))
        response = GetPlan.Response()
        response.plan.poses = plan
        response.plan.header.frame_id = self.global_costmap.global_frame
        response.plan.header.stamp = self.node.now()
        return response

    def _plan_within_tolerance(self, start: Any, goal: Any, tolerance: float) -> list[Any]:
        """move_base's outward search for a goal with a plan within ``tolerance`` (m)."""
        import copy

        self.log.debug(
            f"Failed to find a plan to exact goal of ({goal.pose.position.x:.2f}, {goal.pose.position.y:.2f}), "
            "searching for a feasible goal within tolerance"
        )
        step = self.global_costmap.costmap().resolution * 3.0
        if 0.0 < tolerance < step:
            step = tolerance
        offset = step
        while offset <= tolerance + 1e-9:
            ring = [0.0]
            while ring[-1] + step <= offset + 1e-9:
                ring.append(ring[-1] + step)
            for dy in ring:
                for dx in ring:
                    if dx < offset - 1e-9 and dy < offset - 1e-9:
                        continue
                    for sy in (-1.0, 1.0) if dy > 1e-9 else (1.0,):
                        for sx in (-1.0, 1.0) if dx > 1e-9 else (1.0,):
                            p = copy.deepcopy(goal)
                            p.pose.position.x = goal.pose.position.x + dx * sx
                            p.pose.position.y = goal.pose.position.y + dy * sy
                            plan = self.planner.make_plan(start, p)
                            if plan:
                                if self.p.make_plan_add_unreachable_goal:
                                    plan.append(goal)
                                self.log.debug(
                                    f"Found a plan to point ({p.pose.position.x:.2f}, {p.pose.position.y:.2f})"
                                )
                                return plan
            offset += step
        return []

    def shutdown(self) -> None:
        """Stop the loop and the costmaps; command zero."""
        import contextlib

        from workbench.bus.errors import ShutdownError

        if self.timer is not None:
            self.timer.shutdown()
        with contextlib.suppress(ShutdownError):  # the node went first (SIGINT): no one listens
            self.publish_zero_velocity()
        self.global_costmap.shutdown()
        self.local_costmap.shutdown()
