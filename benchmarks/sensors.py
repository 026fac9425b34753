"""The simulated sensors and drives: accuracy against geometry, speed against PyBullet.

Run ``python benchmarks/sensors.py`` (``--quick`` for a short smoke run). Writes
``benchmarks/results/sensors.json`` and prints tables with the machine.

Accuracy:

* lidar: 720 beams over 360 degrees (noise off) from inside a 9 x 7 m room of
  boxes and cylinders at known places (two boxes turned); each beam's range
  against the distance computed here in closed form (2-D slabs and circles);
* depth: one 640 x 480 frame (hfov 60 degrees, noise off) of the same room on
  the ground plane, looking down at the shapes; each pixel's depth against the
  closed-form depth along the optical axis (3-D slabs, cylinder, plane);
  silhouette pixels (the closed-form depth jumps by more than 5 cm to a
  neighbour) are counted apart, since a rasteriser may give either side;
* odometry: custom_bot and the TurtleBot3 driven about 20 m in slalom on the
  empty world's ground with their diff drive's ``odometrySource`` set to
  ``encoder``; the published odometry against the true pose, and the diff
  drive's kinematics integrated here from the wheel angles at every server chunk.

Speed (the server as ``workbench sim house --fast`` runs it: as fast as possible, the
house world's 8 ms physics step, an in-process bus with ``/clock`` and the plugins
publishing; the IMU, which nobody subscribes to, idle as gazebo_ros's is):

* per scan and frame in the house world: custom_bot's laser (720 beams,
  180 degrees, 40 Hz) and a 640 x 480 depth camera (10 Hz), against PyBullet's
  ``rayTestBatch`` with the same rays and shapes and its ``getCameraImage``
  (TinyRenderer);
* real-time factors: the TurtleBot3 (360-beam lidar at 5 Hz, IMU at 200 Hz,
  diff drive) and custom_bot (720 beams at 40 Hz) wandering in the house, against
  the same robot URDF, house shapes, physics step, wheel velocity motors and
  ``rayTestBatch`` at the laser's rate in PyBullet; with the top of a cProfile.

Wander: the TurtleBot3 driven by turtlebot3_drive's decisions
(:class:`workbench.teleop.turtlebot3_drive.Turtlebot3Drive`, 125 Hz of
simulated time, checked at the end of each server chunk) in the house for 10
simulated minutes; every contact between the robot and anything but the ground
is counted (checked every 10 ms).

PyBullet comes from ``pip install pybullet``; without it its columns read n/a.
"""

from __future__ import annotations

import argparse
import cProfile
import io
import json
import math
import pstats
import statistics
import sys
import tempfile
import time
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from machine import describe  # noqa: E402

from workbench.paths import urdf_dir  # noqa: E402
from workbench.sim import World  # noqa: E402
from workbench.sim.sensors import Camera, Lidar, parse_sensor  # noqa: E402
from workbench.spatial import rigid_transform  # noqa: E402

SEED = 0
STEP = 0.001
BURGER = "turtlebot3_burger"
CUSTOM = "custom_bot"
#: Where the robots start in the house (the living room, clear of furniture).
HOUSE_START = (0.0, 0.0, 0.0)
CASTER = "front_caster_of_wheel_joint"
#: Height of the model frame above the ground when the wheels touch it: custom_bot's
#: base_link is 5 cm above its wheel axles (radius 3.5 cm); the burger's is base_footprint.
SPAWN_Z = {CUSTOM: 0.085, BURGER: 0.0}

# --- the accuracy room ---------------------------------------------------------------

ROOM_HEIGHT = 1.0
#: ('box', name, centre x, y, size x, y, z, yaw) and ('cylinder', name, x, y, radius, length).
ROOM: list[tuple] = [
    ("box", "north", 0.0, 3.5, 9.0, 0.2, ROOM_HEIGHT, 0.0),
    ("box", "south", 0.0, -3.5, 9.0, 0.2, ROOM_HEIGHT, 0.0),
    ("box", "east", 4.5, 0.0, 0.2, 7.2, ROOM_HEIGHT, 0.0),
    ("box", "west", -4.5, 0.0, 0.2, 7.2, ROOM_HEIGHT, 0.0),
    ("box", "table", 2.0, 1.0, 1.2, 0.8, 0.75, 0.0),
    ("box", "crate", -1.5, 1.8, 0.6, 0.6, 0.6, 0.5),
    ("box", "shelf", 2.5, -1.8, 1.5, 0.4, 1.0, -0.3),
    ("box", "block", -2.5, -1.0, 0.5, 1.0, 0.4, 0.0),
    ("cylinder", "pillar", 0.5, 2.2, 0.25, ROOM_HEIGHT),
    ("cylinder", "bin", -0.8, -2.0, 0.2, 0.5),
    ("cylinder", "post", 3.2, 0.0, 0.08, ROOM_HEIGHT),
    ("cylinder", "drum", -3.4, 1.2, 0.35, 0.8),
]
LIDAR_ORIGIN = (0.1, -0.2, 0.3)
LASER_360 = """<sensor type="ray" name="laser"><update_rate>40</update_rate><ray><scan><horizontal>
<samples>720</samples><resolution>1</resolution><min_angle>-3.14159265</min_angle>
<max_angle>3.14159265</max_angle></horizontal></scan><range><min>0.1</min><max>30</max></range>
</ray></sensor>"""
DEPTH = """<sensor type="depth" name="kinect"><update_rate>10</update_rate><camera>
<horizontal_fov>1.0472</horizontal_fov><image><width>640</width><height>480</height></image>
<clip><near>0.05</near><far>30</far></clip></camera></sensor>"""
#: The depth camera's pose in the accuracy room: x, y, z, roll, pitch (down), yaw.
CAMERA_POSE = (-3.8, -2.8, 1.6, 0.0, 0.35, 0.55)


