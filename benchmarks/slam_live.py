"""Live SLAM in the house: slam_gmapping on the simulated TurtleBot3, against dead reckoning.

Experiment 10 as one process: ``workbench sim house --fast`` (the house world's 8 ms
physics step), the TurtleBot3 burger spawned at the origin with its diff drive's odometry
from the wheel encoders (``odometrySource encoder``, so dead reckoning drifts as a real
robot's does; the shipped URDF reports Gazebo's true pose, as turtlebot3_description's
does), robot_state_publisher, the ``slam_gmapping`` node with turtlebot3_slam's
parameters and the wander node's decisions (turtlebot3_drive, every 50 simulated ms), all
on one in-process bus. The simulator is stepped as fast as it goes while slam_gmapping's
worker thread matches the newest scan, as two processes would run side by side; after each
50 ms step the script waits until no scan waits for the worker, so no scan is dropped
(slam_gmapping keeps up) and the run is reproducible, and before each sample until every
scan is processed.

Measured over ``--minutes`` simulated minutes (10 by default):

* map precision and recall of occupied cells against the house's true walls at the
  laser's height, within one cell (precision: mapped cells on a wall; recall: wall faces
  the robot saw free space next to, mapped as occupied);
* the SLAM trajectory (``map -> base_footprint`` from tf) and dead reckoning
  (``odom -> base_footprint``) against the simulator's true pose, sampled every simulated
  second: RMS and maximum position error (no alignment: all three share the start);
* speed: simulated seconds per wall second for the whole (simulator + SLAM + wander),
  and the simulator alone over the same drive (the same commands replayed without SLAM).

Run:  python benchmarks/slam_live.py [--minutes M] [--seed N]
Writes benchmarks/results/slam_live.json and prints a table with the machine.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
import yaml
from machine import describe  # noqa: E402

from workbench.paths import examples_dir, mapping_dir, urdf_dir

HERE = Path(__file__).resolve().parent
ROBOT = "turtlebot3_burger"
DECISION = 0.05  # simulated s between two decisions of the wander node
SCAN_HEIGHT = 0.182  # base_scan above the floor, m
TARGETS = {"ate_m": 0.05, "precision": 0.95, "rtf": 10.0}


def encoder_urdf() -> str:
    text = (urdf_dir() / f"{ROBOT}.urdf").read_text()
    source = "<odometrySource>world</odometrySource>"
    if source in text:
        return text.replace(source, "<odometrySource>encoder</odometrySource>")
    marker = "<legacyMode>false</legacyMode>"
    assert marker in text, "the burger's diff drive block changed"
    return text.replace(marker, marker + "<odometrySource>encoder</odometrySource>", 1)


class Run:
    """The house, the burger, robot_state_publisher and (with ``slam``) slam_gmapping."""

    def __init__(self, *, slam: bool, encoder: bool = True, step: float | None = None) -> None:
        from workbench.bus import Bus, Node
        from workbench.mapping.gmapping_node import SlamGMapping
        from workbench.mapping.gmapping_params import read_params
        from workbench.model import load_robot
        from workbench.msgs import gazebo_msgs as gm
        from workbench.robot_state import RobotStatePublisher
        from workbench.sim.gazebo_ros import GazeboRosApi
        from workbench.sim.gzserver import ServerOptions, build_server
        from workbench.tf import Buffer, TransformListener

        self.bus = Bus()
        self.bus.params.set("/use_sim_time", True)
        options = ServerOptions(world="house", fast=True, view=False, max_step_size=step)
        self.world, self.server, _ = build_server(options, self.bus)
        self.api = GazeboRosApi(self.server, Node("gazebo", bus=self.bus))
        self.me = Node("benchmark", bus=self.bus)
        urdf = encoder_urdf() if encoder else (urdf_dir() / f"{ROBOT}.urdf").read_text()
        request = gm.SpawnModel.Request(model_name=ROBOT, model_xml=urdf, robot_namespace="/")
        request.initial_pose.orientation.w = 1.0
        client = self.me.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel)
        assert client.call(request).success
        robot = load_robot(urdf_dir() / f"{ROBOT}.urdf")  # the same links and joints
        self.rsp = RobotStatePublisher(robot, Node("robot_state_publisher", bus=self.bus))
        self.buffer = Buffer()
        TransformListener(self.buffer, self.me)
        self.mapper: Any = None
        self.maps: list[Any] = []
        if slam:
            from workbench.msgs.nav_msgs import OccupancyGrid

            config = examples_dir() / "packages/turtlebot3_slam/config/gmapping_params.yaml"
            node = Node("slam_gmapping", bus=self.bus)
            for key, value in yaml.safe_load(config.read_text()).items():
                node.set_param(f"~{key}", value)
            self.mapper = SlamGMapping(node, read_params(node))
            self.me.create_subscription("/map", OccupancyGrid, self.maps.append, 10, inline=True)

    def caught_up(self, timeout: float = 10.0, *, busy: bool = False) -> None:
        """Wait until slam_gmapping has processed every scan (``busy``: until the newest,
        if any, is in its hands and none waits to be replaced)."""
        from workbench.mapping.gmapping_node import SKIPPED_AT_START

        if self.mapper is None:
            return
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if busy and not self.mapper.waiting:
                return
            used = max(0, self.mapper.received - SKIPPED_AT_START)
            if self.mapper.processed + self.mapper.dropped >= used:
                return
            time.sleep(0.0005)

    def pose(self, frame: str) -> tuple[float, float] | None:
        from workbench.tf import TransformException

        try:
            t = self.buffer.lookup_transform(frame, "base_footprint", 0).transform.translation
        except TransformException:
            return None
        return float(t.x), float(t.y)

    def truth(self) -> tuple[float, float]:
        p = self.world.get_model_pose(ROBOT).translation()
        return float(p[0]), float(p[1])

    def close(self) -> None:
        if self.mapper is not None:
            self.mapper.close()
        self.api.close()
        self.server.stop()
        self.bus.shutdown()


def wander(run: Run, seconds: float, commands: list[Any] | None) -> dict[str, Any]:
    """Drive ``seconds``: decide (or replay ``commands``), step, let SLAM catch up, sample."""
    from workbench.msgs.geometry_msgs import Twist
    from workbench.msgs.nav_msgs import Odometry
    from workbench.msgs.sensor_msgs import LaserScan
    from workbench.teleop.turtlebot3_drive import Turtlebot3Drive

    cmd_vel = run.me.create_publisher("/cmd_vel", Twist, 10)
    decide = commands is None
    logic = Turtlebot3Drive()
    if decide:
        run.me.create_subscription("/scan", LaserScan, logic.on_scan, 10, inline=True)
        run.me.create_subscription("/odom", Odometry, logic.on_odom, 10, inline=True)
        commands = []
    run.server.run(until=0.5)  # settle
    begin, wall = run.world.time, time.perf_counter()
    samples: list[tuple[float, ...]] = []
    next_sample = begin + 1.0
    k = 0
    while run.world.time - begin < seconds - 1e-9:
        if decide:
            command = logic.step()
            commands.append(None if command is None else (command.x, command.yaw))
        command_xy = commands[k] if k < len(commands) else None
        k += 1
        if command_xy is not None:
            twist = Twist()
            twist.linear.x, twist.angular.z = command_xy
            cmd_vel.publish(twist)
        run.server.run(until=run.world.time + DECISION)
        # slam_gmapping works on the newest scan while the simulator steps on (as two
        # processes do), but never falls further behind: no scan waits to be replaced.
        run.caught_up(busy=True)
        if run.world.time >= next_sample:
            run.caught_up()
            next_sample += 1.0
            slam, odom = run.pose("map"), run.pose("odom")
            if odom is not None:
                samples.append((*run.truth(), *(slam or (math.nan, math.nan)), *odom))
    elapsed = time.perf_counter() - wall
    return {
        "simulated_s": run.world.time - begin,
        "wall_s": elapsed,
        "samples": samples,
        "commands": commands,
    }


def map_quality(grid_message: Any) -> dict[str, Any]:
    """Precision and recall of the occupied cells against the house's walls (one cell)."""
    from workbench.sim.building import blocked_cells, load_plan

    info = grid_message.info
    cells = np.asarray(grid_message.data, dtype=int).reshape(info.height, info.width)
    xs = info.origin.position.x + (np.arange(info.width) + 0.5) * info.resolution
    ys = info.origin.position.y + (np.arange(info.height) + 0.5) * info.resolution
    plan = load_plan(mapping_dir() / "plans" / "house.yaml")
    truth = blocked_cells(plan.pieces(), xs, ys, (SCAN_HEIGHT, SCAN_HEIGHT))
    mapped = cells >= 65
    free = (cells >= 0) & (cells <= 25)
    surface = truth & grow(~truth)
    seen = surface & grow(free)
    return {
        "precision": float((mapped & grow(truth)).sum() / max(mapped.sum(), 1)),
        "recall": float((seen & grow(mapped)).sum() / max(seen.sum(), 1)),
        "occupied_cells": int(mapped.sum()),
        "wall_cells_seen": int(seen.sum()),
    }


