"""``libFollowerPlugin.so``: drive a two-wheeled model towards the nearest thing its depth camera sees.

Behaviour, numbers and assumptions are Gazebo 11's ``FollowerPlugin``
(the model editor tutorial's plugin, Experiment 6 step 26)::

    <plugin name="follower" filename="libFollowerPlugin.so"/>
    <!-- optional: <left_joint>wheel_1_joint</left_joint> <right_joint>wheel_2_joint</right_joint> -->

* **Sensor**: the model's first ``<sensor type="depth">``. Without one the
  plugin is not loaded ("depth sensor not found"). A sensor that is not
  ``<always_on>`` never renders in Gazebo, so the robot never moves; here too
  (with a warning).
* **Wheels**: ``<left_joint>`` and ``<right_joint>`` when both name joints;
  otherwise the model's first two revolute joints, in file order, are left and
  right (the editor's first wheel is the one aligned ``y = max``, the left).
  The wheel separation is the distance between the two joints' anchors, the
  wheel radius half the largest edge of the left wheel's bounding box, both
  measured when the plugin loads.
* **Each depth frame** (the sensor's ``<update_rate>``; every physics step if
  it is 0): in the middle image row (row ``height // 2``) the nearest depth in
  (0.1 m, 5 m) is found. Nothing there, or nearer than 0.4 m: the wheels stop.
  Otherwise, with ``idx`` that pixel's column and ``W`` the image width,
  ``turn = 1 - idx / (W / 2)`` (+1 at the left edge), the yaw rate is
  ``0.1 turn`` rad/s and each wheel's rim speed ``-0.1 -+ 0.1 turn b / 2`` m/s
  (left, right; ``b`` the separation), i.e. joint velocities of that over the
  radius. Gazebo's rim speed is -0.1 m/s because a wheel made as in the
  model editor (a cylinder rolled +90 degrees about x, turning about its own z)
  rolls the robot forward, along +x, when its joint turns negatively.

Gazebo sets the two joint velocities in every physics step from the last
frame; here they are velocity motors (:mod:`workbench.sim.motors`) whose
targets change with each frame, strong enough (:data:`WHEEL_EFFORT_LIMIT`)
that the tyres' grip, not the motor, limits the robot. The depth image is
rendered by Drake's VTK renderer (:class:`~workbench.sim.sensors.Camera`),
headless, once per frame only.
"""

from __future__ import annotations

import contextlib
import logging
import zlib
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.sim.plugins import ModelPlugin, PluginSetupError, SdfElement, UpdateInfo
from workbench.sim.sensors.camera import Camera
from workbench.sim.sensors.spec import CameraSpec, parse_sensor

_LOG = logging.getLogger("workbench.sim.gazebo_plugins")

#: Depths the follower considers, m (exclusive bounds), as Gazebo's.
MIN_RANGE = 0.1
MAX_RANGE = 5.0
#: Nearer than this the wheels stop, m.
STOP_DISTANCE = 0.4
#: Rim speed of both wheels when driving, m/s (negative: forward, see the module docstring).
RIM_SPEED = -0.1
#: Yaw rate when the nearest point is at the image's edge, rad/s.
MAX_TURN_RATE = 0.1
#: Effort limit of each wheel's velocity motor, N m (Gazebo's SetVelocity has none).
WHEEL_EFFORT_LIMIT = 1000.0


def nearest_in_middle_row(depth: np.ndarray) -> tuple[int, float] | None:
    """``(column, depth)`` of the nearest pixel in (MIN_RANGE, MAX_RANGE) of the middle row
    (the leftmost of equals), or None when there is none. ``depth``: (H, W), m."""
    if depth.ndim != 2 or depth.shape[0] == 0 or depth.shape[1] == 0:
        return None
    row = np.asarray(depth[int(depth.shape[0] * 0.5)], dtype=float)
    usable = np.where((row > MIN_RANGE) & (row < MAX_RANGE), row, np.inf)
    column = int(np.argmin(usable))
    if not np.isfinite(usable[column]):
        return None
    return column, float(usable[column])


