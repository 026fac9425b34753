"""The ``angles`` package's functions that ros_control uses (rad)."""

from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi


def normalize_angle(angle: float) -> float:
    """``angle`` in [-pi, pi]."""
    positive = math.fmod(math.fmod(angle, TWO_PI) + TWO_PI, TWO_PI)
    return positive - TWO_PI if positive > math.pi else positive


def shortest_angular_distance(start: float, end: float) -> float:
    """The signed turn from ``start`` to ``end``, in [-pi, pi]."""
    return normalize_angle(end - start)


def two_pi_complement(angle: float) -> float:
    """The same direction the other way round (``angle`` -+ 2 pi); 0 gives 2 pi."""
    if abs(angle) > TWO_PI:
        angle = math.fmod(angle, TWO_PI)
    if angle < 0:
        return TWO_PI + angle
    if angle > 0:
        return angle - TWO_PI
    return TWO_PI


def _min_max_delta(start: float, left: float, right: float) -> tuple[bool, float, float]:
    """``(start is within [left, right], smallest and largest allowed turn from start)``."""
    delta = [
        shortest_angular_distance(start, left),
        shortest_angular_distance(start, right),
    ]
    delta += [two_pi_complement(delta[0]), two_pi_complement(delta[1])]
    if delta[0] == 0:
        return True, delta[0], max(delta[1], delta[3])
    if delta[1] == 0:
        return True, min(delta[0], delta[2]), delta[1]
    low, low_other = (delta[2], delta[0]) if delta[2] < delta[0] else (delta[0], delta[2])
    high, high_other = (delta[3], delta[1]) if delta[3] > delta[1] else (delta[1], delta[3])
    if low <= high_other or high >= low_other:
        return left == -math.pi and right == math.pi, high_other, low_other
    return True, low, high


def shortest_angular_distance_with_limits(
    start: float, end: float, left: float, right: float
) -> float:
    """The turn from ``start`` to ``end`` that stays within ``[left, right]`` where it can."""
    inside, low, high = _min_max_delta(start, left, right)
    delta = shortest_angular_distance(start, end)
    other = two_pi_complement(delta)
    if inside:
        if low <= delta <= high:
            return delta
        if low <= other <= high:
            return other
        _, low_to, high_to = _min_max_delta(end, left, right)
        if abs(low_to) < abs(high_to):
            return max(delta, other)
        if abs(low_to) > abs(high_to):
            return min(delta, other)
    elif abs(low) < abs(high):
        return min(delta, other)
    elif abs(low) > abs(high):
        return max(delta, other)
    return delta if abs(delta) < abs(other) else other
