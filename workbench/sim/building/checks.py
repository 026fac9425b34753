"""The checks of :meth:`BuildingPlan.validate`: every problem is one line naming the element."""

from __future__ import annotations

import bisect
import math
from collections.abc import Iterator

import numpy as np

from workbench.model.limits import name_problem, shown_name
from workbench.sim.building.limits import MIN_PLAN_SIZE
from workbench.sim.building.plan import EPS, BuildingPlan, Level, Wall


def check_plan(plan: BuildingPlan, *, crossings: bool = True) -> None:
    """Raise the first problem of ``plan`` as a :class:`PlanError` (see ``validate``)."""
    if not plan.levels:
        raise plan.error("the plan has no levels and no walls", hint="add a 'walls:' list")
    _unique_names(plan)
    for level in plan.levels:
        _finite(plan, f"level '{level.name}' elevation", level.elevation)
        for wall in level.walls:
            _check_wall(plan, level, wall)
        if crossings:
            _check_crossings(plan, level)
        if level.floor is not None:
            floor = level.floor
            low, high = floor.low, floor.high
            for value in (*low, *high):
                _finite(plan, f"the floor of level '{level.name}': a corner", value)
            if not (high[0] - low[0] > EPS and high[1] - low[1] > EPS):
                raise plan.error(
                    f"the floor of level '{level.name}' is empty: min {_xy(low)}, max {_xy(high)}",
                    hint="give min below and left of max",
                )
            _positive(plan, f"the floor of level '{level.name}': thickness", floor.thickness)
    if not any(level.walls for level in plan.levels):
        raise plan.error("the plan has no walls", hint="add walls to a level")
    for stairs in plan.stairs:
        what = f"stairs '{stairs.name}'"
        for key, value in (("width", stairs.width), ("length", stairs.length)):
            _positive(plan, f"{what}: {key}", value)
        if stairs.steps < 1:
            raise plan.error(f"{what}: 'steps' must be at least 1, got {stairs.steps}")
        rise = plan.level(stairs.top).elevation - plan.level(stairs.bottom).elevation
        if rise <= EPS:
            raise plan.error(
                f"{what} go from level '{stairs.bottom}' to level '{stairs.top}', "
                f"which is not higher ({rise:+g} m)",
                hint="'to' must be a level above 'from'",
            )
    for item in plan.items:
        plan.level(item.level)
        what = f"furniture '{item.name}'"
        sizes = (item.radius, item.size[2]) if item.shape == "cylinder" else item.size
        for value in sizes:
            _positive(plan, f"{what}: size", value)


def _unique_names(plan: BuildingPlan) -> None:
    seen: dict[str, str] = {"ground_plane": "the ground"}
    names = [("building", plan.name)]
    names += [("level", level.name) for level in plan.levels]
    names += [("wall", wall.name) for wall in plan.walls]
    names += [("stairs", stairs.name) for stairs in plan.stairs]
    names += [("furniture", item.name) for item in plan.items]
    names += [("floor", f"floor_{level.name}") for level in plan.levels if level.floor]
    levels: set[str] = set()
    for kind, name in names:
        if not name:
            raise plan.error(f"a {kind} has an empty name")
        problem = name_problem(name)
        if problem is not None:
            raise plan.error(f"the {kind} name '{shown_name(name)}' {problem}", "use a short name")
        if "/" in name or "::" in name or name != name.strip():
            raise plan.error(
                f"the {kind} name '{name}' has '/', '::' or surrounding spaces",
                hint="use letters, digits and _",
            )
        if kind == "level":
            if name in levels:
                raise plan.error(f"two levels are named '{name}'", hint="rename one")
            levels.add(name)
            continue
        if name in seen:
            raise plan.error(
                f"{seen[name]} and a {kind} are both named '{name}'", hint="rename one"
            )
        seen[name] = f"a {kind}"


