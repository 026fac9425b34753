"""``{position,velocity,effort}_controllers/JointTrajectoryController`` (ros_controllers noetic).

Parameters under ``<robot ns>/<name>/``: ``joints`` (required), ``constraints``
(``goal_time``, ``stopped_velocity_tolerance`` (0.01), ``<joint>/trajectory`` and
``<joint>/goal`` position tolerances; 0 means unchecked), ``stop_trajectory_duration``
(0), ``state_publish_rate`` (50 Hz), ``action_monitor_rate`` (20 Hz),
``allow_partial_joints_goal`` (false), and for the velocity and effort interfaces
``gains/<joint>/{p,i,d,i_clamp}`` (required) and ``velocity_ff/<joint>`` (0).

Interfaces: the action ``<name>/follow_joint_trajectory``
(control_msgs/FollowJointTrajectory), the topic ``<name>/command``
(trajectory_msgs/JointTrajectory; an empty one stops), ``<name>/state``
(control_msgs/JointTrajectoryControllerState) and the service ``<name>/query_state``.

As the original: a goal whose joints do not match is rejected with ``INVALID_JOINTS``,
one that cannot be turned into a trajectory with ``INVALID_GOAL`` and its
``error_string``; an accepted goal preempts (cancels) the active one. While a
segment of the goal runs, a joint outside its path tolerance aborts it
(``PATH_TOLERANCE_VIOLATED``); after the last segment it succeeds once every joint is
within its goal tolerance, and aborts (``GOAL_TOLERANCE_VIOLATED``) if that has not
happened ``goal_time`` s after the end. A cancel holds the joints where they are.
The position interface commands the desired position; velocity and effort command
``velocity_ff * desired velocity + PID(position error, velocity error)``, the
position error being the shortest turn. Feedback is sent at ``action_monitor_rate``.
"""

from __future__ import annotations

import logging
import threading
from typing import Any

from workbench.sim.ros_control.angles import shortest_angular_distance
from workbench.sim.ros_control.controllers import Controller, ControllerError
from workbench.sim.ros_control.hardware import POSITION
from workbench.sim.ros_control.pid import Pid
from workbench.sim.ros_control.trajectory import (
    JointTolerances,
    Tolerances,
    Trajectory,
    TrajectoryError,
    build_trajectory,
    hold_trajectory,
    sample,
)

_LOG = logging.getLogger("workbench.sim.ros_control")

SUCCESSFUL, INVALID_GOAL, INVALID_JOINTS = 0, -1, -2
PATH_TOLERANCE_VIOLATED, GOAL_TOLERANCE_VIOLATED = -4, -5


class _Goal:
    """An accepted action goal (the realtime goal handle)."""

    def __init__(self, handle: Any) -> None:
        self.handle = handle
        self.done = False

    def finish(self, how: str, code: int, text: str = "") -> None:
        if self.done:
            return
        self.done = True
        from workbench.msgs.control_msgs import FollowJointTrajectoryResult

        result = FollowJointTrajectoryResult(error_code=code, error_string=text)
        getattr(self.handle, how)(result)


