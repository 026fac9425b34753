"""Checks of the command line's numbers: durations and rates are finite and within bounds.

A duration of ``1e308`` s overflows the clock's deadline, ``inf`` never ends and NaN
compares false with everything; a rate of ``1e9`` Hz is a busy loop, one of ``1e-300``
waits forever. Each is refused before the command starts, in one line naming the option
and the bound (README, "Limits on input").
"""

from __future__ import annotations

import math

from workbench.errors import WorkbenchError
from workbench.limits import MAX_OPTION_SECONDS

#: Fastest and slowest rate an option takes, Hz.
MAX_RATE_HZ = 10_000.0
MIN_RATE_HZ = 0.001


def check_seconds(
    value: float | None,
    option: str,
    error: type[WorkbenchError] = WorkbenchError,
    *,
    zero: bool = False,
) -> None:
    """Refuse a duration that is not finite, not positive (or 0 when ``zero``), or too long.

    Raises:
        error: Naming ``option`` and the bound.
    """
    if value is None:
        return
    low = "of 0 or more" if zero else "above 0"
    if not (math.isfinite(value) and (value >= 0 if zero else value > 0)):
        raise error(f"{option} must be a number of seconds {low}, got {value:g}")
    if value > MAX_OPTION_SECONDS:
        raise error(f"{option} must be at most {MAX_OPTION_SECONDS:,.0f} s, got {value:g}")


def check_rate(
    value: float | None, option: str, error: type[WorkbenchError] = WorkbenchError
) -> None:
    """Refuse a rate that is not finite or not within ``MIN_RATE_HZ`` .. ``MAX_RATE_HZ``.

    Raises:
        error: Naming ``option`` and the bounds.
    """
    if value is None:
        return
    if not MIN_RATE_HZ <= value <= MAX_RATE_HZ:  # NaN fails both comparisons
        raise error(
            f"{option} must be a rate from {MIN_RATE_HZ:g} to {MAX_RATE_HZ:,.0f} Hz, got {value:g}"
        )
