"""``workbench plan ROBOT --to GOAL`` -- plan, time, re-check and (optionally) execute a motion.

Examples::

    workbench plan robot_arm --to home
    workbench plan robot_arm --to random --seed 3 --json traj.json --plot traj.png
    workbench plan arm3 --to xyz=0.3,0.1,0.4 --scene table --execute --html plan.html

When the robot has no planning configuration yet, the setup assistant runs
first (``workbench setup ROBOT``) and says so.
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any


def configure(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Plan a collision-free motion with OMPL, time it with toppra under the joint "
        "limits, re-check it with exact geometry, and optionally execute it in simulation."
    )
    parser.add_argument("robot", help="a name from urdf/ (robot_arm, arm3) or a description path")
    parser.add_argument(
        "--to",
        required=True,
        metavar="GOAL",
        help="a named state (home), random, q=J1,J2,... (rad/m) or xyz=X,Y,Z[,rpy=R,P,Y] (m, world)",
    )
    parser.add_argument(
        "--from",
        dest="start",
        metavar="START",
        help="start state, same forms as --to (default: home, else zeros)",
    )
    parser.add_argument("--group", help="planning group (default: the configuration's)")
    parser.add_argument(
        "--planner", help="OMPL planner: RRTConnect (default), PRM, RRTstar, BITstar, ..."
    )
    parser.add_argument(
        "--scene", metavar="FILE", help="obstacles: a YAML file or a name in planning/scenes/"
    )
    parser.add_argument(
        "--seed",
        type=int,
        help="seed of planner, random goal and IK (default: a fresh one, printed to repeat the run)",
    )
    parser.add_argument(
        "--time-limit", type=float, metavar="S", help="planning time limit (s, at most 3600)"
    )
    parser.add_argument(
        "--config",
        metavar="DIR",
        help="read the planning configuration from DIR (default: planning/ROBOT/, written by "
        "the setup assistant when missing; write another with: workbench setup ROBOT -o DIR)",
    )
    parser.add_argument("--execute", action="store_true", help="execute the plan in simulation")
    parser.add_argument("--html", metavar="OUT", help="write a Meshcat snapshot with the animation")
    parser.add_argument("--plot", metavar="OUT", help="write a PNG plot of q, qd, qdd vs limits")
    parser.add_argument("--json", metavar="OUT", help="write the trajectory as JSON")
    parser.add_argument("--csv", metavar="OUT", help="write the trajectory as CSV")


def run(args: argparse.Namespace) -> int:
    seed = args.seed
    if seed is None:
        # like MoveIt's "random valid", a new draw each run; printed so it can be repeated
        import secrets

        seed = secrets.randbelow(2**31)
    start = args.start
    notes = [] if args.seed is not None else [f"seed: {seed} (repeat this run with --seed {seed})"]
    return plan(
        args.robot,
        args.to,
        start=start,
        group=args.group,
        planner=args.planner,
        scene=args.scene,
        seed=seed,
        time_limit=args.time_limit,
        config_dir=args.config,
        execute=args.execute,
        html=args.html,
        plot=args.plot,
        json_out=args.json,
        csv_out=args.csv,
        notes=notes,
    )


def scene_path(text: str) -> Path:
    """A scene YAML given as a path or as a name in ``planning/scenes/``.

    Raises:
        SceneError: Neither exists; names the available scenes.
    """
    from workbench.paths import is_file, planning_dir
    from workbench.planning.errors import SceneError

    path = Path(text)
    if is_file(path):
        return path
    for candidate in (planning_dir() / "scenes" / text, planning_dir() / "scenes" / f"{text}.yaml"):
        if is_file(candidate):
            return candidate
    available = sorted(p.stem for p in (planning_dir() / "scenes").glob("*.yaml"))
    raise SceneError(
        f"scene '{text}' not found",
        hint=f"give a YAML path or one of: {', '.join(available) or '(none)'}",
    )


#: Output option -> the kind of file it writes (see :mod:`workbench.output_files`).
OUTPUT_KINDS = {
    "--html": "html-snapshot",
    "--plot": "png",
    "--json": "trajectory-json",
    "--csv": "trajectory-csv",
}
#: Longest planning time a request may ask for, s.
MAX_TIME_LIMIT = 3600.0


def check_options(
    goal: str,
    *,
    start: str | None = None,
    planner: str | None = None,
    seed: int = 0,
    time_limit: float | None = None,
    outputs: Mapping[str, str | None] | None = None,
) -> str | None:
    """The checks that need no robot: goal syntax, planner name, numbers, output files.

    Args:
        outputs: Option (``--json``, a key of :data:`OUTPUT_KINDS`) -> the file it names.

    Returns:
        The canonical planner name, or None for the configuration's default.

    Raises:
        GoalError: A malformed goal or start, a seed outside 0..2^32-1, or a time limit
            that is not a positive number of at most an hour.
        UnknownPlannerError: An unknown planner (naming close matches).
        PlanningError: An output's folder does not exist, it names a directory, device or
            someone else's file, a plot that is not ``.png``, or two outputs name one file.
    """
    from workbench.errors import PlanningError
    from workbench.limits import MAX_SEED
    from workbench.output_files import check_output
    from workbench.planning.errors import GoalError
    from workbench.planning.goals import parse_goal
    from workbench.planning.ompl_planner import planner_name

    if time_limit is not None and not 0 < time_limit <= MAX_TIME_LIMIT:
        raise GoalError(
            f"--time-limit must be a positive number of seconds up to {MAX_TIME_LIMIT:g}, "
            f"got {time_limit:g}"
        )
    if seed < 0:
        raise GoalError(f"--seed must not be negative, got {seed}")
    if seed > MAX_SEED:
        raise GoalError(f"--seed must be at most {MAX_SEED} (32 bits), got {seed}")
    parse_goal(goal)
    if start is not None:
        parse_goal(start)
    named: dict[Path, str] = {}
    for option, out in (outputs or {}).items():
        if out is None:
            continue
        if option == "--plot" and Path(out).suffix.lower() != ".png":
            raise PlanningError(
                f"--plot {out}: the plot is a PNG image", hint="give a file name ending in .png"
            )
        path = check_output(out, OUTPUT_KINDS[option], option=option, error=PlanningError)
        key = path.resolve()
        if key in named:
            raise PlanningError(
                f"{named[key]} and {option} both name {out}", hint="give each its own file"
            )
        named[key] = option
    return planner_name(planner) if planner is not None else None


def plan(
    robot: str,
    goal: str,
    *,
    start: str | None = None,
    group: str | None = None,
    planner: str | None = None,
    scene: str | None = None,
    seed: int = 0,
    time_limit: float | None = None,
    config_dir: str | None = None,
    execute: bool = False,
    html: str | None = None,
    plot: str | None = None,
    json_out: str | None = None,
    csv_out: str | None = None,
    notes: Sequence[str] = (),
) -> int:
    """Plan, time and re-check a motion of ``robot`` to ``goal``; optionally execute it.

    Everything that can be checked without Drake (goal and start syntax, named states,
    joint count and limits, planner name, scene file, numbers, output folders) is checked
    before the planner is built, so a bad request fails within a second.

    Args:
        robot: A ``urdf/`` name or a description path.
        goal: ``home`` (a named state), ``random``, ``q=J1,...`` (rad or m) or
            ``xyz=X,Y,Z[,rpy=R,P,Y]`` (m, rad; world frame).
        start: The start, same forms (default: ``home``, else zeros).
        group: Planning group (default: the configuration's).
        planner: OMPL planner (default: the configuration's).
        scene: Obstacles: a YAML path or a name in ``planning/scenes/``.
        seed: Seed of the planner, a random goal and IK.
        time_limit: Planning time limit, s.
        config_dir: Planning configuration directory (default ``planning/ROBOT/``); written
            by the setup assistant first when missing.
        execute: Execute the plan in simulation.
        html: Write a Meshcat snapshot with the animation here.
        plot: Write a PNG of q, qd, qdd against the limits here.
        json_out, csv_out: Write the trajectory as JSON / CSV here.
        notes: Lines printed once the request is valid (the seed drawn, the start chosen).

    Raises:
        PlanningError: The request is invalid or no plan was found (a subclass says which).
    """
    from workbench.planning.goals import check_goal, group_outline

    planner = check_options(
        goal,
        start=start,
        planner=planner,
        seed=seed,
        time_limit=time_limit,
        outputs={"--html": html, "--plot": plot, "--json": json_out, "--csv": csv_out},
    )
    from workbench.planning.scene import load_scene

    obstacles = load_scene(scene_path(scene)) if scene else None
    config = _load_or_setup(robot, config_dir)
    outline = group_outline(config, group)
    if outline is not None:
        check_goal(goal, outline)
        if start is not None:
            check_goal(start, outline, "start")

    from workbench.planning.output import summary_table, write_csv, write_json
    from workbench.planning.pipeline import MotionPlanner

    motion = MotionPlanner(config=config, scene=obstacles, group=group)
    if start is None and goal == motion.default_start_name():
        # the default start is the goal: a plan to it starts somewhere else
        start = "random"
        notes = [*notes, f"start: random (the goal is {goal}, the default start)"]
    for note in notes:
        print(note)
    result = motion.plan(goal, start=start, planner=planner, time_limit=time_limit, seed=seed)
    print(f"plan for '{motion.robot.name}' group '{motion.group}' to {goal}")
    print(summary_table(result))
    if json_out:
        print(f"wrote {write_json(result.trajectory, json_out)}")
    if csv_out:
        print(f"wrote {write_csv(result.trajectory, csv_out)}")
    if plot:
        from workbench.planning.output import plot_png

        print(f"wrote {plot_png(result.trajectory, plot, motion.lower, motion.upper)}")
    report = _execute(motion, result) if execute else None
    if html:
        from workbench.planning.output import animate, animate_samples, show_scene
        from workbench.viz import Viewer

        viewer = Viewer.instance()
        show_scene(viewer, motion.scene)
        if report is not None:  # what the robot did, not what was asked of it
            animate_samples(viewer, motion.robot, motion.joints, report.t, report.q_actual)
        else:
            animate(viewer, motion.robot, motion.joints, result.trajectory)
        print(f"wrote {viewer.save_html(html)}")
    return 0


def _execute(motion: Any, result: Any) -> Any:
    """Run the plan in simulation; with a core running, move the robot there in real time.

    Like MoveIt's fake execution, ``/joint_states`` goes out at wall-clock pace and wall
    time stamps, so robot_state_publisher, ``workbench rviz`` and ``topic echo`` in other
    terminals see the arm move. Without a core there is nobody to tell, so the run goes
    as fast as it computes.
    """
    from workbench.bus import Bus
    from workbench.planning.execute import execute as execute_plan

    bus = Bus.auto(quiet=True)
    try:
        live = bool(getattr(bus, "is_connected", False))
        if live:
            print(f"executing in real time, publishing /joint_states on {bus.uri}", flush=True)
        report = execute_plan(motion, result, bus=bus if live else None, realtime=live)
    finally:
        bus.shutdown()
    print(report.summary())
    return report


def _load_or_setup(robot: str, config_dir: str | None):
    """The robot's planning configuration; the setup runs first only for the default folder.

    A folder given with ``--config`` is read, never written: the setup assistant
    writes where ``workbench setup -o DIR`` is told to.
    """
    from workbench.errors import PlanningError
    from workbench.model.sources import resolve_robot_path
    from workbench.planning.config import ConfigNotFoundError, load_config
    from workbench.planning.config import config_dir as default_dir
    from workbench.planning.setup import run_setup

    if config_dir is not None and not str(config_dir).strip():
        raise PlanningError("--config needs the folder of a planning configuration")
    if config_dir:
        target = Path(config_dir)
        try:
            return load_config(target)
        except ConfigNotFoundError:
            resolve_robot_path(robot)  # an unknown robot fails here, naming the available ones
            raise ConfigNotFoundError(
                f"no planning configuration in {target} (no {target / 'planning.yaml'})",
                hint=f"write one with: workbench setup {robot} -o {target}",
            ) from None
    try:
        return load_config(robot)
    except ConfigNotFoundError:
        pass
    resolve_robot_path(robot)  # an unknown robot fails here, naming the available ones
    target = default_dir(robot)
    print(f"no planning configuration for '{robot}': running setup first (writing {target}/)")
    run_setup(robot)
    return load_config(target)
