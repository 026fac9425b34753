"""``workbench setup ROBOT`` -- the MoveIt setup assistant on the command line.

Writes ``planning/ROBOT/ROBOT.srdf`` and ``planning/ROBOT/planning.yaml`` and
prints the twelve steps it performed.
"""

from __future__ import annotations

import argparse
import math

from workbench.errors import PlanningError
from workbench.limits import MAX_SEED

#: Most collision-matrix samples (--samples).
MAX_SAMPLES = 1_000_000

CONTROLLERS = ("inverse_dynamics", "pid")


def configure(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Write a planning configuration (SRDF + planning.yaml) for a robot: self-collision "
        "matrix, virtual joint, planning groups, named poses, end effector, controller."
    )
    parser.add_argument("robot", help="a name from urdf/ (robot_arm, arm3) or a description path")
    parser.add_argument(
        "-o", "--output", metavar="DIR", help="output directory (default: planning/ROBOT/)"
    )
    parser.add_argument(
        "--samples", type=int, default=10000, help="random states for the collision matrix"
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of the random states")
    parser.add_argument(
        "--srdf", metavar="FILE", help="start from an existing SRDF (e.g. MoveIt's for the Panda)"
    )
    parser.add_argument("--group", default="arm", help="name of the arm group (default: arm)")
    parser.add_argument("--base", metavar="LINK", help="base link of the arm chain")
    parser.add_argument("--tip", metavar="LINK", help="tip link of the arm chain")
    parser.add_argument(
        "--hand-links", metavar="L1,L2", help="links of the hand group (default: inferred)"
    )
    parser.add_argument("--no-hand", action="store_true", help="define no hand group")
    parser.add_argument("--hand", default="hand", help="name of the hand group and end effector")
    parser.add_argument(
        "--pose",
        action="append",
        default=[],
        metavar="NAME=V1,V2,...",
        help="a named pose of the arm group, one value per arm joint (rad or m); repeatable",
    )
    parser.add_argument(
        "--passive", action="append", default=[], metavar="JOINT", help="a passive joint"
    )
    parser.add_argument("--planner", default="RRTConnect", help="default OMPL planner")
    parser.add_argument("--velocity-scaling", type=float, default=1.0)
    parser.add_argument("--acceleration-scaling", type=float, default=1.0)
    parser.add_argument(
        "--edge-resolution",
        type=float,
        default=0.01,
        help="joint-space step between edge checks (rad)",
    )
    parser.add_argument("--controller", choices=CONTROLLERS, default="inverse_dynamics")
    parser.add_argument("--author", metavar="'NAME <EMAIL>'", help="author information")
    parser.add_argument(
        "--matrix", action="store_true", help="also print the whole self-collision matrix"
    )
    parser.add_argument("--dry-run", action="store_true", help="print the steps, write nothing")


def run(args: argparse.Namespace) -> int:
    hand_links = None
    if args.no_hand:
        hand_links = []
    elif args.hand_links:
        hand_links = [name.strip() for name in args.hand_links.split(",") if name.strip()]
    return setup(
        args.robot,
        output=args.output,
        samples=args.samples,
        seed=args.seed,
        srdf=args.srdf,
        group=args.group,
        base=args.base,
        tip=args.tip,
        hand_links=hand_links,
        hand=args.hand,
        poses=dict(_parse_pose(text) for text in args.pose),
        passive=args.passive,
        planner=args.planner,
        velocity_scaling=args.velocity_scaling,
        acceleration_scaling=args.acceleration_scaling,
        edge_resolution=args.edge_resolution,
        controller=args.controller,
        author=_parse_author(args.author),
        matrix=args.matrix,
        dry_run=args.dry_run,
    )


def setup(
    robot: str,
    *,
    output: str | None = None,
    samples: int = 10000,
    seed: int = 0,
    srdf: str | None = None,
    group: str = "arm",
    base: str | None = None,
    tip: str | None = None,
    hand_links: list[str] | None = None,
    hand: str = "hand",
    poses: dict[str, list[float]] | None = None,
    passive: list[str] | None = None,
    planner: str = "RRTConnect",
    velocity_scaling: float = 1.0,
    acceleration_scaling: float = 1.0,
    edge_resolution: float = 0.01,
    controller: str = "inverse_dynamics",
    author: dict[str, str] | None = None,
    matrix: bool = False,
    dry_run: bool = False,
) -> int:
    """The setup assistant: write ``planning/ROBOT/ROBOT.srdf`` and ``planning.yaml``.

    The options are checked (numbers, planner name, files, the robot's name) before the
    collision matrix is sampled. See ``workbench setup --help`` for each option; joint
    values are rad or m, ``edge_resolution`` is rad.

    Args:
        hand_links: Links of the hand group; ``[]`` for none, None to infer them.
        poses: Named arm poses, one value per arm joint.
        matrix: Also print the whole self-collision matrix.
        dry_run: Print the steps, write nothing.

    Raises:
        PlanningError: A bad option, an unknown robot or planner, or a setup step failed.
    """
    from workbench.model.limits import name_problem, shown_name
    from workbench.model.sources import resolve_robot_path
    from workbench.planning.ompl_planner import planner_name
    from workbench.planning.setup import run_setup

    if not 0 <= samples <= MAX_SAMPLES:
        raise PlanningError(f"--samples must be 0 to {MAX_SAMPLES:,}, got {samples}")
    if not 0 <= seed <= MAX_SEED:
        raise PlanningError(f"--seed must be 0 to 2^32 - 1, got {seed}")
    for option, name in (("--group", group), ("--hand", hand)):
        problem = name_problem(name)
        if problem is not None:
            raise PlanningError(f"{option} '{shown_name(name)}' {problem}")
    if output is not None and not output.strip():
        raise PlanningError("-o needs the folder to write the configuration into")
    for name, value in (
        ("velocity-scaling", velocity_scaling),
        ("acceleration-scaling", acceleration_scaling),
    ):
        if not 0 < value <= 1:
            raise PlanningError(f"--{name} must be in (0, 1], got {value}")
    if not 0 < edge_resolution <= math.pi:
        raise PlanningError(
            f"--edge-resolution must be above 0 and at most pi rad, got {edge_resolution}"
        )
    if controller not in CONTROLLERS:
        raise PlanningError(
            f"unknown controller '{controller}'", hint=f"use one of {', '.join(CONTROLLERS)}"
        )
    planner = planner_name(planner)
    resolve_robot_path(robot)
    if output is not None and not dry_run:
        from pathlib import Path

        from workbench.planning.config import check_config_dir

        check_config_dir(Path(output))
    config = run_setup(
        robot,
        out_dir=output,
        samples=samples,
        seed=seed,
        srdf=srdf,
        group=group,
        base_link=base,
        tip_link=tip,
        hand_links=hand_links,
        hand=hand,
        poses=poses or {},
        passive_joints=passive or [],
        planner=planner,
        velocity_scaling=velocity_scaling,
        acceleration_scaling=acceleration_scaling,
        edge_resolution=edge_resolution,
        controller_type=controller,
        author=author,
        write=not dry_run,
        log=print,
    )
    if matrix and config.collision_matrix is not None:
        print(format_matrix(config.collision_matrix))
    return 0


def format_matrix(matrix) -> str:
    """The collision matrix as an aligned text table (one row per link pair)."""
    rows = matrix.rows()
    w1 = max([len("link 1")] + [len(r["link1"]) for r in rows])
    w2 = max([len("link 2")] + [len(r["link2"]) for r in rows])
    lines = [f"{'link 1':<{w1}}  {'link 2':<{w2}}  {'reason':<8}  in collision"]
    for r in rows:
        lines.append(
            f"{r['link1']:<{w1}}  {r['link2']:<{w2}}  {r['reason'] or 'check':<8}  "
            f"{100 * r['collision_fraction']:6.2f} %"
        )
    return "\n".join(lines)


def _parse_pose(text: str) -> tuple[str, list[float]]:
    name, sep, values = text.partition("=")
    if not sep or not name:
        raise PlanningError(f"--pose '{text}' must look like NAME=V1,V2,...")
    try:
        return name, [float(v) for v in values.split(",") if v.strip()]
    except ValueError:
        raise PlanningError(f"--pose '{text}': the values must be numbers (rad or m)") from None


def _parse_author(text: str | None) -> dict[str, str] | None:
    if not text:
        return None
    if "<" in text and text.rstrip().endswith(">"):
        name, _, email = text.rstrip()[:-1].partition("<")
        return {"name": name.strip(), "email": email.strip()}
    return {"name": text.strip()}
