"""Simulation: a Drake World with ground, obstacles, robots and joint controllers.

``from workbench.sim import World, JointTrajectory, TrackingReport``. The names
are loaded on first use so that importing the package stays cheap.
"""

from __future__ import annotations

from typing import Any

__all__ = ["World", "JointTrajectory", "TrackingReport", "as_joint_trajectory"]


def __getattr__(name: str) -> Any:
    if name == "World":
        from workbench.sim.world import World

        return World
    if name in ("JointTrajectory", "TrackingReport", "as_joint_trajectory"):
        from workbench.sim import trajectory

        return getattr(trajectory, name)
    raise AttributeError(f"module 'workbench.sim' has no attribute '{name}'")