class JointTrajectoryController(Controller):
    """Follows trajectories from its action and its command topic (see the module docstring)."""

    def init(self) -> None:
        names = self.joint_list()
        self.handles = [self.joint(n) for n in names]
        self.joint_names = names
        self.wraparound = [h.type == "continuous" for h in self.handles]
        self.state_period = 1.0 / float(self.params.get("state_publish_rate", 50.0))
        self.monitor_period = 1.0 / float(self.params.get("action_monitor_rate", 20.0))
        self.stop_duration = float(self.params.get("stop_trajectory_duration", 0.0))
        self.allow_partial = bool(self.params.get("allow_partial_joints_goal", False))
        self.default_tolerances = self._constraints()
        self.pids: list[Pid] = []
        self.velocity_ff = [0.0] * len(names)
        if self.interface != POSITION:
            for i, name in enumerate(names):
                pid = Pid.from_params(self.params.child("gains").get(name, None))
                if pid is None:
                    raise ControllerError(
                        f"controller '{self.name}': no PID gains for joint '{name}' (set "
                        f"{self.params.name('gains/' + name)}/p, i, d)"
                    )
                self.pids.append(pid)
                self.velocity_ff[i] = float(self.params.get(f"velocity_ff/{name}", 0.0))
        self.lock = threading.RLock()
        self.trajectory: Trajectory = hold_trajectory(
            [0.0] * len(names), [0.0] * len(names), 0.0, 0.0
        )
        self.active: _Goal | None = None
        self.succeeded = [False] * len(names)
        self.time = 0.0
        self.period = 0.0
        self.desired = [(0.0, 0.0, 0.0)] * len(names)
        self.error = [(0.0, 0.0, 0.0)] * len(names)
        self.last_state_publish = 0.0
        self.last_feedback = -1e9
        self.subscribe("command", "trajectory_msgs/JointTrajectory", self._on_command)
        self.state_publisher = self.advertise(
            "state", "control_msgs/JointTrajectoryControllerState"
        )
        self.server = None
        if self.node is not None:
            from workbench.actionlib import ActionServer

            self.server = ActionServer(
                self.node,
                self.topic("follow_joint_trajectory"),
                "control_msgs/FollowJointTrajectoryAction",
                self._on_goal,
                self._on_cancel,
            )
            self._endpoints.append(
                self.node.create_service(
                    self.topic("query_state"), "control_msgs/QueryTrajectoryState", self._query
                )
            )

    def _constraints(self) -> list[JointTolerances]:
        constraints = self.params.child("constraints")
        stopped = float(constraints.get("stopped_velocity_tolerance", 0.01))
        goal_time = float(constraints.get("goal_time", 0.0))
        return [
            JointTolerances(
                state=Tolerances(float(constraints.get(f"{name}/trajectory", 0.0))),
                goal=Tolerances(float(constraints.get(f"{name}/goal", 0.0)), stopped),
                goal_time=goal_time,
            )
            for name in self.joint_names
        ]

    def claimed(self) -> list[str]:
        return list(self.joint_names)

    def shutdown(self) -> None:
        if self.server is not None:
            self.server.shutdown()
        super().shutdown()

    # --- lifecycle ----------------------------------------------------------------------

    def starting(self, time: float) -> None:
        with self.lock:
            self.time, self.period = time, 0.0
            self.desired = [(h.position, h.velocity, 0.0) for h in self.handles]
            self._hold(time)
            self.last_state_publish = time
            for i, handle in enumerate(self.handles):
                if not self.pids:
                    handle.command = handle.position
                else:
                    self.pids[i].reset()
                    handle.command = 0.0

    def stopping(self, time: float) -> None:
        with self.lock:
            self._preempt()

    def _hold(self, time: float, goal: _Goal | None = None) -> None:
        if self.stop_duration > 0.0:
            positions = [d[0] for d in self.desired]
            velocities = [d[1] for d in self.desired]
        else:
            positions = [h.position for h in self.handles]
            velocities = [0.0] * len(self.handles)
        self.trajectory = hold_trajectory(positions, velocities, time, self.stop_duration, goal)

    def _preempt(self) -> None:
        if self.active is not None:
            goal, self.active = self.active, None
            goal.finish("set_canceled", SUCCESSFUL)

    # --- commands -----------------------------------------------------------------------

    def _accept_trajectory(
        self, message: Any, goal: _Goal | None, tolerances: list[JointTolerances]
    ) -> None:
        """``updateTrajectoryCommand``; raises TrajectoryError with the error string."""
        if self.state != "running":
            raise TrajectoryError("Can't accept new commands. Controller is not running.")
        now = self.time + self.period
        if not message.points:
            self._hold(self.time, goal)
            return
        self.trajectory = build_trajectory(
            message,
            now,
            self.joint_names,
            self.trajectory,
            wraparound=self.wraparound,
            tolerances=tolerances,
            goal=goal,
            allow_partial=self.allow_partial,
        )

    def _on_command(self, message: Any) -> None:
        with self.lock:
            try:
                self._accept_trajectory(message, None, self.default_tolerances)
            except TrajectoryError as error:
                _LOG.error("controller '%s': %s", self.name, error.message)
                return
            self._preempt()

    def _on_goal(self, handle: Any) -> None:
        goal = handle.get_goal()
        with self.lock:
            if self.state != "running":
                _LOG.error("controller '%s': can't accept new action goals, not running", self.name)
                return handle.set_rejected(_result(INVALID_GOAL))
            names = list(goal.trajectory.joint_names)
            partial_ok = self.allow_partial or len(names) == len(self.joint_names)
            if (
                not partial_ok
                or any(n not in self.joint_names for n in names)
                or len(names) > len(self.joint_names)
            ):
                _LOG.error(
                    "controller '%s': joints on incoming goal don't match the controller joints",
                    self.name,
                )
                return handle.set_rejected(_result(INVALID_JOINTS))
            active = _Goal(handle)
            try:
                self._accept_trajectory(goal.trajectory, active, self._goal_tolerances(goal))
            except TrajectoryError as error:
                _LOG.error("controller '%s': %s", self.name, error.message)
                return handle.set_rejected(_result(INVALID_GOAL, error.message))
            self._preempt()
            handle.set_accepted()
            self.active = active
            self.succeeded = [False] * len(self.joint_names)
            self.last_feedback = -1e9

    def _goal_tolerances(self, goal: Any) -> list[JointTolerances]:
        result = []
        goal_time = goal.goal_time_tolerance.secs + goal.goal_time_tolerance.nsecs * 1e-9
        for name, tolerances in zip(self.joint_names, self.default_tolerances, strict=True):
            state, final = tolerances.state, tolerances.goal
            for item in goal.path_tolerance:
                if item.name == name:
                    state = _updated(state, item)
            for item in goal.goal_tolerance:
                if item.name == name:
                    final = _updated(final, item)
            time = tolerances.goal_time
            if goal_time < 0:
                time = 0.0
            elif goal_time > 0:
                time = goal_time
            result.append(JointTolerances(state, final, time))
        return result

    def _on_cancel(self, handle: Any) -> None:
        with self.lock:
            if self.active is not None and self.active.handle == handle:
                goal, self.active = self.active, None
                self._hold(self.time)
                goal.finish("set_canceled", SUCCESSFUL)

    def _query(self, request: Any) -> Any:
        from workbench.msgs.control_msgs import QueryTrajectoryState

        with self.lock:
            if self.state != "running":
                raise ControllerError(f"controller '{self.name}' is not running")
            at = request.time.secs + request.time.nsecs * 1e-9
            states = []
            for segments in self.trajectory:
                index, state = sample(segments, at)
                if index is None:
                    raise ControllerError("Requested sample time precedes trajectory start time.")
                states.append(state)
            return QueryTrajectoryState.Response(
                name=list(self.joint_names),
                position=[s[0] for s in states],
                velocity=[s[1] for s in states],
                acceleration=[s[2] for s in states],
            )

    # --- the control step -------------------------------------------------------------

    def update(self, time: float, period: float) -> None:
        with self.lock:
            self.time, self.period = time, period
            segments_now = []
            for i, handle in enumerate(self.handles):
                index, state = sample(self.trajectory[i], time)
                self.desired[i] = state
                self.error[i] = (
                    shortest_angular_distance(handle.position, state[0]),
                    state[1] - handle.velocity,
                    0.0,
                )
                segments_now.append(index)
            for i, index in enumerate(segments_now):
                self._check(i, index, time)
            if self.active is not None and all(self.succeeded):
                goal, self.active = self.active, None
                goal.finish("set_succeeded", SUCCESSFUL)
            self._command(period)
            self._feedback(time)
            self._publish_state(time)

    def _check(self, joint: int, index: int | None, time: float) -> None:
        segments = self.trajectory[joint]
        segment = segments[index if index is not None else 0]
        goal = self.active
        if goal is None or segment.goal is not goal:
            return
        error = self.error[joint]
        name = self.joint_names[joint]
        if time < segment.end:
            if not segment.tolerances.state.holds(error):
                _LOG.error("controller '%s': path tolerances failed for joint %s", self.name, name)
                self.active = None
                self.succeeded = [False] * len(self.joint_names)
                goal.finish(
                    "set_aborted", PATH_TOLERANCE_VIOLATED, f"{name} path error {error[0]:f}"
                )
        elif index == len(segments) - 1:
            if segment.tolerances.goal.holds(error):
                self.succeeded[joint] = True
            elif time >= segment.end + segment.tolerances.goal_time:
                _LOG.error("controller '%s': goal tolerances failed for joint %s", self.name, name)
                self.active = None
                self.succeeded = [False] * len(self.joint_names)
                goal.finish(
                    "set_aborted", GOAL_TOLERANCE_VIOLATED, f"{name} goal error {error[0]:f}"
                )

    def _command(self, period: float) -> None:
        for i, handle in enumerate(self.handles):
            if not self.pids:
                handle.command = self.desired[i][0]
                continue
            handle.command = self.velocity_ff[i] * self.desired[i][1] + self.pids[i].command(
                self.error[i][0], self.error[i][1], period
            )

    def _points(self, time: float) -> tuple[Any, Any, Any]:
        from workbench.msgs.trajectory_msgs import JointTrajectoryPoint

        desired = JointTrajectoryPoint(
            positions=[d[0] for d in self.desired],
            velocities=[d[1] for d in self.desired],
            accelerations=[d[2] for d in self.desired],
        )
        actual = JointTrajectoryPoint(
            positions=[h.position for h in self.handles],
            velocities=[h.velocity for h in self.handles],
        )
        error = JointTrajectoryPoint(
            positions=[e[0] for e in self.error], velocities=[e[1] for e in self.error]
        )
        return desired, actual, error

    def _feedback(self, time: float) -> None:
        goal = self.active
        if goal is None or time - self.last_feedback < self.monitor_period - 1e-9:
            return
        self.last_feedback = time
        from workbench.msgs.control_msgs import FollowJointTrajectoryFeedback
        from workbench.sim.gazebo_ros_plugins.ros_context import ros_stamp

        desired, actual, error = self._points(time)
        feedback = FollowJointTrajectoryFeedback(
            joint_names=list(self.joint_names), desired=desired, actual=actual, error=error
        )
        feedback.header.stamp = ros_stamp(time)
        goal.handle.publish_feedback(feedback)

    def _publish_state(self, time: float) -> None:
        if self.state_publisher is None or not self.last_state_publish + self.state_period < time:
            return
        self.last_state_publish += self.state_period
        from workbench.msgs.control_msgs import JointTrajectoryControllerState
        from workbench.sim.gazebo_ros_plugins.ros_context import ros_stamp

        desired, actual, error = self._points(time)
        message = JointTrajectoryControllerState(
            joint_names=list(self.joint_names), desired=desired, actual=actual, error=error
        )
        message.header.stamp = ros_stamp(time)
        self.state_publisher.publish(message)


def _result(code: int, text: str = "") -> Any:
    from workbench.msgs.control_msgs import FollowJointTrajectoryResult

    return FollowJointTrajectoryResult(error_code=code, error_string=text)


def _updated(tolerances: Tolerances, item: Any) -> Tolerances:
    """``updateStateTolerances``: > 0 sets, < 0 clears, 0 keeps."""
    values = []
    for old, new in (
        (tolerances.position, item.position),
        (tolerances.velocity, item.velocity),
        (tolerances.acceleration, item.acceleration),
    ):
        values.append(new if new > 0 else 0.0 if new < 0 else old)
    return Tolerances(*values)