def room_world(ground: bool) -> World:
    """The accuracy room: the shapes welded to the world (and the ground plane)."""
    world = World(ground=ground)
    for shape in ROOM:
        if shape[0] == "box":
            _, name, x, y, sx, sy, sz, yaw = shape
            world.add_box(name, [sx, sy, sz], rigid_transform([x, y, sz / 2], rpy=[0, 0, yaw]))
        else:
            _, name, x, y, r, length = shape
            world.add_cylinder(name, r, length, rigid_transform([x, y, length / 2]))
    world.build()
    return world


def ray_room(origin: np.ndarray, d: np.ndarray, ground: bool) -> np.ndarray:
    """Distance along rays ``origin + t d`` (d: (N, 3), any length) to the room's surfaces.

    In closed form, one shape at a time: a box's slabs in its own frame, a
    cylinder's side (quadratic) and caps, the ground's plane z = 0. Every ray
    starts outside every shape, so the entry is the first crossing.
    """
    best = np.full(len(d), np.inf)
    for shape in ROOM:
        if shape[0] == "box":
            _, _, x, y, sx, sy, sz, yaw = shape
            c, s = math.cos(yaw), math.sin(yaw)
            R = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])  # W -> box frame
            o = R @ (origin - np.array([x, y, sz / 2]))
            v = d @ R.T
            half = np.array([sx, sy, sz]) / 2
            with np.errstate(divide="ignore", invalid="ignore"):
                a = (-half - o) / v
                b = (half - o) / v
            t_in = np.nanmax(np.minimum(a, b), axis=1)
            t_out = np.nanmin(np.maximum(a, b), axis=1)
            hit = (t_in <= t_out) & (t_in > 0)
        else:
            _, _, x, y, r, length = shape
            ox, oy = origin[0] - x, origin[1] - y
            qa = d[:, 0] ** 2 + d[:, 1] ** 2
            qb = ox * d[:, 0] + oy * d[:, 1]
            qc = ox * ox + oy * oy - r * r
            disc = qb * qb - qa * qc
            with np.errstate(divide="ignore", invalid="ignore"):
                root = np.sqrt(np.maximum(disc, 0.0))
                s_in, s_out = (-qb - root) / qa, (-qb + root) / qa
                z0, z1 = (0.0 - origin[2]) / d[:, 2], (length - origin[2]) / d[:, 2]
            side = disc >= 0
            z_in = np.where(np.isfinite(z0), np.minimum(z0, z1), -np.inf)
            z_out = np.where(np.isfinite(z0), np.maximum(z0, z1), np.inf)
            flat = d[:, 2] == 0
            inside_z = (origin[2] >= 0) & (origin[2] <= length)
            z_in = np.where(flat, np.where(inside_z, -np.inf, np.inf), z_in)
            z_out = np.where(flat, np.where(inside_z, np.inf, -np.inf), z_out)
            t_in = np.maximum(s_in, z_in)
            t_out = np.minimum(s_out, z_out)
            hit = side & (t_in <= t_out) & (t_in > 0)
        best = np.where(hit & (t_in < best), t_in, best)
    if ground:
        with np.errstate(divide="ignore", invalid="ignore"):
            t = -origin[2] / d[:, 2]
        down = d[:, 2] < 0
        best = np.where(down & (t < best), t, best)
    return best


def lidar_accuracy() -> dict[str, Any]:
    world = room_world(ground=False)
    spec = parse_sensor(LASER_360, model="bench", link="base")
    lidar = Lidar(spec)
    X_WS = rigid_transform(list(LIDAR_ORIGIN))
    ranges = lidar.scan(world, X_WS, noise=False)
    expected = ray_room(np.array(LIDAR_ORIGIN), lidar.directions_S, ground=False)
    error = np.abs(ranges - expected)
    return {
        "beams": int(len(ranges)),
        "beams_hit": int(np.isfinite(expected).sum()),
        "max_error_m": float(error.max()),
        "within_1cm": int((error <= 0.01).sum()),
        "range_m": [float(expected.min()), float(expected.max())],
    }


