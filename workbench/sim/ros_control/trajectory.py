"""joint_trajectory_controller's trajectories: spline segments per joint, merged as it merges them.

A segment joins two states over ``[start, start + duration]`` with a polynomial whose
order depends on what both ends give: positions only -> linear, with velocities ->
cubic, with accelerations too -> quintic (``QuinticSplineSegment``). Outside its
interval a segment holds its end position with zero velocity and acceleration. A
joint's trajectory is a list of segments; it is sampled in the last segment that has
started (the first one before any has). Times are simulated time, s.

:func:`build_trajectory` is ``initJointTrajectory``: a message's points are taken
from the first one after "now" (``header.stamp`` zero means now; a first point at
``time_from_start`` 0 of such a message is dropped silently, other past points with a
warning, and a message whose points are all past is refused), the current
trajectory is kept from its active segment up to the one active when the new one
starts, and a bridge segment goes from the current desired state there to the new
first point. Continuous joints are offset by whole turns so the bridge is shortest.
"""

from __future__ import annotations

import bisect
import logging
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.ros_control.angles import shortest_angular_distance

_LOG = logging.getLogger("workbench.sim.ros_control")


class TrajectoryError(SimulationError):
    """A trajectory message that cannot be executed (its ``error_string``)."""


@dataclass(frozen=True)
class Tolerances:
    """Position, velocity and acceleration tolerances of one joint (0: not checked)."""

    position: float = 0.0
    velocity: float = 0.0
    acceleration: float = 0.0

    def holds(self, error: tuple[float, float, float]) -> bool:
        """``checkStateTolerancePerJoint``."""
        return all(
            not (bound > 0.0 and abs(value) > bound)
            for bound, value in zip(
                (self.position, self.velocity, self.acceleration), error, strict=True
            )
        )


@dataclass(frozen=True)
class JointTolerances:
    """What a segment of one joint is checked against."""

    state: Tolerances = Tolerances()
    goal: Tolerances = Tolerances()
    goal_time: float = 0.0


@dataclass(frozen=True)
class State:
    """A point of one joint: position and, when given, velocity and acceleration."""

    position: float
    velocity: float | None = None
    acceleration: float | None = None
    time_from_start: float = 0.0


@dataclass
class Segment:
    """One polynomial piece of a joint's trajectory."""

    start: float
    duration: float
    coefficients: tuple[float, ...]
    time_from_start: float = 0.0
    goal: Any = None
    tolerances: JointTolerances = field(default_factory=JointTolerances)

    @property
    def end(self) -> float:
        return self.start + self.duration

    @classmethod
    def between(cls, start: float, first: State, end: float, last: State) -> Segment:
        """The segment from ``first`` at ``start`` to ``last`` at ``end`` (s)."""
        return cls(
            start, end - start, _coefficients(first, last, end - start), first.time_from_start
        )

    def sample(self, time: float) -> tuple[float, float, float]:
        """``(position, velocity, acceleration)`` at ``time``."""
        s = time - self.start
        if s < 0.0 or s > self.duration:
            position = _evaluate(self.coefficients, 0.0 if s < 0.0 else self.duration)[0]
            return position, 0.0, 0.0
        return _evaluate(self.coefficients, s)


Trajectory = list[list[Segment]]  # one list of segments per joint


