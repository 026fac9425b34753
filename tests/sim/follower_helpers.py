"""The manual's simpledoifffbot (Experiment 6) with a box to follow, in a SimServer run as fast as it can.

The robot is built by examples/gazebo/build_simpledoifffbot.py with a smaller
depth image (80 x 60; the shipped model has the database camera's 320 x 240)
so that a minute of simulated driving renders in seconds.
"""

from __future__ import annotations

import math
import runpy
from pathlib import Path
from typing import Any

import numpy as np
from sim_helpers import box_model

from workbench.sim import World
from workbench.sim.loading import load_sim_model
from workbench.sim.model_spec import SimModel
from workbench.sim.server import SERVER_PHYSICS, SimServer
from workbench.spatial import rigid_transform

SCRIPT = Path(__file__).resolve().parents[2] / "examples" / "gazebo" / "build_simpledoifffbot.py"
ROBOT = "simpledoifffbot"
BOX = "obstacle"
BOX_SIZE = (0.4, 0.4, 1.0)  # tall enough to cross the camera's middle row (0.43 m up)
IMAGE = (80, 60)


def follower_model(folder: Path, **parameters: str) -> SimModel:
    """The test robot, its follower plugin given ``<key>value</key>`` parameters."""
    robot = runpy.run_path(str(SCRIPT))["build"](image=IMAGE, **parameters)
    return load_sim_model(robot.save(folder / f"{ROBOT}.sdf"))


class FollowRig:
    """The robot at the origin facing +x, and a free 40 kg box placed with :meth:`place_box`."""

    def __init__(self, model: SimModel, box_xy: tuple[float, float] | None) -> None:
        self.world = World(**SERVER_PHYSICS)
        self.server = SimServer(self.world, real_time_factor=0)
        self.server.spawn(model, [0.0, 0.0, 0.0])
        self.server.spawn(box_model(BOX, BOX_SIZE, mass=40.0), [50.0, 50.0, BOX_SIZE[2] / 2])
        if box_xy is not None:
            self.place_box(*box_xy)
        self.plugin = next(p for p in self.server.plugins if type(p).__name__ == "FollowerPlugin")

    def camera(self) -> np.ndarray:
        """The depth camera link's origin in W (the sensor sits there)."""
        X = self.world.plant.EvalBodyPoseInWorld(
            self.world.plant.GetMyContextFromRoot(self.world.context),
            self.world.body(f"{ROBOT}::depth_camera"),
        )
        return np.array(X.translation())

    def heading(self) -> float:
        """Yaw of the robot, rad."""
        return float(self.world.get_model_pose(ROBOT).rotation().ToRollPitchYaw().yaw_angle())

    def speed(self) -> float:
        """Horizontal speed of the chassis, m/s."""
        return float(np.linalg.norm(self.world.get_model_twist(ROBOT)[0][:2]))

    def ahead(self, forward: float, left: float) -> tuple[float, float]:
        """The point ``forward`` m ahead of the camera and ``left`` m to its left, in W (x, y)."""
        c, yaw = self.camera(), self.heading()
        return (
            c[0] + forward * math.cos(yaw) - left * math.sin(yaw),
            c[1] + forward * math.sin(yaw) + left * math.cos(yaw),
        )

    def place_box(self, x: float, y: float) -> None:
        """Teleport the box (standing, at rest) so its centre is at ``(x, y)``."""
        self.server.call(
            lambda: self.world.set_model_state(
                BOX, rigid_transform([x, y, BOX_SIZE[2] / 2]), [0, 0, 0], [0, 0, 0]
            )
        )

    def box_xy(self) -> np.ndarray:
        return np.array(self.world.get_model_pose(BOX).translation()[:2])

    def gap(self) -> float:
        """Horizontal distance from the camera to the box's nearest side, m."""
        local = self.camera()[:2] - self.box_xy()
        yaw = self.world.get_model_pose(BOX).rotation().ToRollPitchYaw().yaw_angle()
        c, s = math.cos(yaw), math.sin(yaw)
        in_box = np.array([c * local[0] + s * local[1], -s * local[0] + c * local[1]])
        outside = np.maximum(np.abs(in_box) - np.array(BOX_SIZE[:2]) / 2.0, 0.0)
        return float(np.linalg.norm(outside))

    def bearing(self) -> float:
        """Angle from the robot's heading to the box's centre as the camera sees it, rad (+: left)."""
        d = self.box_xy() - self.camera()[:2]
        return _wrap(math.atan2(d[1], d[0]) - self.heading())

    def run(self, seconds: float) -> None:
        self.server.run(until=self.world.time + seconds)

    def run_until_stopped(self, limit: float) -> float:
        """Run until the follower has commanded a stop for 1 s (or ``limit`` s passed); the time taken."""
        start = self.world.time
        stopped_since: float | None = None
        while self.world.time - start < limit:
            self.run(0.25)
            if self.plugin.command == (0.0, 0.0):
                stopped_since = self.world.time if stopped_since is None else stopped_since
                if self.world.time - stopped_since >= 1.0:
                    break
            else:
                stopped_since = None
        return self.world.time - start

    def close(self) -> None:
        self.server.stop()


def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def counting(camera: Any) -> list[float]:
    """Record the simulated time of every render of ``camera`` (a Camera) from now on."""
    times: list[float] = []
    original = camera.capture

    def capture(world: Any, X_WS: Any, **options: Any) -> Any:
        times.append(float(world.time))
        return original(world, X_WS, **options)

    camera.capture = capture
    return times
