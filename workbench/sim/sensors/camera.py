"""Colour and depth cameras (Gazebo's ``camera`` and ``depth`` sensors) rendered by Drake.

Usable without a server::

    camera = Camera(parse_sensor(xml, model="bot", link="camera_link"))
    frame = camera.capture(world, X_WS)      # frame.color (H, W, 3) uint8, frame.depth (H, W) m

The World gets a ``RenderEngineVtk`` (:meth:`workbench.sim.World.add_renderer`)
the first time a camera renders in it.

Geometry, as Gazebo's camera: the sensor frame S looks along its +x with +z up;
pixel column i (row j) sees along ``atan((i - (W - 1) / 2) / f)`` with
``f = W / (2 tan(hfov / 2))`` and square pixels, i.e. the principal point is
the image centre. Drake renders in its camera frame C (z forward, x right, y
down: ``X_SC = rpy(-pi/2, 0, -pi/2)``, the usual ``*_optical_frame`` rotation)
with ``cx = W / 2``, ``cy = H / 2`` in its own convention (pixel i's centre at
i + 0.5), which is that same image: with drake 1.51 the depth of a tilted
plane matches the analytic value at the pixel centres to 4e-6 m (no half-pixel
correction is needed; tests/sim/test_sensors_camera.py checks it).

Depth is the distance along the optical axis (as Gazebo's depth camera and
OpenNI). Pixels nearer than ``<clip><near>`` read 0, beyond ``<far>`` +inf
(Drake's convention); the ROS plugins map both to NaN as Gazebo's do.
``<noise>`` (Gaussian) is added to every colour channel (in units of full
scale, as Gazebo) and to finite depths (m), from a seeded generator.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from workbench.sim.sensors.spec import CameraSpec

#: The render engine cameras use in a World.
RENDERER = "workbench_vtk"


@dataclass
class CameraFrame:
    """One capture: ``color`` (H, W, 3) uint8 in the spec's channel order, ``depth`` (H, W) float32 m."""

    color: np.ndarray | None
    depth: np.ndarray | None
    time: float = 0.0


class Camera:
    """Images of one ``camera``/``depth`` sensor.

    Args:
        spec: The sensor (see :func:`workbench.sim.sensors.parse_sensor`).
        seed: Seed of the noise generator.
    """

    def __init__(self, spec: CameraSpec, seed: int = 0) -> None:
        self.spec = spec
        self._rng = np.random.default_rng(seed)
        self._cameras: tuple[Any, Any] | None = None

    @property
    def K(self) -> np.ndarray:
        """The intrinsic matrix of the rendered image in ROS's convention (pixel i's centre at i)."""
        f = self.spec.focal_length
        return np.array(
            [
                [f, 0.0, (self.spec.width - 1) / 2.0],
                [0.0, f, (self.spec.height - 1) / 2.0],
                [0.0, 0.0, 1.0],
            ]
        )

    def _render_cameras(self) -> tuple[Any, Any]:
        if self._cameras is None:
            from pydrake.geometry import (
                ClippingRange,
                ColorRenderCamera,
                DepthRange,
                DepthRenderCamera,
                RenderCameraCore,
            )
            from pydrake.math import RigidTransform
            from pydrake.systems.sensors import CameraInfo

            spec = self.spec
            f = spec.focal_length
            info = CameraInfo(spec.width, spec.height, f, f, spec.width / 2.0, spec.height / 2.0)
            # the clipping planes sit a hair outside the depth range Drake checks against
            clip = ClippingRange(spec.near * 0.999, spec.far * 1.001)
            core = RenderCameraCore(RENDERER, info, clip, RigidTransform())
            self._cameras = (
                ColorRenderCamera(core, False),
                DepthRenderCamera(core, DepthRange(spec.near, spec.far)),
            )
        return self._cameras

    def capture(
        self, world: Any, X_WS: Any, *, color: bool = True, depth: bool = True, noise: bool = True
    ) -> CameraFrame:
        """Render the world from the sensor pose ``X_WS`` (a RigidTransform in W).

        Args:
            world: A built :class:`workbench.sim.World` (a renderer is added if it has none).
            X_WS: The sensor frame in W (x forward, z up).
            color: Render the colour image.
            depth: Render the depth image.
            noise: Apply the spec's Gaussian noise.
        """
        from pydrake.math import RigidTransform, RollPitchYaw

        world.add_renderer(RENDERER)
        scene_graph = world.scene_graph
        context = scene_graph.GetMyContextFromRoot(world.context)
        query = scene_graph.get_query_output_port().Eval(context)
        X_WC = X_WS.multiply(
            RigidTransform(RollPitchYaw(-np.pi / 2, 0.0, -np.pi / 2).ToRotationMatrix())
        )
        color_camera, depth_camera = self._render_cameras()
        frame = CameraFrame(None, None, float(world.time))
        spec_noise = self.spec.noise if noise else None
        if color:
            image = query.RenderColorImage(color_camera, scene_graph.world_frame_id(), X_WC)
            rgb = np.array(image.data[:, :, :3], dtype=np.uint8)
            if spec_noise is not None:
                drawn = self._rng.normal(spec_noise.mean, spec_noise.stddev, rgb.shape)
                rgb = np.clip(rgb + 255.0 * drawn, 0, 255).round().astype(np.uint8)
            if self.spec.encoding == "bgr8":
                rgb = rgb[:, :, ::-1].copy()
            elif self.spec.encoding == "mono8":
                rgb = _luminance(rgb)
            frame.color = rgb
        if depth:
            image = query.RenderDepthImage(depth_camera, scene_graph.world_frame_id(), X_WC)
            values = np.array(image.data[:, :, 0], dtype=np.float32)
            if spec_noise is not None:
                finite = np.isfinite(values) & (values > 0)
                drawn = self._rng.normal(spec_noise.mean, spec_noise.stddev, int(finite.sum()))
                values[finite] += drawn.astype(np.float32)
            frame.depth = values
        return frame

    def points(self, depth: np.ndarray) -> np.ndarray:
        """(H, W, 3) points in the optical frame (x right, y down, z forward) of a depth image, m.

        Computed as Gazebo's OpenNI plugin does: ``x = z tan(atan2(i - (W - 1) / 2, f))``.
        """
        height, width = depth.shape
        f = self.spec.focal_length
        u = (np.arange(width) - 0.5 * (width - 1)) / f if width > 1 else np.zeros(1)
        v = (np.arange(height) - 0.5 * (height - 1)) / f if height > 1 else np.zeros(1)
        z = depth.astype(float)
        return np.stack([z * u[None, :], z * v[:, None], z], axis=-1)


def _luminance(rgb: np.ndarray) -> np.ndarray:
    weights = np.array([0.299, 0.587, 0.114])
    return np.clip(rgb @ weights, 0, 255).round().astype(np.uint8)
