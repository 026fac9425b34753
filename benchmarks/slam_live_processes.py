"""Live SLAM in the house as a student runs it: simulator and slam_gmapping in their own processes.

``benchmarks/slam_live.py`` runs the simulator and SLAM as two threads of one process,
never letting SLAM drop a scan, which measures accuracy reproducibly. Here every node
runs in its own process (``workbench core``, one launch file): ``gzserver house --fast
--headless``, the TurtleBot3 burger with encoder odometry (``--odometry world``: the
shipped URDF's true pose), robot_state_publisher and slam_gmapping with turtlebot3_slam's
parameters; once slam_gmapping has published its first map (the robot standing still
until then, so the map frame starts at the true pose, as a student starts driving once
the map shows) turtlebot3_drive starts wandering. The simulator runs as fast as it goes;
slam_gmapping keeps up or drops scans, as the real one does. The script joins the bus
and, every simulated second, asks Gazebo for the robot's true pose
(``/gazebo/get_model_state``, stamped with the simulated time) and looks up
``map -> base_footprint`` and ``odom -> base_footprint`` at that stamp.

Measured over ``--minutes`` simulated minutes (10 by default) from slam_gmapping's first
map: the SLAM and dead-reckoning position errors, the final map's precision and recall
against the true walls (as ``slam_live.py``), scans slam_gmapping used, and simulated
seconds per wall second, then the same launch without slam_gmapping for the simulator
alone. Processes make the run nondeterministic (which scans are dropped depends on
timing); the seed fixes the simulator's noise only.

Run:  python benchmarks/slam_live_processes.py [--minutes M] [--odometry encoder|world]
Writes benchmarks/results/slam_live_processes.json and prints a table with the machine.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from machine import describe  # noqa: E402
from slam_live import ROBOT, encoder_urdf, errors, map_quality, report  # noqa: E402

from workbench.paths import examples_dir, urdf_dir

HERE = Path(__file__).resolve().parent
GMAPPING_PARAMS = "packages/turtlebot3_slam/config/gmapping_params.yaml"


def launch_text(urdf: Path, *, slam: bool, seed: int) -> str:
    """The launch file: simulator, robot, its state publisher (and SLAM); the wanderer is
    started once slam_gmapping has its first map (or the first scan came, without SLAM)."""
    mapping = ""
    if slam:
        params = examples_dir() / GMAPPING_PARAMS
        mapping = (
            '  <node pkg="gmapping" type="slam_gmapping" name="slam_gmapping">\n'
            f'    <rosparam file="{params}" command="load"/>\n'
            "  </node>\n"
        )
    return (
        "<launch>\n"
        '  <param name="/use_sim_time" value="true"/>\n'
        f'  <param name="robot_description" textfile="{urdf}"/>\n'
        '  <node name="gazebo" pkg="gazebo_ros" type="gzserver"'
        f' args="--fast --headless --seed {seed} house"/>\n'
        '  <node name="spawn_urdf" pkg="gazebo_ros" type="spawn_model"'
        f' args="-urdf -model {ROBOT} -param robot_description"/>\n'
        '  <node name="robot_state_publisher" pkg="robot_state_publisher"'
        ' type="robot_state_publisher"/>\n'
        f"{mapping}"
        "</launch>\n"
    )


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def wait_port(port: int, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=0.2):
                return
        except OSError:
            time.sleep(0.05)
    raise RuntimeError(f"workbench core did not open port {port}")


def stop(popen: subprocess.Popen) -> None:
    if popen.poll() is None:
        popen.send_signal(signal.SIGINT)
        try:
            popen.wait(20)
        except subprocess.TimeoutExpired:
            popen.kill()
            popen.wait()


def run(seconds: float, *, slam: bool, encoder: bool, seed: int, folder: Path) -> dict[str, Any]:
    """One launch: measure ``seconds`` simulated from the first map (or the first scan)."""
    from workbench.bus import Bus, Node
    from workbench.msgs import gazebo_msgs as gm
    from workbench.msgs.nav_msgs import OccupancyGrid
    from workbench.msgs.rosgraph_msgs import Clock
    from workbench.msgs.sensor_msgs import LaserScan
    from workbench.tf import Buffer, TransformException, TransformListener

    urdf = folder / f"{ROBOT}.urdf"
    urdf.write_text(encoder_urdf() if encoder else (urdf_dir() / f"{ROBOT}.urdf").read_text())
    launch = folder / ("slam.launch" if slam else "sim.launch")
    launch.write_text(launch_text(urdf, slam=slam, seed=seed))
    port = free_port()
    env = dict(os.environ, WORKBENCH_MASTER_URI=f"tcp/127.0.0.1:{port}")
    log = open(folder / f"{launch.stem}.log", "wb")  # noqa: SIM115 - closed below
    core = subprocess.Popen([sys.executable, "-m", "workbench", "core"], env=env, stdout=log)
    children = [core]
    try:
        wait_port(port)
        nodes = subprocess.Popen(
            [sys.executable, "-m", "workbench", "launch", str(launch)],
            env=env,
            stdout=log,
            stderr=subprocess.STDOUT,
        )
        children.append(nodes)
        bus = Bus.connect(env["WORKBENCH_MASTER_URI"])
        me = Node("benchmark", bus=bus)
        buffer = Buffer()
        TransformListener(buffer, me)
        latest: dict[str, Any] = {"clock": None, "map": None, "maps": 0, "scans": 0}

        def on_clock(msg: Any) -> None:
            latest["clock"] = msg.clock.to_sec()

        def on_map(msg: Any) -> None:
            latest["map"] = msg
            latest["maps"] += 1

        def on_scan(msg: Any) -> None:
            latest["scans"] += 1

        me.create_subscription("/clock", Clock, on_clock, 1)
        me.create_subscription("/map", OccupancyGrid, on_map, 1)
        me.create_subscription("/scan", LaserScan, on_scan, 10)
        state = me.create_client("/gazebo/get_model_state", gm.GetModelState)
        ready = (lambda: latest["maps"] > 0) if slam else (lambda: latest["scans"] > 0)
        deadline = time.monotonic() + 120.0
        while not ready():
            if time.monotonic() > deadline or nodes.poll() is not None:
                raise RuntimeError(f"the launch did not start; see {log.name}")
            time.sleep(0.01)
        # The robot stands still until slam_gmapping has its first map (a student starts
        # driving once the map shows in RViz): the map frame starts at the true pose.
        drive = subprocess.Popen(
            [sys.executable, "-m", "workbench", "run", "turtlebot3_gazebo", "turtlebot3_drive"],
            env=env,
            stdout=log,
            stderr=subprocess.STDOUT,
        )
        children.append(drive)
        begin, wall = latest["clock"], time.perf_counter()
        samples: list[tuple[float, ...]] = []
        next_sample = begin + 1.0
        while latest["clock"] - begin < seconds:
            if nodes.poll() is not None or drive.poll() is not None:
                raise RuntimeError(f"a node stopped; see {log.name}")
            if latest["clock"] < next_sample:
                time.sleep(0.002)
                continue
            next_sample += 1.0
            if not slam:
                continue
            reply = state.call(gm.GetModelState.Request(model_name=ROBOT))
            stamp = reply.header.stamp
            truth = (reply.pose.position.x, reply.pose.position.y)
            row: list[float] = [*truth]
            for frame in ("map", "odom"):
                try:
                    t = buffer.lookup_transform(frame, "base_footprint", stamp, timeout=2.0)
                    row += [t.transform.translation.x, t.transform.translation.y]
                except TransformException:
                    row += [math.nan, math.nan]
            samples.append(tuple(row))
        elapsed = time.perf_counter() - wall
        simulated = latest["clock"] - begin
        result: dict[str, Any] = {"simulated_s": simulated, "wall_s": elapsed}
        if slam:
            final = latest["maps"]
            deadline = time.monotonic() + 30.0
            while latest["maps"] == final and time.monotonic() < deadline:
                time.sleep(0.01)
            result["samples"] = samples
            result["map"] = map_quality(latest["map"])
        me.shutdown()
        bus.shutdown()
        return result
    finally:
        for child in reversed(children):
            stop(child)
        log.close()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="simulated minutes")
    parser.add_argument("--seed", type=int, default=0, help="seed of the simulator's plugins")
    parser.add_argument(
        "--odometry", choices=("encoder", "world"), default="encoder", help="the drive's source"
    )
    parser.add_argument("--out", type=Path, default=HERE / "results" / "slam_live_processes.json")
    args = parser.parse_args(argv)
    seconds = 60.0 * args.minutes
    setup = {"encoder": args.odometry == "encoder", "seed": args.seed}
    with tempfile.TemporaryDirectory(prefix="slam_live_") as folder:
        live = run(seconds, slam=True, folder=Path(folder), **setup)
        alone = run(seconds, slam=False, folder=Path(folder), **setup)
    result = {
        "machine": describe(("drake", "numpy")),
        "seed": args.seed,
        "odometry": args.odometry,
        "simulated_s": live["simulated_s"],
        "rtf_slam_and_sim": live["simulated_s"] / live["wall_s"],
        "rtf_sim_alone": alone["simulated_s"] / alone["wall_s"],
        "slam": errors(live["samples"], slice(2, 4)),
        "dead_reckoning": errors(live["samples"], slice(4, 6)),
        "map": live["map"],
        # Per simulated second: true x y, map -> base_footprint x y, odom -> base_footprint x y.
        "samples": live["samples"],
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=1))
    report(result, "live SLAM in the house, one process per node")
    return 0


if __name__ == "__main__":
    sys.exit(main())
