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
from pathlib import Path


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
    parser.add_argument("--seed", type=int, default=0, help="seed of planner, random goal and IK")
    parser.add_argument("--time-limit", type=float, metavar="S", help="planning time limit (s)")
    parser.add_argument(
        "--config",
        metavar="DIR",
        help="planning configuration directory (default: planning/ROBOT/)",
    )
    parser.add_argument("--execute", action="store_true", help="execute the plan in simulation")
    parser.add_argument("--html", metavar="OUT", help="write a Meshcat snapshot with the animation")
    parser.add_argument("--plot", metavar="OUT", help="write a PNG plot of q, qd, qdd vs limits")
    parser.add_argument("--json", metavar="OUT", help="write the trajectory as JSON")
    parser.add_argument("--csv", metavar="OUT", help="write the trajectory as CSV")


def _scene_path(text: str) -> Path:
    from workbench.paths import planning_dir
    from workbench.planning.errors import SceneError

    path = Path(text)
    if path.is_file():
        return path
    for candidate in (planning_dir() / "scenes" / text, planning_dir() / "scenes" / f"{text}.yaml"):
        if candidate.is_file():
            return candidate
    available = sorted(p.stem for p in (planning_dir() / "scenes").glob("*.yaml"))
    raise SceneError(
        f"scene '{text}' not found",
        hint=f"give a YAML path or one of: {', '.join(available) or '(none)'}",
    )


def _load_or_setup(robot: str, config_dir: str | None):
    from workbench.planning.config import ConfigNotFoundError, find_config, load_config
    from workbench.planning.config import config_dir as default_dir
    from workbench.planning.setup import run_setup

    target = Path(config_dir) if config_dir else None
    try:
        return load_config(target if target is not None else robot)
    except ConfigNotFoundError:
        pass
    if target is None:
        try:
            find_config(robot)
        except ConfigNotFoundError:
            target = default_dir(robot)
    print(f"no planning configuration for '{robot}': running setup first (writing {target}/)")
    run_setup(robot, out_dir=target)
    return load_config(target)


def run(args: argparse.Namespace) -> int:
    from workbench.planning.errors import GoalError
    from workbench.planning.output import summary_table, write_csv, write_json
    from workbench.planning.pipeline import MotionPlanner
    from workbench.planning.scene import load_scene

    if args.time_limit is not None and not args.time_limit > 0:
        raise GoalError(f"--time-limit must be positive, got {args.time_limit:g}")
    scene = load_scene(_scene_path(args.scene)) if args.scene else None
    config = _load_or_setup(args.robot, args.config)
    planner = MotionPlanner(config=config, scene=scene, group=args.group)
    result = planner.plan(
        args.to,
        start=args.start,
        planner=args.planner,
        time_limit=args.time_limit,
        seed=args.seed,
    )
    print(f"plan for '{planner.robot.name}' group '{planner.group}' to {args.to}")
    print(summary_table(result))
    if args.json:
        print(f"wrote {write_json(result.trajectory, args.json)}")
    if args.csv:
        print(f"wrote {write_csv(result.trajectory, args.csv)}")
    if args.plot:
        from workbench.planning.output import plot_png

        print(f"wrote {plot_png(result.trajectory, args.plot, planner.lower, planner.upper)}")
    if args.execute:
        from workbench.planning.execute import execute

        report = execute(planner, result)
        print(report.summary())
    if args.html:
        from workbench.planning.output import animate, show_scene
        from workbench.viz import Viewer

        viewer = Viewer.instance()
        show_scene(viewer, planner.scene)
        animate(viewer, planner.robot, planner.joints, result.trajectory)
        print(f"wrote {viewer.save_html(args.html)}")
    return 0