def _coefficients(first: State, last: State, duration: float) -> tuple[float, ...]:
    p0, p1, T = first.position, last.position, duration
    has_velocity = first.velocity is not None and last.velocity is not None
    has_acceleration = first.acceleration is not None and last.acceleration is not None
    if not has_velocity:
        return (p0, 0.0 if T == 0.0 else (p1 - p0) / T, 0.0, 0.0, 0.0, 0.0)
    v0, v1 = float(first.velocity or 0.0), float(last.velocity or 0.0)
    if not has_acceleration:
        if T == 0.0:
            return (p0, v0, 0.0, 0.0, 0.0, 0.0)
        return (
            p0,
            v0,
            (-3.0 * p0 + 3.0 * p1 - 2.0 * v0 * T - v1 * T) / T**2,
            (2.0 * p0 - 2.0 * p1 + v0 * T + v1 * T) / T**3,
            0.0,
            0.0,
        )
    a0, a1 = float(first.acceleration or 0.0), float(last.acceleration or 0.0)
    if T == 0.0:
        return (p0, v0, 0.5 * a0, 0.0, 0.0, 0.0)
    return (
        p0,
        v0,
        0.5 * a0,
        (-20.0 * p0 + 20.0 * p1 - 3.0 * a0 * T**2 + a1 * T**2 - 12.0 * v0 * T - 8.0 * v1 * T)
        / (2.0 * T**3),
        (30.0 * p0 - 30.0 * p1 + 3.0 * a0 * T**2 - 2.0 * a1 * T**2 + 16.0 * v0 * T + 14.0 * v1 * T)
        / (2.0 * T**4),
        (-12.0 * p0 + 12.0 * p1 - a0 * T**2 + a1 * T**2 - 6.0 * v0 * T - 6.0 * v1 * T)
        / (2.0 * T**5),
    )


def _evaluate(c: Sequence[float], t: float) -> tuple[float, float, float]:
    position = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))))
    velocity = c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])))
    acceleration = 2.0 * c[2] + t * (6.0 * c[3] + t * (12.0 * c[4] + t * 20.0 * c[5]))
    return position, velocity, acceleration


def find_segment(segments: list[Segment], time: float) -> int | None:
    """Index of the last segment started at ``time``; None before the first one."""
    if not segments or time < segments[0].start:
        return None
    return bisect.bisect_right([s.start for s in segments], time) - 1


def sample(segments: list[Segment], time: float) -> tuple[int | None, tuple[float, float, float]]:
    """``(segment index or None, (position, velocity, acceleration))`` of one joint."""
    index = find_segment(segments, time)
    segment = segments[index if index is not None else 0]
    return index, segment.sample(time)


def hold_trajectory(
    positions: Sequence[float],
    velocities: Sequence[float],
    time: float,
    stop_duration: float,
    goal: Any = None,
) -> Trajectory:
    """Hold the joints where they are (``stop_duration`` 0), or stop them over ``stop_duration``
    s from ``velocities`` as joint_trajectory_controller's stop trajectory does."""
    trajectory: Trajectory = []
    for position, velocity in zip(positions, velocities, strict=True):
        start = State(position, 0.0, 0.0)
        if stop_duration <= 0.0:
            segment = Segment.between(time, start, time, start)
        else:
            moving = State(position, velocity, 0.0)
            turned = Segment.between(
                time, moving, time + 2.0 * stop_duration, State(position, -velocity, 0.0)
            )
            p, v, a = turned.sample(time + stop_duration)
            segment = Segment.between(time, moving, time + stop_duration, State(p, v, a))
        segment.goal = goal
        trajectory.append([segment])
    return trajectory


