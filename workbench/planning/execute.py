"""Execute a planned trajectory in a ``workbench.sim`` World and report how well it was tracked.

The World holds the robot (root welded at the origin, as in planning), the
planning scene's obstacles and the joint-level controller named in
``planning.yaml`` (setup step 10). The robot starts at rest at the plan's
start, the controller follows the timed trajectory, and ``/joint_states``
is published when a bus is given. The World has no ground: the plan was
checked against the planning scene only, so the simulation holds the same
obstacles.
"""

from __future__ import annotations

from typing import Any

from workbench.planning.output import trajectory_samples


def execute(
    planner,
    result,
    *,
    bus: Any = None,
    time_step: float = 0.001,
    settle_time: float = 0.5,
    realtime: bool = False,
):
    """Track ``result``'s trajectory in simulation.

    Args:
        planner: The :class:`~workbench.planning.pipeline.MotionPlanner` that planned it.
        result: The :class:`~workbench.planning.pipeline.PlanResult`.
        bus: A ``workbench.bus.Bus`` for ``/joint_states`` (and ``/clock`` unless
            ``realtime``), or None.
        time_step: Simulation step, s.
        settle_time: Simulated time after the end of the motion, s.
        realtime: Run at wall-clock pace and stamp ``/joint_states`` with wall time, no
            ``/clock`` (as MoveIt's fake controllers move the robot in RViz).

    Returns:
        The World's ``TrackingReport`` (max, RMS and final error per joint).
    """
    from workbench.sim import World

    controller = planner.config.controller or {}
    world = World(
        time_step=time_step,
        bus=bus,
        ground=False,
        clock=not realtime,
        realtime_rate=1.0 if realtime else 0.0,
    )
    robot = world.add_robot(
        planner.robot,  # its description: the file is not read again
        controller=controller.get("type", "inverse_dynamics"),
        gains=controller.get("gains"),
    )
    for obj in planner.scene:
        world.add_shape(obj.name, obj.shape, obj.X_WO)
    world.build()
    world.set_positions(robot.name, planner.joints.full(result.start))
    return world.track_trajectory(
        robot.name, trajectory_samples(result.trajectory), settle_time=settle_time
    )