def _check_wall(plan: BuildingPlan, level: Level, wall: Wall) -> None:
    what = f"level '{level.name}', {wall.label}"
    for value in (*wall.start, *wall.end):
        _finite(plan, f"{what}: end point", value)
    length = wall.length
    if length < EPS:
        raise plan.error(
            f"{what} has zero length: it starts and ends at {_xy(wall.start)}",
            hint="remove it or move one end",
        )
    _positive(plan, f"{what}: thickness", wall.thickness)
    _positive(plan, f"{what}: height", wall.height)
    spans: list[tuple[float, float, int, str]] = []
    for opening in wall.openings:
        name = f"{what}, {opening.kind} '{opening.name}'"
        _positive(plan, f"{name}: width", opening.width)
        _positive(plan, f"{name}: height", opening.height)
        _finite(plan, f"{name}: at", opening.at)
        if opening.sill < 0 or not math.isfinite(opening.sill):
            raise plan.error(f"{name}: sill must be 0 or more, got {opening.sill:g}")
        if opening.width > length + EPS:
            raise plan.error(
                f"{name} is {opening.width:g} m wide but the wall is only {_m(length)} m long",
                hint="make the opening narrower or the wall longer",
            )
        low, high = opening.at - opening.width / 2, opening.at + opening.width / 2
        if low < -EPS or high > length + EPS:
            raise plan.error(
                f"{name} runs past the wall's end (from {_m(low)} to {_m(high)} m along a "
                f"{_m(length)} m wall)",
                hint=f"give 'at' between {_m(opening.width / 2)} and "
                f"{_m(length - opening.width / 2)} m (its centre, from the wall's start)",
            )
        if opening.sill + opening.height > wall.height + EPS:
            raise plan.error(
                f"{name} reaches {opening.sill + opening.height:g} m but the wall is "
                f"{wall.height:g} m high",
                hint="lower the opening or raise the wall",
            )
        clash = _overlapping(spans, low, high)
        if clash is not None:
            other_low, other_high, _, other = clash
            raise plan.error(
                f"{name} overlaps {other} (from {_m(max(low, other_low))} to "
                f"{_m(min(high, other_high))} m along the wall)",
                hint="move one of them",
            )
        bisect.insort(spans, (low, high, len(spans), f"{opening.kind} '{opening.name}'"))


def _overlapping(
    spans: list[tuple[float, float, int, str]], low: float, high: float
) -> tuple[float, float, int, str] | None:
    """The earliest-given span of ``spans`` that ``low``..``high`` overlaps, or None.

    ``spans`` is sorted and its spans do not overlap one another (each was checked when
    added), so only a run of neighbours around ``low`` can overlap: a wall with thousands
    of openings is checked in n log n, not n².
    """
    found = []
    at = bisect.bisect_left(spans, (low,))
    for index in range(at - 1, -1, -1):
        span = spans[index]
        if not (low < span[1] - EPS and span[0] < high - EPS):
            if span[1] < low - EPS:
                break
            continue
        found.append(span)
    for span in spans[at:]:
        if span[0] >= high - EPS:
            break
        if low < span[1] - EPS:
            found.append(span)
    return min(found, key=lambda span: span[2]) if found else None


def _check_crossings(plan: BuildingPlan, level: Level) -> None:
    walls = level.walls
    for i, j in _candidate_pairs(walls):
        a, b = walls[i], walls[j]
        problem = _segments_meet(a, b)
        if problem is None:
            continue
        kind, point = problem
        if a.polyline is not None and a.polyline == b.polyline:
            subject = f"wall '{a.polyline}' crosses itself (segments {a.segment} and {b.segment})"
        else:
            subject = f"{a.label} and {b.label}"
            subject += " cross" if kind == "cross" else " overlap"
        where = f"at {_xy(point)}" if kind == "cross" else f"along the line through {_xy(point)}"
        hint = (
            "split the walls where they cross, so that they meet at end points"
            if kind == "cross"
            else "remove one of them or shorten it"
        )
        raise plan.error(f"level '{level.name}': {subject} {where}", hint=hint)


#: Rows of the pair matrix tested at once (bounds the memory of one block to a few MB).
_BLOCK = 64