def depth_accuracy() -> dict[str, Any]:
    world = room_world(ground=True)
    camera = Camera(parse_sensor(DEPTH, model="bench", link="base"))
    x, y, z, roll, pitch, yaw = CAMERA_POSE
    X_WS = rigid_transform([x, y, z], rpy=[roll, pitch, yaw])
    depth = camera.capture(world, X_WS, color=False, noise=False).depth
    assert depth is not None
    height, width = depth.shape
    f = camera.spec.focal_length
    i, j = np.meshgrid(np.arange(width), np.arange(height))
    # S looks along +x, y left, z up; the depth is along x, so d_S has x = 1
    d_S = np.stack(
        [np.ones(i.shape), -(i - (width - 1) / 2) / f, -(j - (height - 1) / 2) / f], axis=-1
    ).reshape(-1, 3)
    R_WS = X_WS.rotation().matrix()
    expected = ray_room(np.array([x, y, z]), d_S @ R_WS.T, ground=True).reshape(height, width)
    expected[expected > camera.spec.far] = np.inf
    got = depth.astype(float)
    both_inf = np.isinf(got) & np.isinf(expected)
    with np.errstate(invalid="ignore"):
        error = np.where(both_inf, 0.0, np.abs(got - expected))
    error = np.nan_to_num(error, nan=np.inf)
    jump = np.zeros(expected.shape, dtype=bool)
    finite = np.where(np.isfinite(expected), expected, 1e3)
    for axis in (0, 1):
        step = np.abs(np.diff(finite, axis=axis)) > 0.05
        if axis == 0:
            jump[1:] |= step
            jump[:-1] |= step
        else:
            jump[:, 1:] |= step
            jump[:, :-1] |= step
    inner = error[~jump]
    return {
        "pixels": int(error.size),
        "pixels_on_shapes": int(np.isfinite(expected).sum()),
        "max_error_m": float(error.max()),
        "within_1cm": int((error <= 0.01).sum()),
        "silhouette_pixels": int(jump.sum()),
        "max_error_off_silhouettes_m": float(inner.max()),
        "within_1cm_off_silhouettes": int((inner <= 0.01).sum()),
        "median_error_m": float(np.median(error[np.isfinite(expected)])),
    }


# --- servers and robots ----------------------------------------------------------------


def robot_xml(name: str, encoder: bool = False) -> str:
    """The robot's URDF text; ``encoder``: its diff drive's odometry from the wheels."""
    text = (urdf_dir() / f"{name}.urdf").read_text()
    if encoder:
        if "<odometrySource>" in text:
            text = text.replace(
                "<odometrySource>world</odometrySource>", "<odometrySource>encoder</odometrySource>"
            )
        else:
            text = text.replace(
                "<legacyMode>false</legacyMode>",
                "<legacyMode>false</legacyMode><odometrySource>encoder</odometrySource>",
                1,
            )
        assert "<odometrySource>encoder</odometrySource>" in text
    return text


class Session:
    """A server as ``workbench sim WORLD --fast --headless`` builds it, with one robot."""

    def __init__(
        self,
        world: str,
        robot: str,
        *,
        encoder: bool = False,
        bus: bool = True,
        joint_positions: dict[str, float] | None = None,
    ) -> None:
        from workbench.sim.gazebo_ros_plugins.diff_drive import GazeboRosDiffDrive
        from workbench.sim.gzserver import ServerOptions, build_server
        from workbench.sim.loading import sim_model_from_xml
        from workbench.sim.sensors.laser_plugin import GazeboRosLaser

        self.bus = self.api = None
        if bus:
            from workbench.bus import Bus, Node
            from workbench.sim.gazebo_ros import GazeboRosApi

            self.bus = Bus()
        options = ServerOptions(world=world, fast=True, view=False, seed=SEED)
        self.world, self.server, _ = build_server(options, self.bus)
        if self.bus is not None:
            self.api = GazeboRosApi(self.server, Node("gazebo", bus=self.bus))
        model = sim_model_from_xml(
            robot_xml(robot, encoder), name=robot, source=f"urdf/{robot}.urdf", base_dir=urdf_dir()
        )
        self.robot = robot
        X = [*HOUSE_START[:2], SPAWN_Z[robot]] if world == "house" else [0, 0, SPAWN_Z[robot]]
        self.server.spawn(model, X, joint_positions=joint_positions)
        plugins = self.server.plugins
        self.drive = next(p for p in plugins if isinstance(p, GazeboRosDiffDrive))
        lasers = [p for p in plugins if isinstance(p, GazeboRosLaser)]
        self.laser = lasers[0] if lasers else None

    def pose2d(self) -> tuple[float, float, float]:
        X = self.world.get_model_pose(self.robot)
        p = X.translation()
        return float(p[0]), float(p[1]), float(X.rotation().ToRollPitchYaw().yaw_angle())

    def close(self) -> None:
        if self.api is not None:
            self.api.close()
        self.server.stop()
        if self.bus is not None:
            self.bus.shutdown()


def twist(forward: float, turn: float) -> Any:
    return SimpleNamespace(
        linear=SimpleNamespace(x=forward, y=0.0, z=0.0),
        angular=SimpleNamespace(x=0.0, y=0.0, z=turn),
    )


# --- odometry ---------------------------------------------------------------------------


