"""The simulated sensors: workbench's lidar and depth camera against PyBullet's.

Run ``python benchmarks/sensors_lidar.py`` (``--quick`` for fewer repetitions).
Writes ``benchmarks/results/sensors_lidar.json`` and prints a table with the machine.

* Lidar: 720 beams over 360 degrees, 0.1-30 m, from the middle of a house-like
  layout of about 100 static boxes and cylinders (outer and inner walls, tables,
  shelves, chairs, bins and pillars; seeded), and of ten such houses side by
  side (about 1000 shapes, to show the broad phase). workbench:
  ``Lidar(spec).scan(world, X_WS)`` (numpy, exact, poses read from the plant
  each scan); PyBullet: ``rayTestBatch`` with the same 720 rays against the same
  shapes (``pip install pybullet``). The two agree to the printed difference.
* Depth: one 640 x 480 depth frame (hfov 60 degrees) of the house, Drake's
  ``RenderEngineVtk`` (``Camera.capture``) vs PyBullet's ``getCameraImage``
  with its CPU TinyRenderer.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from machine import describe  # noqa: E402
from sensors import median_ms  # noqa: E402

from workbench.sim import World  # noqa: E402
from workbench.sim.sensors import Camera, Lidar, parse_sensor  # noqa: E402
from workbench.spatial import rigid_transform  # noqa: E402

HEIGHT = 1.0
SENSOR = (0.3, 0.2, 0.3)
LASER = """<sensor type="gpu_ray" name="laser"><update_rate>40</update_rate><ray><scan><horizontal>
<samples>720</samples><resolution>1</resolution><min_angle>-3.14159</min_angle><max_angle>3.14159</max_angle>
</horizontal></scan><range><min>0.1</min><max>30</max></range></ray></sensor>"""
DEPTH = """<sensor type="depth" name="kinect"><camera><horizontal_fov>1.0472</horizontal_fov>
<image><width>640</width><height>480</height></image><clip><near>0.05</near><far>30</far></clip>
</camera></sensor>"""


def house(offset_x: float = 0.0, seed: int = 0) -> list[tuple]:
    """About 100 shapes: ('box', centre, size, yaw) and ('cylinder', centre, radius)."""
    rng = np.random.default_rng(seed)
    shapes: list[tuple] = []
    w, d, t = 12.0, 9.0, 0.15
    for cx, cy, sx, sy in (
        (0, d / 2, w, t),
        (0, -d / 2, w, t),
        (w / 2, 0, t, d),
        (-w / 2, 0, t, d),
        (-2, 1.5, t, 6.0),
        (2.5, -1.5, t, 6.0),
        (-4, -1, 4.0, t),
        (4.2, 1.2, 3.6, t),
        (0.2, 3.0, 3.0, t),
        (-0.8, -3.2, 2.4, t),
    ):
        shapes.append(("box", (cx + offset_x, cy, HEIGHT / 2), (sx, sy, HEIGHT), 0.0))
    while len(shapes) < 64:  # tables, shelves, beds, boxes
        x, y = rng.uniform(-5.5, 5.5), rng.uniform(-4.0, 4.0)
        if math.hypot(x - SENSOR[0], y - SENSOR[1]) < 0.8:
            continue
        sx, sy, sz = rng.uniform(0.3, 1.6), rng.uniform(0.3, 0.9), rng.uniform(0.4, 1.0)
        shapes.append(("box", (x + offset_x, y, sz / 2), (sx, sy, sz), rng.uniform(-np.pi, np.pi)))
    while len(shapes) < 100:  # chair legs, bins, pillars, plants
        x, y = rng.uniform(-5.5, 5.5), rng.uniform(-4.0, 4.0)
        if math.hypot(x - SENSOR[0], y - SENSOR[1]) < 0.8:
            continue
        shapes.append(("cylinder", (x + offset_x, y, HEIGHT / 2), rng.uniform(0.03, 0.35)))
    return shapes


def layout(houses: int) -> list[tuple]:
    return [s for k in range(houses) for s in house(offset_x=13.0 * k, seed=k)]


def drake_world(shapes: list[tuple]) -> World:
    """A built World (no ground) with the shapes welded to the world.

    Registered on the plant directly, without the ground: a World with its ground half
    space segfaults inside pydrake's geometry registration past about 260 obstacles
    (drake 1.51.1 on the benchmark machine), with add_box or without.
    """
    from pydrake.geometry import Box, Cylinder
    from pydrake.multibody.plant import CoulombFriction

    world = World(ground=False)
    plant = world.plant
    color = np.array([0.6, 0.5, 0.4, 1.0])
    for i, shape in enumerate(shapes):
        if shape[0] == "box":
            _, centre, size, yaw = shape
            geometry, X = Box(*size), rigid_transform(list(centre), rpy=[0, 0, yaw])
        else:
            _, centre, radius = shape
            geometry, X = Cylinder(radius, HEIGHT), rigid_transform(list(centre))
        body = plant.world_body()
        plant.RegisterCollisionGeometry(body, X, geometry, f"s{i}", CoulombFriction(0.8, 0.6))
        plant.RegisterVisualGeometry(body, X, geometry, f"s{i}", color)
    world.build()
    return world


def pybullet_world(shapes: list[tuple]):  # type: ignore[no-untyped-def]
    import pybullet as p

    client = p.connect(p.DIRECT)
    for shape in shapes:
        if shape[0] == "box":
            _, centre, size, yaw = shape
            col = p.createCollisionShape(
                p.GEOM_BOX, halfExtents=[s / 2 for s in size], physicsClientId=client
            )
            vis = p.createVisualShape(
                p.GEOM_BOX, halfExtents=[s / 2 for s in size], physicsClientId=client
            )
            orn = p.getQuaternionFromEuler([0, 0, yaw])
        else:
            _, centre, radius = shape
            col = p.createCollisionShape(
                p.GEOM_CYLINDER, radius=radius, height=HEIGHT, physicsClientId=client
            )
            vis = p.createVisualShape(
                p.GEOM_CYLINDER, radius=radius, length=HEIGHT, physicsClientId=client
            )
            orn = [0, 0, 0, 1]
        p.createMultiBody(
            0, col, vis, basePosition=centre, baseOrientation=orn, physicsClientId=client
        )
    return p, client


def lidar_row(houses: int, repeats: int) -> dict[str, object]:
    shapes = layout(houses)
    world = drake_world(shapes)
    spec = parse_sensor(LASER, model="bench", link="base")
    lidar = Lidar(spec)
    X_WS = rigid_transform(list(SENSOR))
    ours = median_ms(lambda: lidar.scan(world, X_WS, noise=False), repeats)
    ranges = lidar.scan(world, X_WS, noise=False)
    row: dict[str, object] = {"shapes": len(shapes), "workbench_ms": ours, "pybullet_ms": None}
    try:
        p, client = pybullet_world(shapes)
    except ImportError:
        return row
    origin = np.array(SENSOR)
    directions = lidar.directions_S
    starts = np.repeat(origin[None], len(directions), axis=0)
    ends = starts + directions * spec.range_max

    def bullet_scan() -> list:
        return p.rayTestBatch(starts.tolist(), ends.tolist(), physicsClientId=client)

    row["pybullet_ms"] = median_ms(bullet_scan, repeats)
    hits = bullet_scan()
    theirs = np.array([h[2] * spec.range_max if h[0] >= 0 else np.inf for h in hits])
    both = np.isfinite(theirs) & np.isfinite(ranges)
    row["agree_beams"] = int((np.isfinite(theirs) == np.isfinite(ranges)).sum())
    row["max_difference_m"] = (
        float(np.abs(theirs[both] - ranges[both]).max()) if both.any() else 0.0
    )
    p.disconnect(physicsClientId=client)
    return row


def depth_row(repeats: int) -> dict[str, object]:
    shapes = layout(1)
    world = drake_world(shapes)
    camera = Camera(parse_sensor(DEPTH, model="bench", link="base"))
    X_WS = rigid_transform([SENSOR[0], SENSOR[1], 0.8], rpy=[0, 0.2, 0.4])
    ours = median_ms(lambda: camera.capture(world, X_WS, color=False, noise=False), repeats)
    row: dict[str, object] = {"workbench_ms": ours, "pybullet_ms": None}
    try:
        p, client = pybullet_world(shapes)
    except ImportError:
        return row
    forward = X_WS.rotation().matrix()[:, 0]
    eye = np.array([SENSOR[0], SENSOR[1], 0.8])
    view = p.computeViewMatrix(eye.tolist(), (eye + forward).tolist(), [0, 0, 1])
    vfov = math.degrees(2 * math.atan(math.tan(1.0472 / 2) * 480 / 640))
    projection = p.computeProjectionMatrixFOV(vfov, 640 / 480, 0.05, 30.0)
    row["pybullet_ms"] = median_ms(
        lambda: p.getCameraImage(
            640, 480, view, projection, renderer=p.ER_TINY_RENDERER, physicsClientId=client
        ),
        max(3, repeats // 5),
    )
    p.disconnect(physicsClientId=client)
    return row


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repetitions (a smoke test)")
    options = parser.parse_args()
    repeats = 10 if options.quick else 100
    lidar = {f"{n} house{'s' if n > 1 else ''}": lidar_row(n, repeats) for n in (1, 10)}
    depth = depth_row(5 if options.quick else 20)
    machine = describe(("drake", "pybullet", "numpy"))
    print(f"machine: {machine}")
    print("\nlidar: 720 beams, 360 degrees, 0.1-30 m, ms per scan (median)")
    print(
        "| world | shapes | workbench (numpy, exact) | PyBullet rayTestBatch | ratio | agreement |"
    )
    print("|---|---|---|---|---|---|")
    for label, row in lidar.items():
        ours, theirs = row["workbench_ms"], row["pybullet_ms"]
        assert isinstance(ours, float)
        if isinstance(theirs, float):
            agree = f"{row['agree_beams']}/720 beams, max diff {float(row['max_difference_m']) * 1e3:.1f} mm"  # type: ignore[arg-type]
            print(
                f"| {label} | {row['shapes']} | {ours:.2f} | {theirs:.2f} | "
                f"{theirs / ours:.1f}x faster | {agree} |"
            )
        else:
            print(f"| {label} | {row['shapes']} | {ours:.2f} | n/a (pip install pybullet) | | |")
    ours, theirs = depth["workbench_ms"], depth["pybullet_ms"]
    assert isinstance(ours, float)
    print("\ndepth frame 640 x 480, ms per frame (median)")
    print("| workbench (Drake RenderEngineVtk) | PyBullet getCameraImage (TinyRenderer) | ratio |")
    print("|---|---|---|")
    if isinstance(theirs, float):
        print(f"| {ours:.1f} | {theirs:.1f} | {theirs / ours:.1f}x faster |")
    else:
        print(f"| {ours:.1f} | n/a | |")
    out = Path(__file__).resolve().parent / "results" / "sensors_lidar.json"
    out.write_text(
        json.dumps({"machine": machine, "seed": 0, "lidar": lidar, "depth": depth}, indent=2) + "\n"
    )


if __name__ == "__main__":
    main()