def _candidate_pairs(walls: list[Wall]) -> Iterator[tuple[int, int]]:
    """Pairs ``(i, j)``, ``i < j``, in order, whose walls may cross or overlap.

    A vectorised, slightly generous version of :func:`_segments_meet` over all pairs, so
    10,000 walls take seconds, not minutes; each pair it yields is decided exactly by
    :func:`_segments_meet`.
    """
    n = len(walls)
    if n < 2:
        return
    ends = np.array([(*w.start, *w.end) for w in walls], dtype=float)
    p, r = ends[:, :2], ends[:, 2:] - ends[:, :2]
    length = np.hypot(r[:, 0], r[:, 1])
    slack = 2 * EPS  # generous: the exact test decides
    for first in range(0, n, _BLOCK):
        rows = slice(first, min(first + _BLOCK, n))
        pa, ra, la = p[rows, None, :], r[rows, None, :], length[rows, None]
        qp = p[None, first:, :] - pa  # only the pairs' upper triangle: columns from `first`
        s = r[None, first:, :]
        lb = length[None, first:]
        denominator = ra[..., 0] * s[..., 1] - ra[..., 1] * s[..., 0]
        qp_r = qp[..., 0] * ra[..., 1] - qp[..., 1] * ra[..., 0]
        qp_s = qp[..., 0] * s[..., 1] - qp[..., 1] * s[..., 0]
        parallel = np.abs(denominator) <= slack * la * lb + 1e-300
        with np.errstate(divide="ignore", invalid="ignore"):
            t0 = (qp[..., 0] * ra[..., 0] + qp[..., 1] * ra[..., 1]) / (la * la)
            t1 = t0 + (s[..., 0] * ra[..., 0] + s[..., 1] * ra[..., 1]) / (la * la)
            low = np.maximum(0.0, np.minimum(t0, t1))
            high = np.minimum(1.0, np.maximum(t0, t1))
            overlap = parallel & (np.abs(qp_r) <= slack * la) & ((high - low) * la > EPS / 2)
            t = qp_s / denominator
            u = qp_r / denominator
            cross = (
                ~parallel
                & (t > EPS / la / 2)
                & (t < 1 - EPS / la / 2)
                & (u > EPS / lb / 2)
                & (u < 1 - EPS / lb / 2)
            )
        candidates = overlap | cross
        candidates &= np.arange(n - first)[None, :] > np.arange(rows.stop - first)[:, None]
        for i, j in zip(*np.nonzero(candidates), strict=True):
            yield first + int(i), first + int(j)


def _segments_meet(a: Wall, b: Wall) -> tuple[str, tuple[float, float]] | None:
    """('cross', point) when the walls' lines cross inside both, ('overlap', point)
    when they lie on one line and share more than a point, else None. Walls that
    only touch (at an end, or one ending on the other) are fine."""
    p, r = a.start, (a.end[0] - a.start[0], a.end[1] - a.start[1])
    q, s = b.start, (b.end[0] - b.start[0], b.end[1] - b.start[1])
    la, lb = math.hypot(*r), math.hypot(*s)
    denominator = _cross(r, s)
    qp = (q[0] - p[0], q[1] - p[1])
    if abs(denominator) <= EPS * la * lb:  # parallel
        if abs(_cross(qp, r)) > EPS * la:
            return None  # on different lines
        t0 = (qp[0] * r[0] + qp[1] * r[1]) / (la * la)
        t1 = t0 + (s[0] * r[0] + s[1] * r[1]) / (la * la)
        low, high = max(0.0, min(t0, t1)), min(1.0, max(t0, t1))
        if (high - low) * la > EPS:
            return "overlap", (p[0] + low * r[0], p[1] + low * r[1])
        return None
    t = _cross(qp, s) / denominator
    u = _cross(qp, r) / denominator
    inside_a = EPS / la < t < 1 - EPS / la
    inside_b = EPS / lb < u < 1 - EPS / lb
    if inside_a and inside_b:
        return "cross", (p[0] + t * r[0], p[1] + t * r[1])
    return None


def _cross(a: tuple[float, float], b: tuple[float, float]) -> float:
    return a[0] * b[1] - a[1] * b[0]


def _positive(plan: BuildingPlan, what: str, value: float) -> None:
    if not (math.isfinite(value) and value > 0):
        raise plan.error(f"{what} must be a positive number of metres, got {value:g}")
    if value < MIN_PLAN_SIZE:
        raise plan.error(
            f"{what} must be at least {MIN_PLAN_SIZE:g} m, got {value:g}",
            hint="sizes are in metres: 1 mm is the smallest piece a world holds",
        )


def _finite(plan: BuildingPlan, what: str, value: float) -> None:
    if not math.isfinite(value):
        raise plan.error(f"{what} must be a finite number, got {value:g}")


def _xy(point: tuple[float, float]) -> str:
    return f"({_m(point[0])}, {_m(point[1])})"


def _m(value: float) -> str:
    """A length for messages: millimetres at most."""
    return f"{round(value, 3):g}"
