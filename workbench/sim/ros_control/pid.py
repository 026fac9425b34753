"""``control_toolbox::Pid`` (noetic): the PID every ros_control effort and velocity controller uses.

Gains come from a parameter namespace: ``p`` (required), ``i`` and ``d`` (default 0),
``i_clamp`` (the integral term's bound, default 0: with it missing the integral term
is clamped to zero, as in control_toolbox), or ``i_clamp_min``/``i_clamp_max``, and
``antiwindup`` (clamp the accumulated error instead of the term).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any


@dataclass
class Pid:
    """One PID loop; ``command(error, error_dot, dt)`` as ``Pid::computeCommand``."""

    p: float
    i: float = 0.0
    d: float = 0.0
    i_min: float = 0.0
    i_max: float = 0.0
    antiwindup: bool = False
    i_error: float = 0.0
    p_error_last: float = 0.0

    @classmethod
    def from_params(cls, values: Any) -> Pid | None:
        """The PID of a parameter dict, or None without a numeric ``p`` (``Pid::init`` fails)."""
        if not isinstance(values, Mapping) or not _number(values.get("p")):
            return None
        clamp = abs(float(values["i_clamp"])) if _number(values.get("i_clamp")) else 0.0
        i_min, i_max = -clamp, clamp
        if _number(values.get("i_clamp_min")):
            i_min = -abs(float(values["i_clamp_min"]))
        if _number(values.get("i_clamp_max")):
            i_max = abs(float(values["i_clamp_max"]))
        return cls(
            p=float(values["p"]),
            i=float(values["i"]) if _number(values.get("i")) else 0.0,
            d=float(values["d"]) if _number(values.get("d")) else 0.0,
            i_min=i_min,
            i_max=i_max,
            antiwindup=bool(values.get("antiwindup", False)),
        )

    def reset(self) -> None:
        """Forget the accumulated and the last error."""
        self.i_error = 0.0
        self.p_error_last = 0.0

    def command(self, error: float, error_dot: float, dt: float) -> float:
        """The command for ``error`` and its rate ``error_dot`` over ``dt`` s (0 when dt is 0)."""
        if dt == 0.0 or not (math.isfinite(error) and math.isfinite(error_dot)):
            return 0.0
        self.i_error += dt * error
        if self.antiwindup and self.i != 0.0:
            bound = (self.i_min / abs(self.i), self.i_max / abs(self.i))
            self.i_error = min(max(self.i_error, bound[0]), bound[1])
            i_term = self.i * self.i_error
        else:
            i_term = min(max(self.i * self.i_error, self.i_min), self.i_max)
        return self.p * error + i_term + self.d * error_dot

    def command_from_error(self, error: float, dt: float) -> float:
        """The command for ``error``, its rate taken from the last error (``computeCommand(e, dt)``)."""
        if dt == 0.0 or not math.isfinite(error):
            return 0.0
        error_dot = (error - self.p_error_last) / dt
        self.p_error_last = error
        return self.command(error, error_dot, dt)


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)
