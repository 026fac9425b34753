"""OMPL geometric planners by name, with path simplification, over a box of joint values.

The state space is OMPL's ``RealVectorStateSpace`` bounded by the group's
joint limits. Validity comes from Python callables: one for a state, and
optionally one for a whole straight motion (so a vectorised checker can test
every step of an edge in one call, installed as an OMPL ``MotionValidator``).
Without a motion callable OMPL's own discrete motion validator steps the
edge at ``resolution`` (a fraction of the space's extent), as MoveIt does.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from workbench.optional import require
from workbench.planning.errors import NoPathError, UnknownPlannerError

#: Planner names accepted (case-insensitive; MoveIt's ``kConfigDefault`` suffix is ignored).
PLANNERS = (
    "RRTConnect",
    "RRT",
    "RRTstar",
    "InformedRRTstar",
    "SORRTstar",
    "AORRTC",
    "PRM",
    "PRMstar",
    "BITstar",
    "FMT",
    "BFMT",
    "KPIECE1",
    "BKPIECE1",
    "LBKPIECE1",
)

#: Planners that keep improving until the time limit (they stop early only when told).
OPTIMIZING = {"RRTstar", "InformedRRTstar", "SORRTstar", "AORRTC", "PRMstar", "BITstar"}


def planner_name(name: str) -> str:
    """The canonical OMPL class name for ``name`` (``rrtconnect``, ``RRTConnectkConfigDefault``).

    Raises:
        UnknownPlannerError: naming the close matches.
    """
    import difflib

    key = name.strip()
    if key.endswith("kConfigDefault"):
        key = key[: -len("kConfigDefault")]
    key = key.replace("*", "star").replace("-", "").replace("_", "").lower()
    for candidate in PLANNERS:
        if candidate.lower() == key:
            return candidate
    close = difflib.get_close_matches(name, PLANNERS, n=3, cutoff=0.5)
    hint = f"did you mean {', '.join(close)}?" if close else f"choose one of {', '.join(PLANNERS)}"
    raise UnknownPlannerError(f"unknown planner '{name}'", hint=hint)


@dataclass
class OmplResult:
    """What the planner found.

    Attributes:
        path: (k, n) waypoints after simplification, start and goal included.
        raw_path: (k0, n) waypoints as the planner returned them.
        planner: Canonical planner name.
        solve_time: Seconds spent in ``solve``.
        simplify_time: Seconds spent simplifying.
    """

    path: np.ndarray
    raw_path: np.ndarray
    planner: str
    solve_time: float
    simplify_time: float


_SEEDED: list[int] = []


def _seed(ou, seed: int) -> None:
    """Seed OMPL's generator; OMPL accepts this once per process, before its first sample.

    Later requests in the same process continue the seeded sequence, so a
    program that plans the same requests in the same order gets the same paths.
    """
    if not _SEEDED:
        ou.RNG.setSeed(int(seed) % (2**31 - 2) + 1)
        _SEEDED.append(int(seed))


def plan(
    lower: np.ndarray,
    upper: np.ndarray,
    start: np.ndarray,
    goal: np.ndarray,
    state_valid: Callable[[np.ndarray], bool],
    *,
    motion_valid: Callable[[np.ndarray, np.ndarray], bool] | None = None,
    resolution: float = 0.005,
    planner: str = "RRTConnect",
    time_limit: float = 1.0,
    seed: int = 0,
    simplify: bool | str = True,
    simplify_time: float = 1.0,
    planner_range: float | None = None,
) -> OmplResult:
    """Plan a collision-free joint path from ``start`` to ``goal``.

    Args:
        lower, upper: (n,) joint bounds, rad or m.
        start, goal: (n,) configurations (checked by the caller).
        state_valid: True when a configuration is free.
        motion_valid: True when the straight motion between two configurations is free;
            None uses OMPL's discrete validator at ``resolution``.
        resolution: OMPL's state validity checking resolution, a fraction of the extent.
        planner: OMPL planner name (see :data:`PLANNERS`).
        time_limit: Seconds allowed for solving.
        seed: Seed of OMPL's random number generator (OMPL takes it once per process;
            see :func:`_seed`).
        simplify: True (or ``"ompl"``): OMPL's PathSimplifier (shortcuts, vertex reduction,
            B-spline smoothing), as MoveIt does; ``"shortcut"``: :func:`shortcut`, a greedy
            pass that needs far fewer motion checks; False: none.
        simplify_time: Seconds allowed for simplifying.
        planner_range: Maximum motion length per tree extension (None: OMPL's default).

    Raises:
        NoPathError: no exact solution within ``time_limit``.
    """
    ob = require("ompl.base")
    og = require("ompl.geometric")
    ou = require("ompl.util")
    name = planner_name(planner)
    ou.setLogLevel(ou.LOG_WARN)
    _seed(ou, seed)
    n = len(lower)
    space = ob.RealVectorStateSpace(n)
    bounds = ob.RealVectorBounds(n)
    for i in range(n):
        bounds.setLow(i, float(lower[i]))
        bounds.setHigh(i, float(upper[i]))
    space.setBounds(bounds)
    si = ob.SpaceInformation(space)

    def to_array(state) -> np.ndarray:
        return np.fromiter((state[i] for i in range(n)), float, n)

    si.setStateValidityChecker(lambda state: bool(state_valid(to_array(state))))
    validator = None
    if motion_valid is not None:

        class _Motion(ob.MotionValidator):
            def checkMotion(self, s1, s2, *rest):  # noqa: N802 (OMPL's name)
                return bool(motion_valid(to_array(s1), to_array(s2)))

        validator = _Motion(si)
        si.setMotionValidator(validator)
    else:
        si.setStateValidityCheckingResolution(float(resolution))
    si.setup()
    setup = og.SimpleSetup(si)
    start_state, goal_state = si.allocState(), si.allocState()
    for i in range(n):
        start_state[i] = float(start[i])
        goal_state[i] = float(goal[i])
    setup.setStartAndGoalStates(start_state, goal_state)
    algorithm = getattr(og, name)(si)
    if planner_range is not None and hasattr(algorithm, "setRange"):
        algorithm.setRange(float(planner_range))
    setup.setPlanner(algorithm)
    setup.setup()
    began = time.perf_counter()
    status = setup.solve(float(time_limit))
    solve_time = time.perf_counter() - began
    if not setup.haveExactSolutionPath():
        raise NoPathError(
            f"{name} found no path within the time limit of {time_limit:g} s ({status.asString()})",
            hint="allow more time (--time-limit), try another planner, or move obstacles",
        )
    path = setup.getSolutionPath()
    raw = _path_array(path, n)
    began = time.perf_counter()
    if simplify == "shortcut":
        motion = motion_valid or (lambda a, b: bool(si.checkMotion(_state(si, a), _state(si, b))))
        simplified = shortcut(raw, motion)
    else:
        if simplify:
            og.PathSimplifier(si).simplify(path, float(simplify_time))
        simplified = _path_array(path, n)
    simplify_seconds = time.perf_counter() - began
    result = OmplResult(simplified, raw, name, solve_time, simplify_seconds)
    # Keep Python-side validator alive until OMPL is done with it.
    del validator
    return result


def shortcut(
    path: np.ndarray, motion_valid: Callable[[np.ndarray, np.ndarray], bool], passes: int = 2
) -> np.ndarray:
    """Greedy shortcutting: from each kept waypoint jump to the farthest one in straight view.

    Each pass first inserts the midpoint of every segment, so later passes can cut
    corners; a pass never makes the path longer.
    """
    path = np.asarray(path, float)
    for k in range(passes):
        if k > 0:
            mids = (path[:-1] + path[1:]) / 2
            dense = np.empty((2 * len(path) - 1, path.shape[1]))
            dense[0::2], dense[1::2] = path, mids
            path = dense
        kept, i = [path[0]], 0
        while i < len(path) - 1:
            for j in range(len(path) - 1, i, -1):
                if j == i + 1 or motion_valid(path[i], path[j]):
                    kept.append(path[j])
                    i = j
                    break
        path = np.array(kept)
    return path


def _state(si, values: np.ndarray):
    state = si.allocState()
    for i, v in enumerate(values):
        state[i] = float(v)
    return state


def _path_array(path, n: int) -> np.ndarray:
    states = [path.getState(i) for i in range(path.getStateCount())]
    return np.array([[state[i] for i in range(n)] for state in states], dtype=float)