def save_final_map(grid_message: Any, name: Path) -> None:
    """``map_saver -f NAME`` run in NAME's folder, so the YAML names its image relatively."""
    import os

    from workbench.mapping.map_saver_node import save_map_files

    here = Path.cwd()
    name.parent.mkdir(parents=True, exist_ok=True)
    os.chdir(name.parent)
    try:
        save_map_files(grid_message, name.name, log=print)
    finally:
        os.chdir(here)


def grow(mask: np.ndarray) -> np.ndarray:
    """``mask`` dilated by one cell (8-neighbourhood)."""
    out = mask.copy()
    padded = np.pad(mask, 1)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            out |= padded[1 + dy : 1 + dy + mask.shape[0], 1 + dx : 1 + dx + mask.shape[1]]
    return out


def errors(samples: list[tuple[float, ...]], columns: slice) -> dict[str, float]:
    data = np.asarray(samples, dtype=float)
    diff = data[:, columns] - data[:, 0:2]
    distance = np.hypot(diff[:, 0], diff[:, 1])
    distance = distance[np.isfinite(distance)]
    return {"rms_m": float(np.sqrt(np.mean(distance**2))), "max_m": float(distance.max())}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="simulated minutes")
    parser.add_argument("--seed", type=int, default=0, help="seed of the simulator's plugins")
    parser.add_argument(
        "--odometry", choices=("encoder", "world"), default="encoder", help="the drive's source"
    )
    parser.add_argument(
        "--max-step-size", type=float, help="physics step, s (default: the world's)"
    )
    parser.add_argument("--out", type=Path, default=HERE / "results" / "slam_live.json")
    parser.add_argument(
        "--save-map", type=Path, help="also save the final map as NAME.pgm/NAME.yaml (map_saver)"
    )
    args = parser.parse_args(argv)
    np.random.seed(args.seed)
    seconds = 60.0 * args.minutes

    setup = {"encoder": args.odometry == "encoder", "step": args.max_step_size}
    run = Run(slam=True, **setup)
    try:
        live = wander(run, seconds, None)
        run.server.run(until=run.world.time + 0.5)
        run.caught_up()
        run.mapper.update_map()
        quality = map_quality(run.maps[-1])
        if args.save_map is not None:
            save_final_map(run.maps[-1], args.save_map)
        counts = {k: getattr(run.mapper, k) for k in ("received", "processed", "dropped")}
    finally:
        run.close()
    bare = Run(slam=False, **setup)
    try:
        alone = wander(bare, seconds, live["commands"])
    finally:
        bare.close()

    result = {
        "machine": describe(("drake", "numpy")),
        "seed": args.seed,
        "odometry": args.odometry,
        "step_s": args.max_step_size,
        "simulated_s": live["simulated_s"],
        "rtf_slam_and_sim": live["simulated_s"] / live["wall_s"],
        "rtf_sim_alone": alone["simulated_s"] / alone["wall_s"],
        "slam": errors(live["samples"], slice(2, 4)),
        "dead_reckoning": errors(live["samples"], slice(4, 6)),
        "map": quality,
        "scans": counts,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=1))
    report(result)
    return 0