def odometry_drift(robot: str, distance: float) -> dict[str, Any]:
    """Slalom ``distance`` m; encoder odometry and wheel kinematics against the true pose."""
    # custom_bot's caster wheel leads its swivel by 5 cm: it starts turned round (trailing),
    # else the first metres are spent dragging it round (see the report)
    trailing = {CASTER: math.pi} if robot == CUSTOM else None
    session = Session("empty", robot, encoder=True, bus=False, joint_positions=trailing)
    drive = session.drive
    speed = 0.2 if robot == BURGER else 0.3
    period = 8.0  # s per slalom swing
    turn = 0.6
    right, left = drive.wheels
    radius, separation = drive.diameter / 2, drive.separation
    model = drive.model
    wheel_links = [model.joint_links(joint)[1] for joint in (left, right)]

    def axle() -> tuple[float, float, float]:
        """The middle of the wheels (the point diff-drive odometry tracks) and the heading."""
        middle = sum(np.asarray(model.link_pose(link).translation()) for link in wheel_links) / 2
        return float(middle[0]), float(middle[1]), session.pose2d()[2]

    x0, y0, yaw0 = axle()
    record: list[tuple[float, ...]] = []
    state = {"pose": (0.0, 0.0, 0.0), "angles": None, "path": 0.0, "last": (x0, y0)}

    def hook(server: Any) -> None:
        t = server.world.time
        sign = 1.0 if math.sin(2 * math.pi * t / period) >= 0 else -1.0
        drive.on_command(twist(speed, sign * turn))
        angles = (model.joint_position(left), model.joint_position(right))
        if state["angles"] is not None:  # the diff drive's kinematics, at every chunk
            dl, dr = (a - b for a, b in zip(angles, state["angles"], strict=True))
            x, y, th = state["pose"]
            sl, sr = dl * radius, dr * radius
            dth = (sr - sl) / separation
            mid = th + dth / 2
            state["pose"] = (
                x + (sl + sr) / 2 * math.cos(mid),
                y + (sl + sr) / 2 * math.sin(mid),
                th + dth,
            )
        state["angles"] = angles
        xt, yt, yawt = axle()
        lx, ly = state["last"]
        state["path"] += math.hypot(xt - lx, yt - ly)
        state["last"] = (xt, yt)
        # the truth in the start frame (the odometry starts at the origin)
        c, s = math.cos(-yaw0), math.sin(-yaw0)
        tx, ty = c * (xt - x0) - s * (yt - y0), s * (xt - x0) + c * (yt - y0)
        odometer = drive.odometer
        record.append(
            (t, tx, ty, yawt - yaw0, odometer.x, odometer.y, odometer.theta, *state["pose"])
        )

    session.server.hooks.append(hook)
    duration = distance / speed
    start = time.perf_counter()
    session.server.run(until=duration)
    wall = time.perf_counter() - start
    rolled = [
        abs(model.joint_position(left) - 0.0) * radius,
        abs(model.joint_position(right) - 0.0) * radius,
    ]
    session.close()
    data = np.array(record)
    truth, odom, kin = data[:, 1:4], data[:, 4:7], data[:, 7:10]

    def planar(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return np.hypot(a[:, 0] - b[:, 0], a[:, 1] - b[:, 1])

    def heading(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return np.abs(np.remainder(a[:, 2] - b[:, 2] + np.pi, 2 * np.pi) - np.pi)

    drift = planar(odom, truth)
    wheel_path = statistics.mean(rolled)
    return {
        "robot": robot,
        "speed_m_s": speed,
        "simulated_s": duration,
        "path_m": state["path"],
        "wheel_path_m": wheel_path,
        "wheel_over_true_path": wheel_path / state["path"],
        "final_drift_m": float(drift[-1]),
        "max_drift_m": float(drift.max()),
        "drift_percent_of_path": float(100 * drift[-1] / state["path"]),
        "final_heading_error_rad": float(heading(odom, truth)[-1]),
        "odometry_vs_kinematics_max_m": float(planar(odom, kin).max()),
        "kinematics_final_drift_m": float(planar(kin, truth)[-1]),
        "update_rate_hz": drive.update_rate,
        "real_time_factor": duration / wall,
    }


# --- the house in PyBullet -------------------------------------------------------------


def house_shapes(world: World) -> list[tuple]:
    """The built world's proximity shapes, posed in W: ('box', size, X) / ('cylinder', r, l, X)."""
    from pydrake.geometry import Box, Cylinder, Role

    plant, inspector = world.plant, world.scene_graph.model_inspector()
    context = plant.GetMyContextFromRoot(world.context)
    shapes = []
    for geometry in inspector.GetAllGeometryIds(Role.kProximity):
        shape = inspector.GetShape(geometry)
        body = plant.GetBodyFromFrameId(inspector.GetFrameId(geometry))
        X = plant.EvalBodyPoseInWorld(context, body).multiply(inspector.GetPoseInFrame(geometry))
        if isinstance(shape, Box):
            shapes.append(("box", tuple(shape.size()), X))
        elif isinstance(shape, Cylinder):
            shapes.append(("cylinder", shape.radius(), shape.length(), X))
    return shapes


def pybullet_house(
    shapes: list[tuple], ground: bool = False, step: float = STEP
) -> tuple[Any, int]:
    import pybullet as p

    client = p.connect(p.DIRECT)
    p.setGravity(0, 0, -9.81, physicsClientId=client)
    p.setTimeStep(step, physicsClientId=client)
    if ground:
        plane = p.createCollisionShape(p.GEOM_PLANE, physicsClientId=client)
        p.createMultiBody(0, plane, physicsClientId=client)
    for shape in shapes:
        X = shape[-1]
        q = X.rotation().ToQuaternion()
        orientation = [q.x(), q.y(), q.z(), q.w()]
        if shape[0] == "box":
            half = [s / 2 for s in shape[1]]
            col = p.createCollisionShape(p.GEOM_BOX, halfExtents=half, physicsClientId=client)
            vis = p.createVisualShape(p.GEOM_BOX, halfExtents=half, physicsClientId=client)
        else:
            r, length = shape[1], shape[2]
            col = p.createCollisionShape(
                p.GEOM_CYLINDER, radius=r, height=length, physicsClientId=client
            )
            vis = p.createVisualShape(
                p.GEOM_CYLINDER, radius=r, length=length, physicsClientId=client
            )
        p.createMultiBody(
            0,
            col,
            vis,
            basePosition=list(X.translation()),
            baseOrientation=orientation,
            physicsClientId=client,
        )
    return p, client


def have_pybullet() -> bool:
    try:
        import pybullet  # noqa: F401
    except ImportError:
        return False
    return True


# --- sensor speed in the house --------------------------------------------------------------


def median_ms(fn: Any, repeats: int) -> float:
    fn()  # warm up
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1e3


def custom_bot_laser() -> str:
    text = (urdf_dir() / "custom_bot.urdf").read_text()
    start = text.index('<sensor type="gpu_ray"')
    return text[start : text.index("</sensor>", start) + len("</sensor>")]


def sensor_speed(repeats: int) -> dict[str, Any]:
    from workbench.sim.gzserver import ServerOptions, build_server

    world, server, _ = build_server(ServerOptions(world="house", fast=True, view=False))
    spec = parse_sensor(custom_bot_laser(), model=CUSTOM, link="laser_scanner")
    lidar = Lidar(spec)
    X_WS = rigid_transform([HOUSE_START[0], HOUSE_START[1], 0.23])
    ours = median_ms(lambda: lidar.scan(world, X_WS, noise=False), repeats)
    ranges = lidar.scan(world, X_WS, noise=False)
    camera = Camera(parse_sensor(DEPTH, model="bench", link="base"))
    X_WC = rigid_transform([HOUSE_START[0], HOUSE_START[1], 0.5], rpy=[0, 0.15, 0.3])
    frame_ms = median_ms(
        lambda: camera.capture(world, X_WC, color=False, noise=False), max(3, repeats // 5)
    )
    result: dict[str, Any] = {
        "laser": {
            "beams": len(ranges),
            "rate_hz": spec.update_rate,
            "workbench_ms": ours,
            "pybullet_ms": None,
        },
        "depth": {
            "size": [640, 480],
            "rate_hz": 10.0,
            "workbench_ms": frame_ms,
            "pybullet_ms": None,
        },
    }
    if have_pybullet():
        p, client = pybullet_house(house_shapes(world), ground=True)
        origin = np.asarray(X_WS.translation())
        directions = lidar.directions_S @ X_WS.rotation().matrix().T
        starts = np.repeat(origin[None], len(directions), axis=0)
        ends = starts + directions * spec.range_max
        starts_list, ends_list = starts.tolist(), ends.tolist()

        def bullet_scan() -> list:
            return p.rayTestBatch(starts_list, ends_list, physicsClientId=client)

        result["laser"]["pybullet_ms"] = median_ms(bullet_scan, repeats)
        hits = bullet_scan()
        theirs = np.array([h[2] * spec.range_max if h[0] >= 0 else np.inf for h in hits])
        both = np.isfinite(theirs) & np.isfinite(ranges)
        result["laser"]["agree_beams"] = int((np.isfinite(theirs) == np.isfinite(ranges)).sum())
        result["laser"]["max_difference_m"] = float(np.abs(theirs[both] - ranges[both]).max())
        forward = X_WC.rotation().matrix()[:, 0]
        eye = np.asarray(X_WC.translation())
        view = p.computeViewMatrix(eye.tolist(), (eye + forward).tolist(), [0, 0, 1])
        vfov = math.degrees(2 * math.atan(math.tan(1.0472 / 2) * 480 / 640))
        projection = p.computeProjectionMatrixFOV(vfov, 640 / 480, 0.05, 30.0)
        result["depth"]["pybullet_ms"] = median_ms(
            lambda: p.getCameraImage(
                640, 480, view, projection, renderer=p.ER_TINY_RENDERER, physicsClientId=client
            ),
            max(3, repeats // 5),
        )
        p.disconnect(physicsClientId=client)
    server.stop()
    return result


# --- wandering: real-time factors and the 10 minutes --------------------------------------


class Wanderer:
    """turtlebot3_drive's decisions at 125 Hz of simulated time, fed by the laser plugin's
    scans and, at the diff drive's rate (its /odom), the robot's heading."""

    def __init__(self, session: Session) -> None:
        from workbench.teleop.turtlebot3_drive import LOOP_HZ, Turtlebot3Drive

        self.session = session
        self.logic = Turtlebot3Drive()
        self.period = 1.0 / LOOP_HZ
        self.next_tick = 0.0
        self.seen: Any = None
        self.odom_stamp: Any = None

    def __call__(self, server: Any) -> None:
        t = server.world.time
        if t + 1e-9 < self.next_tick:
            return
        self.next_tick = t + self.period
        laser = self.session.laser
        if laser is not None and laser.latest_message is not self.seen:
            self.seen = laser.latest_message
            self.logic.on_scan(self.seen)
        drive = self.session.drive
        stamp = drive.last[0] if drive.last is not None else None
        if stamp != self.odom_stamp:  # the drive published /odom since
            self.odom_stamp = stamp
            self.logic.on_odom(orientation_message(self.session.pose2d()[2]))
        command = self.logic.step()
        if command is not None:
            self.session.drive.on_command(twist(command.x, command.yaw))


def orientation_message(yaw: float) -> Any:
    q = SimpleNamespace(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))
    return SimpleNamespace(pose=SimpleNamespace(pose=SimpleNamespace(orientation=q)))


def profile_top(profile: cProfile.Profile, count: int = 12) -> list[dict[str, Any]]:
    stats = pstats.Stats(profile, stream=io.StringIO())
    rows = []
    for (filename, line, name), (_cc, calls, tottime, cumtime, _callers) in stats.stats.items():  # type: ignore[attr-defined]
        short = filename.split("/site-packages/")[-1].split("/wt-bench/")[-1]
        rows.append(
            {
                "function": f"{short}:{line}({name})",
                "calls": calls,
                "tottime_s": tottime,
                "cumtime_s": cumtime,
            }
        )
    rows.sort(key=lambda r: -r["tottime_s"])
    return rows[:count]


def workbench_rtf(robot: str, seconds: float, profile_seconds: float) -> dict[str, Any]:
    """Wander ``seconds`` as fast as possible, then ``profile_seconds`` more under cProfile."""
    session = Session("house", robot)
    session.server.hooks.append(Wanderer(session))
    session.server.run(until=0.5)  # settle and first scans
    t0 = session.world.time
    start = time.perf_counter()
    session.server.run(until=t0 + seconds)
    wall = time.perf_counter() - start
    moved = session.pose2d()
    profiler = cProfile.Profile()
    start = time.perf_counter()
    profiler.enable()
    session.server.run(until=t0 + seconds + profile_seconds)
    profiler.disable()
    profiled = time.perf_counter() - start
    session.close()
    return {
        "rtf": seconds / wall,
        "simulated_s": seconds,
        "end_pose": moved,
        "profile": profile_top(profiler),
        "profiled_s": profile_seconds,
        "profiled_wall_s": profiled,
    }


def bare_physics_rtf(robot: str, seconds: float) -> float:
    """The house and the robot in the server's World, no plugins, one AdvanceTo."""
    from workbench.sim.gzserver import ServerOptions, build_server
    from workbench.sim.loading import sim_model_from_xml

    world, server, _ = build_server(ServerOptions(world="house", fast=True, view=False))
    model = sim_model_from_xml(
        robot_xml(robot), name=robot, source=f"urdf/{robot}.urdf", base_dir=urdf_dir()
    )
    world.add_model(model, [*HOUSE_START[:2], SPAWN_Z[robot]])
    world.advance_to(0.1)
    start = time.perf_counter()
    world.advance_to(0.1 + seconds)
    wall = time.perf_counter() - start
    server.stop()
    return seconds / wall


def pybullet_rtf(robot: str, seconds: float) -> dict[str, Any] | None:
    """The same robot URDF in the same house shapes, the house world's physics step,
    wheel velocity motors, rayTestBatch at the laser's rate from the laser's link, the same
    wander decisions."""
    if not have_pybullet():
        return None
    from workbench.sim.gzserver import ServerOptions, build_server
    from workbench.teleop.turtlebot3_drive import LOOP_HZ, Turtlebot3Drive

    world, server, _ = build_server(ServerOptions(world="house", fast=True, view=False))
    shapes = house_shapes(world)
    step = world.time_step
    server.stop()
    p, client = pybullet_house(shapes, ground=True, step=step)
    text = robot_xml(robot)
    if robot == BURGER:
        laser_xml = text[text.index('<sensor type="ray"') :]
        laser_link, left, right, separation, diameter = (
            "base_scan",
            "wheel_left_joint",
            "wheel_right_joint",
            0.160,
            0.066,
        )
    else:
        laser_xml = custom_bot_laser()
        laser_link, left, right, separation, diameter = (
            "laser_scanner",
            "left_wheel_joint",
            "right_wheel_joint",
            0.25,
            0.07,
        )
    spec = parse_sensor(laser_xml[: laser_xml.index("</sensor>") + 9], model=robot, link=laser_link)
    lidar = Lidar(spec)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"{robot}.urdf"
        path.write_text(_strip_meshes(text))
        body = p.loadURDF(str(path), [*HOUSE_START[:2], SPAWN_Z[robot]], physicsClientId=client)
    joints = {
        p.getJointInfo(body, j, physicsClientId=client)[1].decode(): j
        for j in range(p.getNumJoints(body, physicsClientId=client))
    }
    links = {
        p.getJointInfo(body, j, physicsClientId=client)[12].decode(): j
        for j in range(p.getNumJoints(body, physicsClientId=client))
    }
    laser_index = links[laser_link]
    logic = Turtlebot3Drive()
    command = (0.0, 0.0)
    h = spec.horizontal
    increment = (h.max_angle - h.min_angle) / (h.count - 1)
    steps = int(round(seconds / step))
    scan_every = int(round(1.0 / spec.update_rate / step))
    decide_every = int(round(1.0 / LOOP_HZ / step))
    drive_every = int(round(1.0 / (30.0 if robot == BURGER else 100.0) / step))
    start = time.perf_counter()
    for k in range(steps):
        if k % scan_every == 0:
            state = p.getLinkState(body, laser_index, physicsClientId=client)
            origin = np.asarray(state[4])
            R = np.asarray(p.getMatrixFromQuaternion(state[5])).reshape(3, 3)
            directions = lidar.directions_S @ R.T
            starts = np.repeat(origin[None], len(directions), axis=0) + directions * spec.range_min
            ends = origin[None] + directions * spec.range_max
            hits = p.rayTestBatch(starts.tolist(), ends.tolist(), physicsClientId=client)
            span = spec.range_max - spec.range_min
            ranges = [
                spec.range_min + hit[2] * span if hit[0] >= 0 and hit[0] != body else math.inf
                for hit in hits
            ]
            logic.on_scan(
                SimpleNamespace(
                    ranges=ranges,
                    angle_min=h.min_angle,
                    angle_increment=increment,
                    range_max=spec.range_max,
                )
            )
        if k % decide_every == 0:
            q = p.getBasePositionAndOrientation(body, physicsClientId=client)[1]
            yaw = p.getEulerFromQuaternion(q)[2]
            logic.on_odom(orientation_message(yaw))
            decision = logic.step()
            if decision is not None:
                command = (decision.x, decision.yaw)
        if k % drive_every == 0:
            forward, turn = command
            for joint, sign in ((left, -1.0), (right, 1.0)):
                speed = (forward + sign * turn * separation / 2) / (diameter / 2)
                p.setJointMotorControl2(
                    body,
                    joints[joint],
                    p.VELOCITY_CONTROL,
                    targetVelocity=speed,
                    force=10.0,
                    physicsClientId=client,
                )
        p.stepSimulation(physicsClientId=client)
    wall = time.perf_counter() - start
    position = p.getBasePositionAndOrientation(body, physicsClientId=client)[0]
    p.disconnect(physicsClientId=client)
    return {"rtf": seconds / wall, "simulated_s": seconds, "end_xy": list(position[:2])}


def _strip_meshes(urdf: str) -> str:
    """The URDF without mesh visuals (PyBullet reads the collisions; visuals cost nothing here)."""
    from lxml import etree

    root = etree.fromstring(urdf.encode())
    for visual in root.iter("visual"):
        if visual.find(".//mesh") is not None:
            visual.getparent().remove(visual)
    for gazebo in root.findall("gazebo"):
        root.remove(gazebo)
    return etree.tostring(root, encoding="unicode")


def wander_contacts(seconds: float) -> dict[str, Any]:
    """The TurtleBot3 wandering in the house; every contact with something but the ground."""
    session = Session("house", BURGER)
    world = session.world
    wanderer = Wanderer(session)
    session.server.hooks.append(wanderer)
    plant = world.plant
    instance = world.model_instance(BURGER)
    robot_bodies = {plant.get_body(b).name() for b in plant.GetBodyIndices(instance)}
    events: list[dict[str, Any]] = []
    touching: dict[tuple[str, str], dict[str, Any]] = {}
    state = {"next": 0.0, "samples": 0, "min_center": math.inf}

    def check(server: Any) -> None:
        t = server.world.time
        if t + 1e-9 < state["next"]:
            return
        state["next"] = t + 0.01
        state["samples"] += 1
        now = set()
        for a, b in world.contact_pairs():
            mine, other = (a, b) if a in robot_bodies else (b, a)
            if mine not in robot_bodies or other in robot_bodies or "ground" in other:
                continue
            now.add((mine, other))
        for pair in now - set(touching):
            readings = wanderer.logic.readings
            x, y, yaw = session.pose2d()
            touching[pair] = {
                "start_s": round(t, 3),
                "robot_link": pair[0],
                "touched": pair[1],
                "pose": [round(x, 3), round(y, 3), round(yaw, 3)],
                "state": wanderer.logic.state.name,
                "readings_m": [round(r, 3) for r in readings] if readings else None,
                "min_scan_m": _min_scan(session),
            }
        for pair in set(touching) - now:
            event = touching.pop(pair)
            event["end_s"] = round(t, 3)
            events.append(event)
        if wanderer.logic.readings:
            state["min_center"] = min(state["min_center"], wanderer.logic.readings[0])

    session.server.hooks.append(check)
    start = time.perf_counter()
    session.server.run(until=seconds)
    wall = time.perf_counter() - start
    for event in touching.values():
        event["end_s"] = None
        events.append(event)
    x, y, _ = session.pose2d()
    session.close()
    events.sort(key=lambda e: e["start_s"])
    return {
        "simulated_s": seconds,
        "contacts": len(events),
        "events": events,
        "touched": sorted({e["touched"] for e in events}),
        "contact_checks": state["samples"],
        "min_center_reading_m": state["min_center"],
        "end_xy": [x, y],
        "rtf_with_contact_checks": seconds / wall,
    }


def _min_scan(session: Session) -> float | None:
    laser = session.laser
    if laser is None or laser.latest is None:
        return None
    finite = laser.latest[np.isfinite(laser.latest)]
    return round(float(finite.min()), 3) if finite.size else None


# --- main ---------------------------------------------------------------------------------


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="short runs (a smoke test)")
    parser.add_argument("--no-wander", action="store_true", help="skip the 10-minute wander")
    options = parser.parse_args()
    quick = options.quick
    np.random.seed(SEED)

    accuracy = {"lidar": lidar_accuracy(), "depth": depth_accuracy()}
    distance = 2.0 if quick else 20.0
    odometry = {robot: odometry_drift(robot, distance) for robot in (CUSTOM, BURGER)}
    sensors = sensor_speed(5 if quick else 50)
    seconds = 2.0 if quick else 30.0
    rtf: dict[str, Any] = {}
    for robot in (BURGER, CUSTOM):
        rtf[robot] = {
            "workbench": workbench_rtf(robot, seconds, 2.0 if quick else 10.0),
            "bare_physics": bare_physics_rtf(robot, seconds),
            "pybullet": pybullet_rtf(robot, seconds),
        }
    wander = None if options.no_wander else wander_contacts(10.0 if quick else 600.0)

    machine = describe(("drake", "pybullet", "numpy"))
    report(machine, accuracy, odometry, sensors, rtf, wander)
    results = {
        "machine": machine,
        "seed": SEED,
        "quick": quick,
        "accuracy": accuracy,
        "odometry": odometry,
        "sensor_speed": sensors,
        "real_time_factor": rtf,
        "wander": wander,
    }
    out = Path(__file__).resolve().parent / "results" / "sensors.json"
    out.write_text(json.dumps(results, indent=2) + "\n")
    print(f"wrote {out}")


def report(
    machine: dict[str, Any],
    accuracy: dict[str, Any],
    odometry: dict[str, Any],
    sensors: dict[str, Any],
    rtf: dict[str, Any],
    wander: dict[str, Any] | None,
) -> None:
    print(f"machine: {machine}")
    lidar, depth = accuracy["lidar"], accuracy["depth"]
    print("\naccuracy against closed-form geometry (noise off)")
    print("| sensor | max error | within 1 cm | notes |\n|---|---|---|---|")
    print(
        f"| lidar, {lidar['beams']} beams | {lidar['max_error_m'] * 1e3:.3f} mm | "
        f"{lidar['within_1cm']}/{lidar['beams']} | ranges {lidar['range_m'][0]:.2f}-"
        f"{lidar['range_m'][1]:.2f} m |"
    )
    print(
        f"| depth 640 x 480 | {depth['max_error_m'] * 1e3:.1f} mm "
        f"({depth['max_error_off_silhouettes_m'] * 1e3:.2f} mm off silhouettes) | "
        f"{depth['within_1cm']}/{depth['pixels']} | {depth['silhouette_pixels']} silhouette "
        f"pixels; off them {depth['within_1cm_off_silhouettes']}/"
        f"{depth['pixels'] - depth['silhouette_pixels']}; median {depth['median_error_m'] * 1e3:.2f} mm |"
    )
    print("\nodometry (diff drive, odometrySource encoder) against the true pose")
    print(
        "| robot | path | final drift | max drift | heading error | wheels / true path "
        "| odometry vs kinematics |\n|---|---|---|---|---|---|---|"
    )
    for row in odometry.values():
        print(
            f"| {row['robot']} | {row['path_m']:.2f} m | {row['final_drift_m'] * 100:.1f} cm "
            f"({row['drift_percent_of_path']:.2f} %) | {row['max_drift_m'] * 100:.1f} cm | "
            f"{math.degrees(row['final_heading_error_rad']):.2f} deg | "
            f"{row['wheel_over_true_path']:.4f} | {row['odometry_vs_kinematics_max_m'] * 1e3:.2f} mm |"
        )
    laser, frame = sensors["laser"], sensors["depth"]
    print("\nsensors in the house, ms per scan / frame (median)")
    print(
        "| sensor | workbench | PyBullet | PyBullet / workbench | workbench cost at its rate |"
        "\n|---|---|---|---|---|"
    )
    for label, row, what in (
        (f"laser {laser['beams']} beams @ {laser['rate_hz']:g} Hz", laser, "rayTestBatch"),
        (f"depth 640 x 480 @ {frame['rate_hz']:g} Hz", frame, "getCameraImage TinyRenderer"),
    ):
        ours, theirs = row["workbench_ms"], row["pybullet_ms"]
        cost = f"{ours * row['rate_hz'] / 10:.1f} % of a simulated second"
        if theirs is not None:
            print(
                f"| {label} | {ours:.2f} | {theirs:.2f} ({what}) | {theirs / ours:.2f}x | {cost} |"
            )
        else:
            print(f"| {label} | {ours:.2f} | n/a | | {cost} |")
    if "agree_beams" in laser:
        print(
            f"laser agreement with PyBullet: {laser['agree_beams']}/{laser['beams']} beams, "
            f"max difference {laser['max_difference_m'] * 1e3:.2f} mm"
        )
    from workbench.sim.world_file import load_world

    step = load_world("house").physics.time_step or 0.001
    print(
        "\nreal-time factor, wandering in the house (workbench sim house --fast: as fast as "
        f"possible, the world's {step * 1e3:g} ms step)"
    )
    print(
        "| robot | workbench server | target | bare Drake physics | PyBullet | workbench / PyBullet |"
        "\n|---|---|---|---|---|---|"
    )
    for robot, row in rtf.items():
        target = 20.0 if robot == BURGER else 5.0
        ours = row["workbench"]["rtf"]
        theirs = row["pybullet"]["rtf"] if row["pybullet"] else None
        met = "met" if ours >= target else "MISSED"
        print(
            f"| {robot} | {ours:.1f}x | {target:g}x ({met}) | {row['bare_physics']:.1f}x | "
            + (f"{theirs:.1f}x | {ours / theirs:.2f} |" if theirs else "n/a | |")
        )
    for robot, row in rtf.items():
        bench = row["workbench"]
        print(
            f"\nprofile, {robot}: {bench['profiled_s']:g} simulated s in "
            f"{bench['profiled_wall_s']:.2f} s wall under cProfile, top by own time"
        )
        print("| function | calls | own s | cumulative s |\n|---|---|---|---|")
        for entry in row["workbench"]["profile"][:10]:
            print(
                f"| {entry['function']} | {entry['calls']} | {entry['tottime_s']:.3f} | "
                f"{entry['cumtime_s']:.3f} |"
            )
    if wander is not None:
        print(
            f"\nwander: TurtleBot3 in the house for {wander['simulated_s']:g} simulated s: "
            f"{wander['contacts']} contacts with something but the ground "
            f"(checked {wander['contact_checks']} times; RTF {wander['rtf_with_contact_checks']:.1f}x)"
        )
        if wander["events"]:
            print(
                "| start s | end s | link | touched | state | readings c/l/r m | nearest scan m |"
            )
            print("|---|---|---|---|---|---|---|")
            for event in wander["events"][:20]:
                print(
                    f"| {event['start_s']} | {event['end_s']} | {event['robot_link']} | "
                    f"{event['touched']} | {event['state']} | {event['readings_m']} | "
                    f"{event['min_scan_m']} |"
                )


if __name__ == "__main__":
    main()