def wheel_velocities(depth: np.ndarray, separation: float, radius: float) -> tuple[float, float]:
    """``(left, right)`` joint velocities, rad/s, Gazebo's follower gives for one depth image."""
    nearest = nearest_in_middle_row(depth)
    if nearest is None or nearest[1] < STOP_DISTANCE:
        return 0.0, 0.0
    column, _ = nearest
    turn = 1.0 - column / (depth.shape[1] / 2.0)
    yaw_rate = turn * MAX_TURN_RATE
    left = RIM_SPEED + yaw_rate * separation / 2.0
    right = RIM_SPEED - yaw_rate * separation / 2.0
    return left / radius, right / radius


class FollowerPlugin(ModelPlugin):
    """Gazebo's ``FollowerPlugin``: steer towards the nearest point, stop when close.

    After ``load``: ``spec`` (the depth sensor), ``wheels`` (left, right joints),
    ``separation`` and ``radius`` (m); after each frame ``depth`` (the image, m),
    ``nearest`` (column and depth, or None) and ``command`` (left, right rad/s).
    """

    wheels: tuple[str, str] | None = None

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        self.model = model
        where = f"model '{model.name}': follower '{sdf.name}'"
        spec = _depth_sensor(model)
        if spec is None:
            raise PluginSetupError(f'{where}: depth sensor not found (no <sensor type="depth">)')
        self.spec = spec
        wheels = _wheel_joints(model, sdf)
        if wheels is None:
            raise PluginSetupError(
                f"{where}: left or right joint not found (give <left_joint> and <right_joint>, "
                "or two revolute joints)"
            )
        left, right = wheels
        self.separation = float(
            np.linalg.norm(model.joint_anchor(left) - model.joint_anchor(right))
        )
        low, high = model.link_bounding_box(model.joint_links(left)[1])
        self.radius = float(np.max(high - low)) * 0.5  # the wheel's diameter is its largest size
        if self.radius <= 0.0:
            raise PluginSetupError(f"{where}: the left wheel has no size")
        self.camera = Camera(
            spec, seed=zlib.crc32(f"{model.name}::{spec.link}::{spec.name}".encode())
        )
        self.update_rate = spec.update_rate
        if not spec.always_on:
            _LOG.warning(
                "%s: depth sensor '%s' is not <always_on>: it renders no frames (as in Gazebo) "
                "and the robot stays still",
                where,
                spec.name,
            )
        self.depth: np.ndarray | None = None
        self.nearest: tuple[int, float] | None = None
        self.command = (0.0, 0.0)
        model.add_velocity_motors({left: WHEEL_EFFORT_LIMIT, right: WHEEL_EFFORT_LIMIT})
        self.wheels = wheels

    def update(self, info: UpdateInfo) -> None:
        if not self.spec.always_on or self.wheels is None:
            return
        X_WS = self.model.link_pose(self.spec.link).multiply(self.spec.pose())
        frame = self.camera.capture(self.model.server.world, X_WS, color=False)
        assert frame.depth is not None
        self.depth = frame.depth
        self.nearest = nearest_in_middle_row(frame.depth)
        self.command = wheel_velocities(frame.depth, self.separation, self.radius)
        left, right = self.wheels
        self.model.set_motor_velocities({left: self.command[0], right: self.command[1]})

    def reset(self) -> None:
        self.depth, self.nearest, self.command = None, None, (0.0, 0.0)
        self._stop()

    def close(self) -> None:
        with contextlib.suppress(SimulationError):  # the model may be gone already
            self._stop()

    def _stop(self) -> None:
        if self.wheels is not None:
            self.model.set_motor_velocities({joint: 0.0 for joint in self.wheels})


def _depth_sensor(model: Any) -> CameraSpec | None:
    """The model's first depth sensor that parses (bad ones were reported at spawn)."""
    from lxml import etree

    for link, xml in model.sensors():
        if str(etree.fromstring(xml.encode()).get("type", "")).strip() != "depth":
            continue
        try:
            spec = parse_sensor(xml, model=model.name, link=link)
        except SimulationError:
            continue
        if isinstance(spec, CameraSpec):
            return spec
    return None


def _wheel_joints(model: Any, sdf: SdfElement) -> tuple[str, str] | None:
    """``(left, right)``: the named joints, else the first two revolute joints, else None."""
    named = [str(sdf.get(key, "")).strip() for key in ("left_joint", "right_joint")]
    if all(named) and all(model.has_joint(name) for name in named):
        return named[0], named[1]
    revolute = [name for name, kind in model.joints() if kind == "revolute"]
    if len(revolute) < 2:
        return None
    return revolute[0], revolute[1]
