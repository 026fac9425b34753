"""Worlds and sensor blocks for the sensor tests, and analytic distances to check them against."""

from __future__ import annotations

import math

import numpy as np

from workbench.sim.model_spec import SimModel

#: Static obstacles: boxes (name, centre x, y, size x, y, yaw) and cylinders (name, x, y, radius).
BOXES = [
    ("wall_east", 4.0, 0.0, 0.2, 6.0, 0.0),
    ("wall_north", 0.0, 3.5, 6.0, 0.2, 0.0),
    ("crate", -2.0, -1.0, 0.6, 0.4, 0.5),
    ("shelf", 1.5, -2.5, 1.2, 0.3, -0.3),
]
CYLINDERS = [("post", -1.0, 2.0, 0.25), ("bin", 2.0, 1.2, 0.4), ("pillar", -3.0, 1.0, 0.15)]
HEIGHT = 1.0  # every obstacle stands from z = 0 to z = HEIGHT
SENSOR_Z = 0.5


def build_world(world: object) -> None:
    """Put the obstacles into an unbuilt World."""
    from workbench.spatial import rigid_transform

    for name, x, y, sx, sy, yaw in BOXES:
        world.add_box(  # type: ignore[attr-defined]
            name, size=(sx, sy, HEIGHT), X_WB=rigid_transform([x, y, HEIGHT / 2], rpy=[0, 0, yaw])
        )
    for name, x, y, r in CYLINDERS:
        world.add_cylinder(name, radius=r, length=HEIGHT, X_WB=[x, y, HEIGHT / 2])  # type: ignore[attr-defined]


def analytic_distance(origin: np.ndarray, direction: np.ndarray) -> float:
    """Distance from ``origin`` along the horizontal ``direction`` to the first obstacle (2D)."""
    best = math.inf
    ox, oy = float(origin[0]), float(origin[1])
    dx, dy = float(direction[0]), float(direction[1])
    for _, cx, cy, sx, sy, yaw in BOXES:
        c, s = math.cos(yaw), math.sin(yaw)
        # into the box frame
        px, py = c * (ox - cx) + s * (oy - cy), -s * (ox - cx) + c * (oy - cy)
        qx, qy = c * dx + s * dy, -s * dx + c * dy
        t_in, t_out = -math.inf, math.inf
        for p, q, h in ((px, qx, sx / 2), (py, qy, sy / 2)):
            if abs(q) < 1e-15:
                if abs(p) > h:
                    t_in, t_out = math.inf, -math.inf
                continue
            a, b = (-h - p) / q, (h - p) / q
            t_in, t_out = max(t_in, min(a, b)), min(t_out, max(a, b))
        if t_in <= t_out and t_in > 0:
            best = min(best, t_in)
    for _, cx, cy, r in CYLINDERS:
        fx, fy = ox - cx, oy - cy
        b = fx * dx + fy * dy
        disc = b * b - (fx * fx + fy * fy - r * r)
        if disc >= 0:
            t = -b - math.sqrt(disc)
            if t > 0:
                best = min(best, t)
    return best


def laser_xml(
    name: str = "laser",
    samples: int = 720,
    min_angle: float = -math.pi,
    max_angle: float = math.pi,
    range_min: float = 0.1,
    range_max: float = 10.0,
    rate: float = 10.0,
    noise: str = "",
    plugin: str = "",
    vertical: str = "",
) -> str:
    return f"""<sensor type="ray" name="{name}">
  <pose>0 0 0.1 0 0 0</pose><update_rate>{rate}</update_rate><visualize>false</visualize>
  <ray><scan><horizontal><samples>{samples}</samples><resolution>1</resolution>
    <min_angle>{min_angle}</min_angle><max_angle>{max_angle}</max_angle></horizontal>{vertical}</scan>
    <range><min>{range_min}</min><max>{range_max}</max><resolution>0.01</resolution></range>{noise}</ray>
  {plugin}
</sensor>"""


def sensor_robot_sdf(name: str, sensors: str, static: bool = True, size: float = 0.3) -> str:
    """An SDF model: one box link 'base' (edge ``size``) carrying ``sensors``."""
    return f"""<sdf version="1.7"><model name="{name}">
  <static>{str(static).lower()}</static>
  <link name="base">
    <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    <collision name="c"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>
    <visual name="v"><geometry><box><size>{size} {size} {size}</size></box></geometry></visual>
    {sensors}
  </link>
</model></sdf>"""


def sdf_model(text: str, name: str | None = None) -> SimModel:
    from workbench.sim.gazebo_sdf import sim_model_from_sdf

    return sim_model_from_sdf(text, name=name, source="test")
