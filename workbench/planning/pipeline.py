"""The planning pipeline: goal → checks → OMPL → simplification → toppra → exact dense re-check.

>>> from workbench.planning.pipeline import MotionPlanner
>>> planner = MotionPlanner("robot_arm")                 # planning/robot_arm/planning.yaml
>>> result = planner.plan("home", start=q0, seed=1)       # or "random", "q=...", "xyz=..."
>>> result.trajectory.sample([0.0, 0.5])                  # q, qd, qdd

Every returned trajectory has been sampled densely (no joint moves more than
the configuration's edge resolution between samples) and every sample
checked with Drake's exact geometry; its sampled velocities and
accelerations stay within the configured limits. Anything else raises a
:class:`~workbench.errors.PlanningError` subclass saying what failed.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from workbench.optional import require
from workbench.planning import goals as goal_types
from workbench.planning.collision import CollisionWorld
from workbench.planning.errors import (
    GoalError,
    GoalInCollisionError,
    NoPathError,
    StartInCollisionError,
    TrajectoryError,
)
from workbench.planning.ompl_planner import plan as ompl_plan
from workbench.planning.ompl_planner import planner_name
from workbench.planning.scene import PlanningScene, load_scene
from workbench.planning.spheres import SphereChecker
from workbench.planning.timing import TimedTrajectory, time_parameterize
from workbench.planning.validity import Validity

#: Bound used for joints without position limits (continuous joints), radians.
UNLIMITED_BOUND = math.pi
#: Default longest tree extension as a fraction of the joint space's extent (measured on
#: the MotionBenchMaker Panda problems: 0.02-0.05 solve fastest with batched edge checks).
RANGE_FRACTION = 0.04
#: Share of the time limit for planning in the spheres' free space before every sphere
#: rejection is confirmed exactly for the rest (measured on MotionBenchMaker: the spheres'
#: space solves nearly every problem given time; the exact space rescues few, slowly).
SPHERES_SHARE = 0.75
#: Random states tried around a start or goal inside the spheres' margin, and the share of
#: the free ones among them that must be clear of the margin too for the spheres' space to
#: be worth planning in first.
ESCAPE_SAMPLES = 32
ESCAPE_SHARE = 0.25
#: Random states whose sphere and exact answers measure how much of the free space the
#: sphere model keeps, and the least share for planning in the spheres' space first (the
#: Panda keeps about 0.9 of it; a small arm whose links nearly touch in most poses, 0.2).
FIDELITY_SAMPLES = 200
MIN_FIDELITY = 0.5


@dataclass
class PlanResult:
    """A planned, timed and re-checked motion, with what it cost.

    Attributes:
        joint_names: The group's joints (columns of every array).
        start, goal: Group configurations, rad or m.
        path: (k, n) simplified waypoints.
        raw_path: (k0, n) waypoints as the planner returned them.
        trajectory: The timed trajectory.
        planner: OMPL planner name.
        times: Seconds per stage: goal, solve, simplify, timing, recheck, total.
        recheck_samples: How many configurations the final exact check tested.
        recheck_ok: Always True for a returned result (failures raise).
        peak_velocity, peak_acceleration: Largest fraction of a limit over all joints.
        checks: Collision-check counts (sphere, exact, motions).
    """

    joint_names: list[str]
    start: np.ndarray
    goal: np.ndarray
    path: np.ndarray
    raw_path: np.ndarray
    trajectory: TimedTrajectory
    planner: str
    times: dict[str, float]
    recheck_samples: int
    recheck_ok: bool
    peak_velocity: float
    peak_acceleration: float
    checks: dict[str, int] = field(default_factory=dict)

    @property
    def path_length(self) -> float:
        """Joint-space length of the simplified path (Euclidean, rad or m)."""
        return float(np.linalg.norm(np.diff(self.path, axis=0), axis=1).sum())

    @property
    def duration(self) -> float:
        """Duration of the timed trajectory, seconds."""
        return self.trajectory.duration


class MotionPlanner:
    """Plans for one group of one robot in one scene.

    Args:
        robot: A ``urdf/`` name, a description path, or a config directory / planning.yaml.
        config: A loaded :class:`~workbench.planning.config.PlanningConfig` (default: load it
            for ``robot``).
        scene: A :class:`PlanningScene` or the path of a scene YAML file.
        group: Planning group (default: the configuration's).
        use_spheres: Plan with the sphere model (exact geometry still confirms and re-checks).
        description: The robot's :class:`~workbench.model.RobotDescription` (or a loaded
            ``Robot``) to plan for instead of reading the configuration's robot file.
        edge_step: Joint step between collision checks on planner edges (rad or m; default
            the configuration's ``edge_resolution``, which the final re-check always uses).
            A coarser step plans faster; if the re-check then finds a collision the
            request is planned again at the re-check's step.
    """

    def __init__(
        self,
        robot: str | os.PathLike[str] | None = None,
        *,
        config: Any = None,
        scene: PlanningScene | str | os.PathLike[str] | None = None,
        group: str | None = None,
        use_spheres: bool = True,
        edge_step: float | None = None,
        description: Any = None,
    ) -> None:
        from workbench.planning.config import load_config

        if config is None:
            if robot is None:
                raise GoalError("give a robot or a planning configuration")
            config = load_config(robot)
        self.config = config
        if scene is not None and not isinstance(scene, PlanningScene):
            scene = load_scene(scene)
        self.scene = scene if scene is not None else PlanningScene()
        srdf = config.srdf
        disabled = [(d.link1, d.link2) for d in srdf.disabled_collisions]
        self.world = CollisionWorld(
            description if description is not None else config.robot,
            self.scene,
            disabled_pairs=disabled,
            edge_step=config.edge_resolution,
        )
        self.robot = self.world.robot
        self.group = group or config.group
        srdf.group(self.group)  # unknown group -> SrdfError naming the choices
        self.joint_names = srdf.group_joints(self.group, self.robot)
        self.joints = self.world.joint_map(self.joint_names)
        lower, upper = self.world.position_limits()
        self.lower = np.where(np.isfinite(lower), lower, -UNLIMITED_BOUND)[self.joints.indices]
        self.upper = np.where(np.isfinite(upper), upper, UNLIMITED_BOUND)[self.joints.indices]
        self.velocity_limits = np.array(config.velocity_limits(self.joint_names), float)
        self.acceleration_limits = np.array(config.acceleration_limits(self.joint_names), float)
        self.recheck_step = float(config.edge_resolution)
        self.step = float(edge_step) if edge_step else self.recheck_step
        self.spheres = SphereChecker(self.world, self.joints) if use_spheres else None
        self.sphere_fidelity = self._sphere_fidelity() if self.spheres is not None else 0.0
        # toppra's first import takes about a second (it loads matplotlib): pay it here,
        # not inside the first plan's timing.
        require("toppra.algorithm")

    # --- states ---------------------------------------------------------------------------

    def tip_link(self) -> str:
        """The link an ``xyz=`` goal places (the group's tip)."""
        return self.config.srdf.group_tip(self.group, self.robot)

    def named_state(self, name: str) -> np.ndarray:
        """Group values of a named state (joints it omits keep their default)."""
        state = self.config.srdf.group_state(self.group, name)
        q = self.joints.group(self.joints.base).copy()
        for i, joint in enumerate(self.joint_names):
            if joint in state.values:
                value = state.values[joint]
                q[i] = float(value[0] if isinstance(value, list | tuple) else value)
        return q

    def default_start_name(self) -> str | None:
        """The named state a plan starts from by default: ``home``, else ``ready`` (MoveIt's
        Panda), else the group's first named state; None when it has none."""
        names = self.config.srdf.group_state_names(self.group)
        for name in ("home", "ready", *names):
            if name in names:
                return name
        return None

    def default_start(self) -> np.ndarray:
        """The robot's default state (:meth:`default_start_name`), else zeros within limits."""
        name = self.default_start_name()
        if name is not None:
            return self.named_state(name)
        return np.clip(np.zeros(len(self.joint_names)), self.lower, self.upper)

    def is_free(self, q: np.ndarray) -> bool:
        """Exact check of a group configuration."""
        return self.world.is_free(self.joints.full(np.asarray(q, float)))

    def resolve(
        self, goal: goal_types.Goal | str, *, seed: int = 0, start: np.ndarray | None = None
    ) -> np.ndarray:
        """Group joint values for a goal (named, joints, random valid, or a tip position).

        Raises:
            GoalError: Malformed, unknown name, wrong length, outside the limits.
            IKError: No collision-free IK solution.
        """
        from workbench.planning.ik import solve_ik

        if isinstance(goal, str):
            goal = goal_types.parse_goal(goal)
        if isinstance(goal, goal_types.NamedGoal):
            return self.named_state(goal.name)
        if isinstance(goal, goal_types.JointGoal):
            if len(goal.values) != len(self.joint_names):
                raise GoalError(
                    f"group '{self.group}' has {len(self.joint_names)} joints "
                    f"({', '.join(self.joint_names)}), the goal gives {len(goal.values)} values"
                )
            return np.array(goal.values, float)
        if isinstance(goal, goal_types.RandomGoal):
            return goal_types.random_valid_state(self.lower, self.upper, self.is_free, seed)
        if isinstance(goal, goal_types.PositionGoal):
            return solve_ik(
                self.world,
                self.joints,
                self.tip_link(),
                np.array(goal.xyz),
                rpy=None if goal.rpy is None else np.array(goal.rpy),
                seed=seed,
                q_seed=start,
            )
        raise GoalError(f"unsupported goal {goal!r}")

    def _sphere_fidelity(self) -> float:
        """Share of the free space (over seeded random states) the sphere model keeps free."""
        rng = np.random.default_rng(0)
        states = rng.uniform(self.lower, self.upper, size=(FIDELITY_SAMPLES, len(self.lower)))
        free = np.asarray(self.world.configs_free(self.joints.full(states)), dtype=bool)
        if not free.any():
            return 0.0
        return float(np.mean(self.spheres.configs_free(states[free])))

    def _spheres_open(self, q: np.ndarray, reach: float, seed: int) -> bool:
        """Whether the spheres' free space is open around ``q`` (a start or goal).

        A state clear of the spheres is; one inside their margin is when, of the free random
        states within ``reach`` of it, enough are clear of the margin too (near an obstacle,
        moving away clears the margin; between links that nearly touch everywhere, as on a
        small arm, it does not).
        """
        if self.spheres.is_free(q):
            return True
        rng = np.random.default_rng(seed)
        direction = rng.normal(size=(ESCAPE_SAMPLES, len(q)))
        direction /= np.linalg.norm(direction, axis=1)[:, None]
        around = np.clip(q + reach * direction, self.lower, self.upper)
        clear = int(self.spheres.configs_free(around).sum())
        if clear >= ESCAPE_SHARE * len(around) or clear == 0:
            return clear > 0
        free = int(np.sum(self.world.configs_free(self.joints.full(around))))
        return clear >= ESCAPE_SHARE * max(free, 1)

    def _check_state(self, q: np.ndarray, what: str) -> None:
        goal_types.check_limits(self.joint_names, q, self.lower, self.upper, what)
        full = self.joints.full(q)
        if not self.world.is_free(full):
            message = f"the {what} is in collision: {self.world.describe_collision(full)}"
            hint = "move it out of collision or disable the pair in the SRDF if it is expected"
            if what == "start":
                raise StartInCollisionError(message, hint=hint)
            raise GoalInCollisionError(message, hint=hint)

    # --- planning -------------------------------------------------------------------------

    def plan(
        self,
        goal: goal_types.Goal | str | np.ndarray,
        *,
        start: np.ndarray | str | None = None,
        planner: str | None = None,
        time_limit: float | None = None,
        seed: int = 0,
        simplify: bool | str = "shortcut",
        planner_range: float | None = None,
    ) -> PlanResult:
        """Plan, simplify, time and re-check a motion to ``goal``.

        Args:
            goal: A goal object, its command-line text, or group joint values.
            start: Group joint values or a goal text for the start (default: :meth:`default_start`).
            planner: OMPL planner name (default: the configuration's).
            time_limit: Seconds for the planner (default: the configuration's planning_time).
            seed: Seed of the planner, random goals and IK restarts.
            simplify: ``"shortcut"`` (greedy, few checks), True/``"ompl"`` (OMPL's
                PathSimplifier, as MoveIt) or False.
            planner_range: Longest tree extension (joint space, rad or m); None uses
                :data:`RANGE_FRACTION` of the space's extent (OMPL's own default is a fifth,
                which suits cheap per-state checks less than batched edge checks).

        Raises:
            PlanningError subclasses: see the module docstring.
        """
        began = time.perf_counter()
        name = planner_name(planner or self.config.default_planner)
        limit = float(time_limit if time_limit is not None else self.config.planning_time)
        if not limit > 0:
            raise GoalError(f"the time limit must be positive, got {limit:g} s")
        if start is None:
            q_start = self.default_start()
        elif isinstance(start, str):
            q_start = self.resolve(start, seed=seed)
        else:
            q_start = np.asarray(start, float)
        if len(q_start) != len(self.joint_names):
            raise GoalError(
                f"the start has {len(q_start)} values, group '{self.group}' has {len(self.joint_names)} joints"
            )
        self._check_state(q_start, "start")
        if isinstance(goal, np.ndarray | list | tuple):
            goal = goal_types.JointGoal(tuple(float(v) for v in goal))
        q_goal = self.resolve(goal, seed=seed, start=q_start)
        self._check_state(q_goal, "goal")
        t_goal = time.perf_counter() - began

        if planner_range is None:
            planner_range = RANGE_FRACTION * float(np.linalg.norm(self.upper - self.lower))
        # Plan in the spheres' free space first (fast, conservative; a start or goal inside
        # the spheres' margin is confirmed exactly, and so are the samples leading out of it)
        # when the model keeps most of the free space and that space is open around the
        # start and goal; if that finds nothing in its share of the time, confirm every
        # sphere rejection exactly for the rest (the exact free space, slower). The whole
        # search never takes longer than the time limit.
        spheres = self.spheres
        if spheres is None:
            attempts = [(self.step, False, 1.0, None)]
        elif (
            self.sphere_fidelity >= MIN_FIDELITY
            and self._spheres_open(q_start, planner_range, seed)
            and self._spheres_open(q_goal, planner_range, seed + 1)
        ):
            attempts = [(self.step, False, SPHERES_SHARE, spheres), (self.step, True, 1.0, spheres)]
        else:
            attempts = [(self.step, True, 1.0, spheres)]
        solve_time = simplify_time = 0.0
        deadline = time.perf_counter() + limit
        outcome = failure = None
        index = 0
        while outcome is None and index < len(attempts):
            step, confirm, share, model = attempts[index]
            index += 1
            remaining = deadline - time.perf_counter()
            budget = min(share * limit, remaining) if index < len(attempts) else remaining
            if budget <= 0.0:
                break
            validity = Validity(self.world, self.joints, step, model, confirm=confirm)
            validity.trust(q_start, q_goal)
            try:
                result = ompl_plan(
                    self.lower,
                    self.upper,
                    q_start,
                    q_goal,
                    validity.state_valid,
                    motion_valid=validity.motion_valid,
                    planner=name,
                    time_limit=budget,
                    seed=seed,
                    simplify=simplify,
                    planner_range=planner_range,
                )
            except NoPathError:
                solve_time += budget
                failure = None
                continue
            solve_time += result.solve_time
            simplify_time += result.simplify_time
            try:
                outcome = result, self._time_and_recheck(result.path), validity
            except TrajectoryError as error:
                # The edge step missed a thin obstacle: plan again at the re-check's step with
                # every rejection confirmed, and at last with exact geometry only.
                failure = error
                if model is not None and step > self.recheck_step:
                    attempts.append((self.recheck_step, True, 1.0, model))
                elif model is not None:
                    attempts.append((self.recheck_step, True, 1.0, None))
        if outcome is None:
            if failure is not None:
                raise failure
            raise NoPathError(
                f"{name} found no path within the time limit of {limit:g} s",
                hint="allow more time (--time-limit), try another planner, or move obstacles",
            )
        result, (trajectory, recheck_samples, t_timing, t_recheck), validity = outcome
        result.solve_time, result.simplify_time = solve_time, simplify_time
        checks = {
            key: int(getattr(validity, key)) for key in ("sphere_checks", "exact_checks", "motions")
        }
        v_frac, a_frac = trajectory.peak_fractions()
        times = {
            "goal": t_goal,
            "solve": result.solve_time,
            "simplify": result.simplify_time,
            "timing": t_timing,
            "recheck": t_recheck,
        }
        times["total"] = time.perf_counter() - began
        return PlanResult(
            joint_names=list(self.joint_names),
            start=q_start,
            goal=q_goal,
            path=result.path,
            raw_path=result.raw_path,
            trajectory=trajectory,
            planner=name,
            times=times,
            recheck_samples=recheck_samples,
            recheck_ok=True,
            peak_velocity=float(v_frac.max()) if len(v_frac) else 0.0,
            peak_acceleration=float(a_frac.max()) if len(a_frac) else 0.0,
            checks=checks,
        )

    def time(self, path: np.ndarray, spacing: float = 0.5) -> TimedTrajectory:
        """Time a group path with toppra under the configured (scaled) limits."""
        return time_parameterize(
            path,
            self.velocity_limits,
            self.acceleration_limits,
            joint_names=self.joint_names,
            spacing=spacing,
        )

    def _time_and_recheck(self, path: np.ndarray) -> tuple[TimedTrajectory, int, float, float]:
        """Time the path; if the timed curve leaves free space, follow the segments more tightly."""
        t_timing = t_recheck = 0.0
        for spacing in (0.5, 0.1, 0.02):
            began = time.perf_counter()
            trajectory = self.time(path, spacing)
            t_timing += time.perf_counter() - began
            began = time.perf_counter()
            samples, ok = self.recheck(trajectory)
            t_recheck += time.perf_counter() - began
            if ok:
                return trajectory, samples, t_timing, t_recheck
        raise TrajectoryError(
            "the timed trajectory collides in the final exact check even when it follows the "
            "planned segments closely",
            hint="lower edge_resolution in planning.yaml",
        )

    def recheck(self, trajectory: TimedTrajectory) -> tuple[int, bool]:
        """Exact dense check of a timed trajectory: (samples tested, all free).

        Samples are spaced so no joint moves more than the configuration's edge
        resolution between two.
        """
        if trajectory.duration == 0.0:
            return 1, self.is_free(trajectory.waypoints[0])
        # Fine time samples (each moves a joint by at most a quarter step at the velocity
        # limits), thinned to one per 3/4 step of accumulated joint motion: two kept
        # samples are then never more than one step apart.
        dt = min(0.002, 0.25 * self.recheck_step / float(np.max(trajectory.velocity_limits)))
        t = trajectory.times(dt)
        q, _, _ = trajectory.sample(t)
        travelled = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(q, axis=0)).max(axis=1))])
        bucket = np.floor(travelled / (0.75 * self.recheck_step))
        keep = np.nonzero(np.diff(bucket, prepend=-1.0))[0]
        if keep[-1] != len(q) - 1:
            keep = np.append(keep, len(q) - 1)
        dense = q[keep]
        free = self.world.configs_free(self.joints.full(dense))
        limits_ok = np.all(dense >= self.lower - 1e-6) and np.all(dense <= self.upper + 1e-6)
        return len(dense), bool(np.all(free) and limits_ok)