def build_trajectory(
    message: Any,
    now: float,
    joint_names: Sequence[str],
    current: Trajectory | None,
    *,
    wraparound: Sequence[bool],
    tolerances: Sequence[JointTolerances],
    goal: Any = None,
    allow_partial: bool = False,
) -> Trajectory:
    """The trajectory after ``message`` (a trajectory_msgs/JointTrajectory) arrives at ``now``.

    Raises:
        TrajectoryError: Empty, times not strictly increasing, joints that do not match,
            points of the wrong size, or every point in the past.
    """
    points = list(message.points)
    if not points:
        raise TrajectoryError("Trajectory message contains empty trajectory. Nothing to convert.")
    times = [_seconds(p.time_from_start) for p in points]
    if any(b <= a for a, b in zip(times, times[1:], strict=False)):
        raise TrajectoryError(
            "Trajectory message contains waypoints that are not strictly increasing in time."
        )
    names = list(message.joint_names)
    if (not allow_partial and len(names) != len(joint_names)) or len(names) > len(joint_names):
        raise TrajectoryError(
            "Cannot create trajectory from message. It does not contain the expected joints."
        )
    if any(n not in joint_names for n in names):
        raise TrajectoryError(
            "Cannot create trajectory from message. It does not contain the expected joints."
        )
    stamp = message.header.stamp
    start = now if stamp.secs == 0 and stamp.nsecs == 0 else stamp.secs + stamp.nsecs * 1e-9
    first = 0
    while first < len(points) and start + times[first] <= now:
        first += 1
    if first == len(points):
        raise TrajectoryError(
            f"Dropping all {len(points)} trajectory point(s), as they occur before the current "
            f"time.\nLast point is {now - (start + times[-1]):f}s in the past."
        )
    if first > 0 and not (times[0] == 0.0 and start == now and first == 1):
        _LOG.warning(
            "Dropping first %d trajectory point(s) out of %d, as they occur before the "
            "current time.",
            first,
            len(points),
        )
    for point in points[first:]:
        _check_sizes(point, len(names))
    result: Trajectory = (
        [list(segments) for segments in current] if current else [[] for _ in joint_names]
    )
    if current:
        for kept in result:  # the rest of the current trajectory belongs to this goal
            active = find_segment(kept, now)
            for segment in kept[active or 0 :]:
                segment.goal = goal
    for column, name in enumerate(names):
        joint = list(joint_names).index(name)
        states = [_state(p, column, t) for p, t in zip(points[first:], times[first:], strict=True)]
        offset = 0.0
        segments: list[Segment] = []
        if current:
            old = current[joint]
            bridge_start = max(start, now)
            _, (p, v, a) = sample(old, bridge_start)
            if wraparound[joint]:
                offset = _wrap_offset(p, states[0].position)
            states = [_shifted(s, offset) for s in states]
            active = find_segment(old, now)
            ending = find_segment(old, bridge_start)
            segments = old[(active or 0) : (ending or 0) + 1]
            bridge = Segment.between(
                bridge_start, State(p, v, a), start + states[0].time_from_start, states[0]
            )
            bridge.goal, bridge.tolerances = goal, tolerances[joint]
            segments.append(bridge)
        for a_state, b_state in zip(states, states[1:], strict=False):
            segment = Segment.between(
                start + a_state.time_from_start, a_state, start + b_state.time_from_start, b_state
            )
            segment.goal, segment.tolerances = goal, tolerances[joint]
            segments.append(segment)
        if segments:
            result[joint] = segments
    return result


def _wrap_offset(current: float, target: float) -> float:
    """Whole turns to add to ``target`` so that it is the nearest to ``current``."""
    return (current + shortest_angular_distance(current, target)) - target


def _shifted(state: State, offset: float) -> State:
    if offset == 0.0:
        return state
    return State(state.position + offset, state.velocity, state.acceleration, state.time_from_start)


def _state(point: Any, column: int, time_from_start: float) -> State:
    return State(
        float(point.positions[column]),
        float(point.velocities[column]) if len(point.velocities) else None,
        float(point.accelerations[column]) if len(point.accelerations) else None,
        time_from_start,
    )


def _check_sizes(point: Any, size: int) -> None:
    for field_name in ("positions", "velocities", "accelerations"):
        values = getattr(point, field_name)
        if (field_name == "positions" or len(values)) and len(values) != size:
            raise TrajectoryError(
                "Size mismatch in trajectory point position, velocity or acceleration data."
            )
        if any(not math.isfinite(float(v)) for v in values):
            raise TrajectoryError(f"Trajectory point {field_name} are not finite.")


def _seconds(duration: Any) -> float:
    return float(duration.secs) + float(duration.nsecs) * 1e-9
