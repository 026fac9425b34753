"""The setup assistant: a robot description in, ``<robot>.srdf`` and ``planning.yaml`` out.

It follows the twelve steps of MoveIt's setup assistant and reports each one
through ``log``:

1. load the robot; 2. self-collision matrix; 3. virtual joint to ``world``;
4. planning groups (the arm chain, the hand); 5. named poses (``home``);
6. end effector; 7. passive joints; 8. 3D perception (not used);
9. simulation (checks that the model can be simulated in ``workbench.sim``);
10. controller for execution; 11. author; 12. write the files.

Given an existing SRDF (e.g. MoveIt's for the Panda) it keeps that file's
groups, states, end effectors and disabled pairs and only adds what is
missing.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from workbench.model.robot_library import library_srdf
from workbench.planning.collision_matrix import compute_collision_matrix, default_state
from workbench.planning.config import (
    DEFAULT_ACCELERATION_TIME,
    DEFAULT_EDGE_RESOLUTION,
    DEFAULT_PLANNER,
    PlanningConfig,
    config_dir,
    default_controller,
    default_joint_limits,
)
from workbench.planning.groups import infer_groups
from workbench.planning.srdf import (
    EndEffector,
    Group,
    GroupState,
    Srdf,
    SrdfError,
    VirtualJoint,
    read_srdf,
)

Log = Callable[[str], None]


def run_setup(
    robot_source: Any,
    out_dir: str | os.PathLike[str] | None = None,
    samples: int = 10000,
    seed: int = 0,
    *,
    srdf: str | os.PathLike[str] | None = None,
    group: str = "arm",
    base_link: str | None = None,
    tip_link: str | None = None,
    hand_links: Sequence[str] | None = None,
    hand: str = "hand",
    poses: Mapping[str, Mapping[str, float] | Sequence[float]] | None = None,
    passive_joints: Sequence[str] = (),
    planner: str = DEFAULT_PLANNER,
    velocity_scaling: float = 1.0,
    acceleration_scaling: float = 1.0,
    edge_resolution: float = DEFAULT_EDGE_RESOLUTION,
    controller_type: str = "inverse_dynamics",
    author: Mapping[str, str] | None = None,
    write: bool = True,
    log: Log | None = None,
) -> PlanningConfig:
    """Write a planning configuration for a robot, as MoveIt's setup assistant does.

    Args:
        robot_source: A ``urdf/`` name, a description path, or a loaded ``Robot``.
        out_dir: Output directory (default ``planning/<robot>/``).
        samples: Random states for the "never in collision" test.
        seed: Seed of those random states.
        srdf: An existing SRDF to start from (its groups, states and disabled
            pairs are kept; the matrix is computed only if it has none).
        group: Name of the arm group (ignored when ``srdf`` defines groups:
            then the first group with a chain, or ``group`` if it exists).
        base_link: Base of the arm chain (default: the root link).
        tip_link: Tip of the arm chain (default: inferred).
        hand_links: Links of the hand group (default: inferred; ``[]`` for none).
        hand: Name of the hand group and its end effector.
        poses: Extra named poses of the arm group: ``{name: {joint: value}}`` or
            ``{name: [one value per arm joint]}`` (rad or m). When the groups are
            inferred, ``home`` defaults to MoveIt's default state.
        passive_joints: Unactuated joints.
        planner: Default OMPL planner.
        velocity_scaling: Fraction of the velocity limits plans may use, (0, 1].
        acceleration_scaling: Fraction of the acceleration limits, (0, 1].
        edge_resolution: Joint-space step between collision checks on an edge (rad).
        controller_type: ``inverse_dynamics`` or ``pid``.
        author: ``{"name": ..., "email": ...}`` (step 11).
        write: Write the files (False: only return the configuration).
        log: Receives one line per step (default: discard).

    Returns:
        The :class:`PlanningConfig` (``collision_matrix`` set when computed).

    Raises:
        SrdfError: A given link, joint or pose does not fit the robot.
        ModelError: The robot cannot be loaded.
    """
    from workbench.model import load_robot

    say = log or (lambda line: None)
    robot = robot_source if hasattr(robot_source, "plant") else load_robot(robot_source)
    robot.finalize()
    movable = robot.movable_joints
    say(
        f"[1/12] Start: loaded '{robot.name}' from {robot.path} "
        f"({len(robot.links)} links, {len(robot.joints)} joints, {len(movable)} movable)"
    )

    if srdf is None and robot.path is not None:
        srdf = library_srdf(Path(robot.path))
        if srdf is not None:
            say(f"        using the SRDF that ships with the description: {srdf}")
    base = read_srdf(srdf) if srdf is not None else None
    if base is not None and base.name != robot.name:
        say(f"        note: the SRDF names robot '{base.name}', the description '{robot.name}'")
    semantic = base if base is not None else Srdf(name=robot.name)
    if base is not None:
        base.validate(robot)

    # Decide groups and poses first so that bad flags fail before the sampling.
    group_lines: list[str] = []
    inferred = not semantic.groups
    if semantic.groups:
        arm = group if group in semantic.group_names else _first_chain_group(semantic)
        for g in semantic.groups:
            joints = semantic.group_joints(g.name, robot)
            group_lines.append(
                f"[4/12] Planning group '{g.name}' (from SRDF): {', '.join(joints) or 'no joints'}"
            )
    else:
        guess = infer_groups(
            robot,
            base_link=base_link,
            tip_link=tip_link,
            hand_links=None if hand_links is None else list(hand_links),
        )
        arm = group
        semantic.groups.append(Group(name=arm, chains=[(guess.base_link, guess.tip_link)]))
        group_lines.append(
            f"[4/12] Planning group '{arm}': chain {guess.base_link} -> {guess.tip_link} "
            f"({len(guess.arm_joints)} joints: {', '.join(guess.arm_joints)})"
        )
        if guess.hand_links:
            semantic.groups.append(Group(name=hand, links=list(guess.hand_links)))
            group_lines.append(
                f"[4/12] Planning group '{hand}': links {', '.join(guess.hand_links)}"
            )
        else:
            group_lines.append("[4/12] No hand group (no finger or gripper joints found)")
        semantic.end_effectors = (
            [EndEffector(hand, hand, guess.tip_link, arm)] if guess.hand_links else []
        )
    arm_joints = semantic.group_joints(arm, robot)
    index = {name: i for i, name in enumerate(robot.joint_names)}
    q_default = default_state(robot.lower_limits, robot.upper_limits)
    wanted: dict[str, Mapping[str, float] | Sequence[float]] = {}
    if inferred and "home" not in semantic.group_state_names(arm):
        wanted["home"] = {j: float(q_default[index[j]]) for j in arm_joints}
    wanted.update(poses or {})
    new_states = [
        GroupState(name, arm, _pose_values(name, values, arm_joints, robot))
        for name, values in wanted.items()
    ]
    for name in passive_joints:
        robot.joint(name)

    # 2. self-collision matrix
    matrix = None
    if base is not None and base.disabled_collisions:
        say(
            f"[2/12] Self-collisions: kept {len(base.disabled_collisions)} disabled pairs "
            f"from {base.path}"
        )
    else:
        matrix = compute_collision_matrix(robot, samples=samples, seed=seed)
        counts = matrix.summary()
        say(
            f"[2/12] Self-collisions: {len(matrix.links)} links with geometry, "
            f"{counts['Total']} pairs, {matrix.sampled} random states (seed {seed}) "
            f"in {matrix.seconds:.2f} s: {counts['Adjacent']} adjacent, {counts['Default']} "
            f"default, {counts['Always']} always, {counts['Never']} never, "
            f"{counts['Check']} to check"
        )
        semantic.disabled_collisions = matrix.disabled()

    # 3. virtual joint
    if not semantic.virtual_joints:
        semantic.virtual_joints = [VirtualJoint("virtual_joint", "fixed", "world", robot.root_link)]
    for vj in semantic.virtual_joints:
        say(f"[3/12] Virtual joint: {vj.name} ({vj.type}) {vj.parent_frame} -> {vj.child_link}")

    # 4. planning groups
    for line in group_lines:
        say(line)

    # 5. poses
    for state in new_states:
        semantic.group_states = [
            s
            for s in semantic.group_states
            if not (s.group == state.group and s.name == state.name)
        ]
        semantic.group_states.append(state)
    for state in semantic.group_states:
        shown = ", ".join(f"{j}={_fmt(v)}" for j, v in state.values.items())
        say(f"[5/12] Pose '{state.name}' of '{state.group}': {shown}")

    # 6. end effectors
    if semantic.end_effectors:
        for ee in semantic.end_effectors:
            say(f"[6/12] End effector '{ee.name}': group '{ee.group}' on link {ee.parent_link}")
    else:
        say("[6/12] End effector: none")

    # 7. passive joints
    for name in passive_joints:
        if name not in semantic.passive_joints:
            semantic.passive_joints.append(name)
    say(f"[7/12] Passive joints: {', '.join(semantic.passive_joints) or 'none'}")
    say("[8/12] 3D perception: none (workbench plans against scene objects, not sensor data)")

    # 9. simulation
    massless = [
        link.name
        for link in robot.links
        if link.mass is None and any(j.child == link.name and j.is_movable for j in robot.joints)
    ]
    if massless:
        say(
            "[9/12] Simulation: links without <inertial> get a nominal inertia in "
            f"workbench.sim: {', '.join(massless)}"
        )
    else:
        say(f"[9/12] Simulation: the description loads in workbench.sim as is ({robot.path.name})")

    # 10. controller
    controller = default_controller(f"{arm}_controller", arm_joints)
    controller["type"] = controller_type
    say(
        f"[10/12] Controller '{controller['name']}' ({controller_type}, kp={controller['gains']['kp']}, "
        f"kd={controller['gains']['kd']}) on {len(arm_joints)} joints"
    )
    say(f"[11/12] Author: {_author_text(author)}")

    all_movable = [j for j in movable if j.name not in semantic.passive_joints]
    config = PlanningConfig(
        robot=Path(robot.path),
        srdf=semantic,
        group=arm,
        joint_limits=default_joint_limits(all_movable),
        velocity_scaling=velocity_scaling,
        acceleration_scaling=acceleration_scaling,
        default_planner=planner,
        edge_resolution=edge_resolution,
        controller=controller,
        author=dict(author or {}),
        collision_matrix=matrix,
    )
    source_name = robot_source if isinstance(robot_source, (str, os.PathLike)) else robot.path
    target = Path(out_dir) if out_dir is not None else config_dir(source_name)
    if write:
        config.save(target, create_parents=out_dir is None)
        say(
            f"[12/12] Wrote {target / (semantic.name + '.srdf')} and {target / 'planning.yaml'} "
            f"(acceleration limits: velocity / {DEFAULT_ACCELERATION_TIME} s)"
        )
    else:
        config.path = target
        say("[12/12] Files not written (write=False)")
    return config


def _first_chain_group(srdf: Srdf) -> str:
    for g in srdf.groups:
        if g.chains:
            return g.name
    return srdf.groups[0].name


def _pose_values(
    name: str, values: Mapping[str, float] | Sequence[float], joints: list[str], robot: Any
) -> dict[str, float]:
    if isinstance(values, Mapping):
        out = {}
        for joint, value in values.items():
            if joint not in joints:
                raise SrdfError(
                    f"pose '{name}' sets joint '{joint}', which is not in the arm group",
                    hint="arm joints: " + ", ".join(joints),
                )
            out[joint] = float(value)
    else:
        seq = list(values)
        if len(seq) != len(joints):
            raise SrdfError(
                f"pose '{name}' has {len(seq)} values; the arm group has {len(joints)} joints",
                hint="arm joints: " + ", ".join(joints),
            )
        out = {joint: float(v) for joint, v in zip(joints, seq, strict=True)}
    index = {j: i for i, j in enumerate(robot.joint_names)}
    lower, upper = robot.lower_limits, robot.upper_limits
    for joint, value in out.items():
        i = index[joint]
        if not (lower[i] - 1e-9 <= value <= upper[i] + 1e-9):
            raise SrdfError(
                f"pose '{name}': {joint}={value:g} is outside its limits "
                f"[{lower[i]:g}, {upper[i]:g}]"
            )
    return out


def _fmt(value: Any) -> str:
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + " ".join(f"{float(v):.4g}" for v in value) + "]"
    return f"{float(value):.4g}"


def _author_text(author: Mapping[str, str] | None) -> str:
    if not author:
        return "not given"
    name = author.get("name", "")
    email = author.get("email", "")
    return f"{name} <{email}>" if email else name
