"""The browser RViz: how fast it draws what is published, against drawing with Meshcat directly.

Run ``python benchmarks/rviz.py`` (``--quick`` for shorter runs). Writes
``benchmarks/results/rviz.json`` and prints a table with the machine.

Scenes (one in-process bus, the viewer updating 60 times a second):

* a 720-beam LaserScan published at 40 Hz for 5 s;
* a 640 x 480 PointCloud2 (xyz + rgb) published at 10 Hz for 5 s;
* one 4000 x 4000 OccupancyGrid;
* a MarkerArray of 10,000 cubes.

Reported: the rate the viewer drew at, the latency from publish to drawn
(median and worst), the longest ``publish()`` call while the viewer worked
(publishers must never wait for it), and the same drawing done by direct
Meshcat calls (no bus, no tf, no message decoding) as the baseline.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import threading
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from machine import describe  # noqa: E402

SEED = 0


def _stamp(message, t: float) -> None:
    message.header.stamp.sec = int(t)
    message.header.stamp.nanosec = int((t - int(t)) * 1e9)


def _seconds(stamp) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


class Watch:
    """Records, per draw of ``display``, the latency from publish (the header stamp) to drawn.

    The viewer is updated by :meth:`run` in the calling thread: Drake's Meshcat may
    only be driven from the thread that created it.
    """

    def __init__(self, rviz, display) -> None:
        self.rviz, self.display = rviz, display
        self.latencies: list[float] = []
        self.draws = 0
        original = display.draw

        def draw(context, message):
            original(context, message)
            self.latencies.append(time.time() - _seconds(message.header.stamp))
            self.draws += 1

        display.draw = draw

    def run(self, until) -> None:
        """Update 60 times a second until ``until()`` is true."""
        while not until():
            self.rviz.update()
            time.sleep(1 / 60)
        self.rviz.update()


def stream(make, topic_type, topic, display_name, rate, seconds, options=None):
    from workbench.bus import Bus, Node
    from workbench.msgs.geometry_msgs import TransformStamped
    from workbench.rviz import RViz
    from workbench.tf import StaticTransformBroadcaster

    bus = Bus()
    rviz = RViz(bus, fixed_frame="map", displays=[])
    display = rviz.add_display(display_name, **(options or {}))
    node = Node("bench", bus=bus)
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = "map", "sensor"
    t.transform.rotation.w = 1.0
    StaticTransformBroadcaster(node).sendTransform(t)
    publisher = node.create_publisher(topic, topic_type)
    watch = Watch(rviz, display)
    message = make()
    worst = [0.0]
    n = int(rate * seconds)
    done = threading.Event()

    def publish() -> None:
        begin = time.monotonic()
        for k in range(n):
            _stamp(message, time.time())
            t0 = time.perf_counter()
            publisher.publish(message)
            worst[0] = max(worst[0], time.perf_counter() - t0)
            time.sleep(max(0.0, begin + (k + 1) / rate - time.monotonic()))
        time.sleep(0.3)
        done.set()

    thread = threading.Thread(target=publish, daemon=True)
    thread.start()
    watch.run(done.is_set)
    worst_publish = worst[0]
    rviz.close()
    bus.shutdown()
    return {
        "published_hz": n / seconds,
        "drawn_hz": watch.draws / seconds,  # every message is drawn: same count as published
        "latency_median_ms": 1e3 * statistics.median(watch.latencies) if watch.latencies else None,
        "latency_max_ms": 1e3 * max(watch.latencies) if watch.latencies else None,
        "worst_publish_ms": 1e3 * worst_publish,
    }


def one_shot(make, topic_type, topic, display_name):
    from workbench.bus import Bus, Node
    from workbench.rviz import RViz

    bus = Bus()
    rviz = RViz(bus, fixed_frame="map", displays=[])
    display = rviz.add_display(display_name)
    node = Node("bench", bus=bus)
    publisher = node.create_publisher(topic, topic_type)
    message = make()
    start = time.time()
    if hasattr(message, "header"):
        _stamp(message, start)
    t0 = time.perf_counter()
    publisher.publish(message)
    publish = time.perf_counter() - t0
    deadline = time.monotonic() + 60
    while display.drawn == 0 and time.monotonic() < deadline:
        rviz.update()
        time.sleep(0.001)
    latency = time.time() - start
    rviz.close()
    bus.shutdown()
    return {"latency_ms": 1e3 * latency, "publish_ms": 1e3 * publish}


def laser():
    from workbench.msgs.sensor_msgs import LaserScan

    rng = np.random.default_rng(SEED)
    scan = LaserScan(angle_min=-np.pi / 2, angle_max=np.pi / 2, angle_increment=np.pi / 720)
    scan.range_min, scan.range_max = 0.05, 30.0
    scan.header.frame_id = "sensor"
    scan.ranges = list(rng.uniform(0.5, 10.0, 720))
    return scan


def cloud():
    from workbench.msgs.sensor_msgs import PointCloud2, PointField

    rng = np.random.default_rng(SEED)
    n = 640 * 480
    xyz = rng.uniform(-2, 2, (n, 3)).astype("<f4")
    rgb = rng.integers(0, 2**24, n).astype("<u4")
    data = np.zeros(n, dtype=[("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("rgb", "<u4")])
    data["x"], data["y"], data["z"], data["rgb"] = xyz[:, 0], xyz[:, 1], xyz[:, 2], rgb
    message = PointCloud2(height=480, width=640, point_step=16, row_step=640 * 16, is_dense=True)
    message.header.frame_id = "sensor"
    message.fields = [
        PointField(name=name, offset=4 * i, datatype=7 if name != "rgb" else 6, count=1)
        for i, name in enumerate(("x", "y", "z", "rgb"))
    ]
    message.data = data.tobytes()
    return message


def big_map():
    from workbench.msgs.nav_msgs import OccupancyGrid

    rng = np.random.default_rng(SEED)
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.info.width = grid.info.height = 4000
    grid.info.resolution = 0.05
    grid.info.origin.orientation.w = 1.0
    cells = rng.choice(np.array([-1, 0, 100], dtype=np.int8), size=4000 * 4000, p=[0.3, 0.6, 0.1])
    grid.data = cells
    return grid


def cubes():
    from workbench.msgs.visualization_msgs import Marker, MarkerArray

    markers = []
    for i in range(10_000):
        m = Marker(type=Marker.CUBE, id=i, ns="cubes")
        m.header.frame_id = "map"
        m.pose.position.x, m.pose.position.y = float(i % 100), float(i // 100)
        m.pose.orientation.w = 1.0
        m.scale.x = m.scale.y = m.scale.z = 0.5
        m.color.r = m.color.a = 1.0
        markers.append(m)
    return MarkerArray(markers=markers)


def baseline_laser(repeats: int) -> float:
    """Direct Meshcat: ranges to points, SetObject(PointCloud) and SetTransform, ms per scan."""
    from pydrake.geometry import Meshcat, Rgba
    from pydrake.math import RigidTransform
    from pydrake.perception import BaseField, Fields, PointCloud

    meshcat = Meshcat()
    scan = laser()
    ranges = np.asarray(scan.ranges)
    angles = scan.angle_min + scan.angle_increment * np.arange(len(ranges))
    t0 = time.perf_counter()
    for _ in range(repeats):
        xyz = np.stack([ranges * np.cos(angles), ranges * np.sin(angles), np.zeros_like(ranges)])
        points = PointCloud(xyz.shape[1], Fields(BaseField.kXYZs))
        points.mutable_xyzs()[:] = xyz.astype(np.float32)
        meshcat.SetObject("/scan", points, 0.03, Rgba(1, 0, 0, 1))
        meshcat.SetTransform("/scan", RigidTransform())
    return 1e3 * (time.perf_counter() - t0) / repeats


def baseline_cloud(repeats: int) -> float:
    from pydrake.geometry import Meshcat, Rgba
    from pydrake.perception import BaseField, Fields, PointCloud

    meshcat = Meshcat()
    rng = np.random.default_rng(SEED)
    xyz = rng.uniform(-2, 2, (3, 640 * 480)).astype(np.float32)
    rgb = rng.integers(0, 255, (3, 640 * 480)).astype(np.uint8)
    t0 = time.perf_counter()
    for _ in range(repeats):
        points = PointCloud(xyz.shape[1], Fields(BaseField.kXYZs | BaseField.kRGBs))
        points.mutable_xyzs()[:] = xyz
        points.mutable_rgbs()[:] = rgb
        meshcat.SetObject("/cloud", points, 0.01, Rgba(1, 1, 1, 1))
    return 1e3 * (time.perf_counter() - t0) / repeats


def baseline_cubes() -> float:
    from pydrake.geometry import Box, Meshcat, Rgba
    from pydrake.math import RigidTransform

    meshcat = Meshcat()
    t0 = time.perf_counter()
    for i in range(10_000):
        meshcat.SetObject(f"/cubes/{i}", Box(0.5, 0.5, 0.5), Rgba(1, 0, 0, 1))
        meshcat.SetTransform(f"/cubes/{i}", RigidTransform([float(i % 100), float(i // 100), 0.0]))
    return 1e3 * (time.perf_counter() - t0)


def main() -> None:
    from workbench.msgs.nav_msgs import OccupancyGrid
    from workbench.msgs.sensor_msgs import LaserScan, PointCloud2
    from workbench.msgs.visualization_msgs import MarkerArray

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1 s streams")
    options = parser.parse_args()
    seconds = 1.0 if options.quick else 5.0
    results = {
        "laser_720_40hz": stream(laser, LaserScan, "scan", "LaserScan", 40, seconds),
        "cloud_640x480_10hz": stream(cloud, PointCloud2, "points", "PointCloud2", 10, seconds),
        # the second of two runs: the first also pays for imports and the Meshcat start
        "map_4000x4000": [one_shot(big_map, OccupancyGrid, "map", "Map") for _ in range(2)][1],
        "markers_10000_cubes": one_shot(
            cubes, MarkerArray, "visualization_marker_array", "MarkerArray"
        ),
    }
    baseline = {
        "laser_ms": baseline_laser(50),
        "cloud_ms": baseline_cloud(5),
        "cubes_ms_individual_objects": baseline_cubes(),
    }
    machine = describe(("drake", "numpy"))
    print(f"machine: {machine}")
    laser_r, cloud_r = results["laser_720_40hz"], results["cloud_640x480_10hz"]
    print("| scene | published | drawn | latency median / max | worst publish() | direct Meshcat |")
    print("|---|---|---|---|---|---|")
    for label, r, base in (
        ("LaserScan 720 beams", laser_r, baseline["laser_ms"]),
        ("PointCloud2 640x480", cloud_r, baseline["cloud_ms"]),
    ):
        print(
            f"| {label} | {r['published_hz']:.0f} Hz | {r['drawn_hz']:.1f} Hz | "
            f"{r['latency_median_ms']:.1f} / {r['latency_max_ms']:.1f} ms | "
            f"{r['worst_publish_ms']:.2f} ms | {base:.1f} ms per draw |"
        )
    m, c = results["map_4000x4000"], results["markers_10000_cubes"]
    print(
        f"| OccupancyGrid 4000x4000 | once | once | {m['latency_ms']:.0f} ms | {m['publish_ms']:.2f} ms | — |"
    )
    print(
        f"| MarkerArray 10,000 cubes | once | once | {c['latency_ms']:.0f} ms | {c['publish_ms']:.2f} ms "
        f"| {baseline['cubes_ms_individual_objects']:.0f} ms (one Meshcat object per cube) |"
    )
    out = Path(__file__).resolve().parent / "results" / "rviz.json"
    out.write_text(
        json.dumps(
            {"machine": machine, "seed": SEED, "results": results, "baseline": baseline}, indent=2
        )
        + "\n"
    )
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