def report(result: dict[str, Any], title: str = "live SLAM in the house") -> None:
    m = result["machine"]
    print(f"machine: {m['cpu']}, {m['usable_cores']} cores, load {m['load_average']}")
    print(f"{title}: {result['simulated_s']:.0f} simulated s, seed {result['seed']}")
    source = "encoders" if result["odometry"] == "encoder" else "Gazebo's true pose, as shipped"
    print(f"| measure | slam_gmapping | dead reckoning ({source}) | target |\n|---|---|---|---|")
    slam, odom, quality = result["slam"], result["dead_reckoning"], result["map"]
    print(
        f"| position error RMS (max) | {slam['rms_m']:.3f} m ({slam['max_m']:.3f}) | "
        f"{odom['rms_m']:.3f} m ({odom['max_m']:.3f}) | ≤ {TARGETS['ate_m']} m |"
    )
    print(f"| map precision | {quality['precision']:.3f} | — | ≥ {TARGETS['precision']} |")
    print(f"| map recall | {quality['recall']:.3f} | — | — |")
    print(
        f"| real-time factor | {result['rtf_slam_and_sim']:.1f}× (simulator + SLAM) | "
        f"{result['rtf_sim_alone']:.1f}× (simulator alone) | ≥ {TARGETS['rtf']:g}× |"
    )
    scans = result.get("scans")
    if scans is None:
        return
    print(
        f"scans: {scans['received']} received, {scans['processed']} processed, "
        f"{scans['dropped']} dropped"
    )


if __name__ == "__main__":
    sys.exit(main())
