"""Dead reckoning from two wheels: ``diff_drive``'s ``odometrySource`` ``encoder``.

gazebo_plugins' ``UpdateOdometryEncoder`` (noetic): when the wheels (radius
``r``, separation ``b``) have rolled ``sl`` and ``sr`` since the last update, the
pose advances along the chord at the mean heading (Siegwart, *Autonomous Mobile
Robots*, 2011, p. 337)::

    dtheta = (sr - sl) / b
    dx = (sl + sr) / 2 * cos(theta + dtheta / 2)
    dy = (sl + sr) / 2 * sin(theta + dtheta / 2)

The twist it reports is the last interval's: ``v = |(dx, dy)| / dt`` (negative
when the wheels roll backwards), ``w = dtheta / dt``, no sideways speed.

Gazebo runs this before every physics step with ``s = wheel velocity * r * dt``;
here it runs at the plugin's ``updateRate`` with ``s = change of the wheel angle
* r``. Both are the angle the wheel turned (the physics step advances the angle
by velocity x step), so the pose is the same; the twist is averaged over the
update period rather than the last step.
"""

from __future__ import annotations

import math


class EncoderOdometry:
    """The pose ``(x, y, theta)`` integrated from wheel speeds.

    Args:
        wheel_separation: Distance between the wheels' contact points, m.
        wheel_diameter: m.
    """

    def __init__(self, wheel_separation: float, wheel_diameter: float) -> None:
        self.separation = float(wheel_separation)
        self.radius = float(wheel_diameter) / 2.0
        self.reset()

    def reset(self) -> None:
        """Back to the origin, at rest."""
        self.x = self.y = self.theta = 0.0
        self.v = self.w = 0.0

    def advance(self, left: float, right: float, dt: float) -> None:
        """Move on by the wheels' turns ``left``, ``right`` (rad) made in ``dt`` s."""
        if dt <= 0.0:
            return
        sl = left * self.radius
        sr = right * self.radius
        dtheta = (sr - sl) / self.separation
        heading = self.theta + dtheta / 2.0
        dx = (sl + sr) / 2.0 * math.cos(heading)
        dy = (sl + sr) / 2.0 * math.sin(heading)
        self.x += dx
        self.y += dy
        self.theta += dtheta
        speed = math.hypot(dx, dy) / dt
        self.v = -speed if sl + sr < 0.0 else speed
        self.w = dtheta / dt

    def quaternion(self) -> tuple[float, float, float, float]:
        """The heading as a quaternion ``(x, y, z, w)``."""
        return (0.0, 0.0, math.sin(self.theta / 2.0), math.cos(self.theta / 2.0))
