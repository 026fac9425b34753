"""Navigation in the house: the TurtleBot3 burger driven by AMCL and move_base to random goals.

Experiment 10's navigation as one process, on one stepped in-process bus: ``workbench sim
house --fast`` (the house world's 8 ms physics step), the burger spawned at the origin with
its diff drive's odometry from the wheel encoders (so dead reckoning drifts as a real
robot's does), robot_state_publisher, ``map_server`` serving the saved house map,
``amcl`` and ``move_base`` with turtlebot3_navigation's launch files and parameter files
(read by the launcher as ``turtlebot3_navigation.launch`` loads them: amcl.launch's
parameters, DWAPlannerROS, the burger's costmaps). The script steps the simulator; after
every physics chunk it runs everything that became due on the bus and waits until amcl
has handled every scan, so the nodes keep up as they would at real time.

Goals: ``--goals`` seeded random poses inside the house, free with ``CLEARANCE`` on the
saved map (from occupied and unknown cells) and on the true map (the building plan's
walls and furniture), and reachable on the true map from where the robot stands. Each is
sent through the ``move_base`` action (``SimpleActionClient``) and given
``30 s + 4 x`` its shortest path at the burger's 0.22 m/s of simulated time.

Measured per goal: success (SUCCEEDED and the true pose within DWA's
``xy_goal_tolerance`` + ``SLACK``), time to goal (sim s), driven path length (true
positions every chunk) against the shortest collision-free path on the true map,
contacts of the robot with anything but the ground (checked every 10 simulated ms).
Along the way, every simulated second: amcl's pose (``map -> base_footprint`` on tf)
against the simulator's true pose, reported after ``CONVERGED_AFTER`` m of travel.
Global planning time: navfn and the heapq A* baseline
(:mod:`workbench.navigation.astar_baseline`) on move_base's global costmap as it was
when each goal was sent. Speed: simulated s per wall s for the whole (simulator + amcl +
move_base), and for the simulator alone with the same velocity commands replayed.

Run:  python benchmarks/navigation.py [--goals N] [--seed S] [--map YAML]
Writes benchmarks/results/navigation.json and prints a table with the machine.
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
from machine import describe
from navigation_truth import ShortestPaths, TrueMap, house_true_map
from slam_live import ROBOT, encoder_urdf

from workbench.paths import examples_dir, mapping_dir, urdf_dir

HERE = Path(__file__).resolve().parent
NAV = examples_dir() / "packages" / "turtlebot3_navigation"
#: The house's outer walls (inside faces), m: goals are drawn inside.
HOUSE = (-4.9, 4.9, -3.9, 3.9)
#: Distance of a goal from occupied/unknown cells of the saved map and from the true walls, m:
#: the burger's circumscribed radius (0.148 m) plus a margin.
CLEARANCE = 0.30
#: The robot's radius on the true map (ROBOTIS's ``robot_radius`` for the burger), m.
ROBOT_RADIUS = 0.105
#: Goals are at least this far from the robot, m.
MIN_DISTANCE = 1.0
#: Slack on top of ``xy_goal_tolerance`` for the true pose at a reached goal, m: the robot
#: stops where amcl puts the goal, and amcl may be off by its target error, 0.1 m.
SLACK = 0.10
#: AMCL errors count once the robot has driven this far, m.
CONVERGED_AFTER = 2.0
MAX_SPEED = 0.22
CONTACT_PERIOD = 0.01
TARGETS = {"success": 0.95, "collisions": 0, "amcl_error_m": 0.1, "rtf": 5.0}


def display_path(path: Path) -> str:
    """``path`` relative to the repository when it is inside it."""
    try:
        return str(path.relative_to(HERE.parent))
    except ValueError:
        return str(path)


def default_map() -> Path:
    return mapping_dir() / "house.yaml"


class Stack:
    """The house, the burger, robot_state_publisher and (``navigation``) map_server, amcl and
    move_base on one stepped bus, with the measurements taken after each physics chunk."""

    def __init__(self, map_yaml: Path | None, *, seed: int = 0) -> None:
        from workbench.bus import Bus, Node
        from workbench.model import load_robot
        from workbench.msgs import gazebo_msgs as gm
        from workbench.robot_state import RobotStatePublisher
        from workbench.sim.gazebo_ros import GazeboRosApi
        from workbench.sim.gzserver import ServerOptions, build_server
        from workbench.tf import Buffer, TransformListener

        self.last_scan: Any = None  # the stamp of the latest scan
        self.measuring_s = 0.0  # wall time of the contact checks (not part of the stack)
        self.measuring_cpu_s = 0.0  # and their CPU time
        self.wall_s = self.cpu_s = 0.0  # what stepping took, without the contact checks
        self.bus = Bus(threaded=False)
        self.bus.params.set("/use_sim_time", True)
        options = ServerOptions(world="house", fast=True, view=False, seed=seed)
        self.world, self.server, _ = build_server(options, self.bus)
        self.api = GazeboRosApi(self.server, Node("gazebo", bus=self.bus))
        self.me = Node("benchmark", bus=self.bus)
        request = gm.SpawnModel.Request(
            model_name=ROBOT, model_xml=encoder_urdf(), robot_namespace="/"
        )
        request.initial_pose.orientation.w = 1.0
        client = self.me.create_client("/gazebo/spawn_urdf_model", gm.SpawnModel)
        assert client.call(request).success
        robot = load_robot(urdf_dir() / f"{ROBOT}.urdf")
        self.rsp = RobotStatePublisher(robot, Node("robot_state_publisher", bus=self.bus))
        self.buffer = Buffer(cache_time=10.0)
        TransformListener(self.buffer, self.me)
        self.amcl: Any = None
        self.move_base: Any = None
        self.client: Any = None
        if map_yaml is not None:
            self._navigation(map_yaml)
        # measurements
        plant = self.world.plant
        instance = self.world.model_instance(ROBOT)
        self.robot_bodies = {plant.get_body(b).name() for b in plant.GetBodyIndices(instance)}
        self.touching: set[tuple[str, str]] = set()
        self.contacts: list[dict[str, Any]] = []
        self.next_contact_check = 0.0
        self.last_xy = self.truth()[:2]
        self.driven = 0.0
        self.commands: list[tuple[float, float, float]] = []
        from workbench.msgs.geometry_msgs import Twist
        from workbench.msgs.sensor_msgs import LaserScan

        self.me.create_subscription("/cmd_vel", Twist, self._on_cmd, 100, inline=True)
        self.me.create_subscription("/scan", LaserScan, self._on_scan, 10, inline=True)
        self.server.hooks.append(self._after_chunk)

    def _navigation(self, map_yaml: Path) -> None:
        from workbench.actionlib import SimpleActionClient
        from workbench.bus import Node
        from workbench.bus.launch import load_launch
        from workbench.mapping.map_server_node import MapServer
        from workbench.msgs.move_base_msgs import MoveBaseAction
        from workbench.navigation.amcl_node import Amcl
        from workbench.navigation.move_base import MoveBase
        from workbench.tf import Buffer, TransformListener

        launch = NAV / "launch" / "turtlebot3_navigation.launch"
        plan = load_launch(launch, {"open_rviz": "false", "map_file": str(map_yaml)})
        for key, value in plan.params.items():
            if key != "/robot_description":
                self.bus.params.set(key, value)
        self.map_server = MapServer(Node("map_server", bus=self.bus), str(map_yaml))
        self.amcl = Amcl(Node("amcl", bus=self.bus))
        self.drain()
        self.amcl.wait_idle()
        node = Node("move_base", bus=self.bus)
        buffer = Buffer(cache_time=10.0)
        TransformListener(buffer, node)
        self.move_base = MoveBase(node, buffer)
        self.client = SimpleActionClient("move_base", MoveBaseAction, self.me)
        self.xy_goal_tolerance = float(
            self.bus.params.get("/move_base/DWAPlannerROS/xy_goal_tolerance")
        )

    # --- stepping ------------------------------------------------------------------------

    def drain(self) -> None:
        """Run every callback that is due on the bus, and let amcl handle the scans it can.

        amcl holds a scan until ``odom -> base_footprint`` at its stamp is on tf (the
        diff drive sends it at 30 Hz, the laser scans at 5 Hz): a scan waiting for
        odometry the simulator has not produced yet is left to amcl while it steps on.
        """
        amcl = self.amcl
        while True:
            while self.bus.spin_once(0.0):
                pass
            if amcl is None or not amcl.busy:
                return
            if self.last_scan is not None and not amcl.buffer.can_transform(
                "odom", "base_footprint", self.last_scan
            ):
                return
            amcl.wait_idle()

    def _after_chunk(self, server: Any) -> None:
        self.drain()
        x, y, _ = self.truth()
        self.driven += math.hypot(x - self.last_xy[0], y - self.last_xy[1])
        self.last_xy = (x, y)
        t = self.world.time
        if t + 1e-9 >= self.next_contact_check:
            self.next_contact_check = t + CONTACT_PERIOD
            begin, cpu = time.perf_counter(), time.process_time()
            self._check_contacts(t)
            self.measuring_s += time.perf_counter() - begin
            self.measuring_cpu_s += time.process_time() - cpu

    def _check_contacts(self, t: float) -> None:
        now = set()
        for a, b in self.world.contact_pairs():
            mine, other = (a, b) if a in self.robot_bodies else (b, a)
            if mine not in self.robot_bodies or other in self.robot_bodies or "ground" in other:
                continue
            now.add((mine, other))
        for pair in now - self.touching:
            x, y, yaw = self.truth()
            self.contacts.append(
                {"t": round(t, 3), "link": pair[0], "touched": pair[1], "pose": [x, y, yaw]}
            )
        self.touching = now

    def _on_scan(self, msg: Any) -> None:
        self.last_scan = msg.header.stamp

    def _on_cmd(self, msg: Any) -> None:
        self.commands.append((self.world.time, float(msg.linear.x), float(msg.angular.z)))

    def run_for(self, seconds: float) -> None:
        """Step the simulator ``seconds``; counts the wall and CPU time the stack took."""
        self.run_until(self.world.time + seconds)

    def run_until(self, t: float) -> None:
        wall, cpu = time.perf_counter(), time.process_time()
        measuring, measuring_cpu = self.measuring_s, self.measuring_cpu_s
        self.server.run(until=t)
        self.wall_s += time.perf_counter() - wall - (self.measuring_s - measuring)
        self.cpu_s += time.process_time() - cpu - (self.measuring_cpu_s - measuring_cpu)

    # --- poses ---------------------------------------------------------------------------

    def truth(self) -> tuple[float, float, float]:
        X = self.world.get_model_pose(ROBOT)
        p = X.translation()
        R = X.rotation().matrix()
        return float(p[0]), float(p[1]), float(math.atan2(R[1, 0], R[0, 0]))

    def estimate(self) -> tuple[float, float, float] | None:
        from workbench.tf import TransformException

        try:
            t = self.buffer.lookup_transform("map", "base_footprint", 0).transform
        except TransformException:
            return None
        q = t.rotation
        yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        return float(t.translation.x), float(t.translation.y), yaw

    def close(self) -> None:
        if self.move_base is not None:
            self.move_base.shutdown()
        if self.amcl is not None:
            self.amcl.close()
        self.api.close()
        self.server.stop()
        self.bus.shutdown()


# --- goals ------------------------------------------------------------------------------


def saved_map_clearance(map_yaml: Path) -> tuple[np.ndarray, Any]:
    """Distance (m) of every saved-map cell from the nearest occupied or unknown cell."""
    from scipy import ndimage

    from workbench.mapping.map_server_node import load_map_yaml

    loaded = load_map_yaml(str(map_yaml))
    free = np.asarray(loaded.cells) == 0
    return ndimage.distance_transform_edt(free) * loaded.meta.resolution, loaded.meta


def draw_goal(
    rng: np.random.Generator,
    start: tuple[float, float],
    truth: TrueMap,
    paths: ShortestPaths,
    saved: tuple[np.ndarray, Any],
) -> tuple[float, float, float, float]:
    """A goal (x, y, yaw) and its shortest path length from ``start`` (see the docstring)."""
    clearance, meta = saved
    _, pred, source = paths.from_point(*start)
    for _ in range(10000):
        x = float(rng.uniform(HOUSE[0], HOUSE[1]))
        y = float(rng.uniform(HOUSE[2], HOUSE[3]))
        yaw = float(rng.uniform(-math.pi, math.pi))
        mx = int((x - meta.origin[0]) / meta.resolution)
        my = int((y - meta.origin[1]) / meta.resolution)
        if not (0 <= my < clearance.shape[0] and 0 <= mx < clearance.shape[1]):
            continue
        if clearance[my, mx] < CLEARANCE or truth.clearance_at(x, y) < CLEARANCE:
            continue
        if math.hypot(x - start[0], y - start[1]) < MIN_DISTANCE:
            continue
        length, _ = paths.path_length(pred, source, x, y)
        if math.isfinite(length):
            return x, y, yaw, length
    raise RuntimeError("no reachable goal found in 10000 draws")


def goal_message(x: float, y: float, yaw: float) -> Any:
    from workbench.msgs.move_base_msgs import MoveBaseGoal

    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = "map"
    goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
    goal.target_pose.pose.orientation.z = math.sin(yaw / 2)
    goal.target_pose.pose.orientation.w = math.cos(yaw / 2)
    return goal


# --- planning time ----------------------------------------------------------------------


def planning_times(costmap: Any, start: tuple[float, float], goal: tuple[float, float]) -> dict:
    """navfn and the heapq A* on one costmap snapshot: times (ms) and path lengths (m)."""
    from workbench.navigation.astar_baseline import astar
    from workbench.navigation.navfn import navfn_plan, path_length
    from workbench.navigation.navfn_grid import cell_costs

    t0 = time.perf_counter()
    path = navfn_plan(costmap, start, goal)
    navfn_ms = (time.perf_counter() - t0) * 1e3
    a, b = costmap.world_to_map(*start), costmap.world_to_map(*goal)
    t0 = time.perf_counter()
    cells, _ = astar(cell_costs(costmap.costs), a, b) if a and b else ([], math.inf)
    astar_ms = (time.perf_counter() - t0) * 1e3
    baseline = [costmap.map_to_world(*c) for c in cells]
    return {
        "navfn_ms": navfn_ms,
        "astar_ms": astar_ms,
        "navfn_path_m": path_length(path) if path else None,
        "astar_path_m": path_length(baseline) if baseline else None,
    }


# --- the run ----------------------------------------------------------------------------


def navigate(stack: Stack, goals: int, seed: int, saved: tuple[np.ndarray, Any]) -> dict:
    """Send ``goals`` goals one after another; per-goal rows and the pose error samples."""
    from workbench.actionlib import SUCCEEDED
    from workbench.actionlib.client import SIMPLE_DONE

    rng = np.random.default_rng(seed)
    truth = house_true_map(ROBOT_RADIUS)
    paths = ShortestPaths(truth)
    stack.run_for(1.0)  # amcl's first pose, the costmaps' first maps
    rows: list[dict[str, Any]] = []
    samples: list[tuple[float, ...]] = []
    begin, wall, cpu = stack.world.time, stack.wall_s, stack.cpu_s
    for index in range(goals):
        x0, y0, _ = stack.truth()
        gx, gy, gyaw, shortest = draw_goal(rng, (x0, y0), truth, paths, saved)
        pose = stack.estimate() or stack.truth()
        timing = planning_times(stack.move_base.global_costmap.costmap(), pose[:2], (gx, gy))
        limit = 30.0 + 4.0 * shortest / MAX_SPEED
        contacts_before, driven_before = len(stack.contacts), stack.driven
        t_start = stack.world.time
        stack.client.send_goal(goal_message(gx, gy, gyaw))
        next_sample = math.floor(stack.world.time) + 1.0
        while stack.client.simple_state != SIMPLE_DONE and stack.world.time - t_start < limit:
            stack.run_for(0.1)
            if stack.world.time >= next_sample - 1e-9:
                next_sample += 1.0
                estimate = stack.estimate()
                if estimate is not None:
                    samples.append((stack.world.time, stack.driven, *stack.truth(), *estimate))
        done = stack.client.simple_state == SIMPLE_DONE
        if not done:
            stack.client.cancel_goal()
            stack.run_for(0.5)
        state = stack.client.get_state()
        tx, ty, tyaw = stack.truth()
        miss = math.hypot(tx - gx, ty - gy)
        reached = done and state == SUCCEEDED and miss <= stack.xy_goal_tolerance + SLACK
        rows.append(
            {
                "goal": [gx, gy, gyaw],
                "state": int(state),
                "text": stack.client.get_goal_status_text(),
                "success": bool(reached),
                "time_s": stack.world.time - t_start if done else None,
                "limit_s": limit,
                "final_error_m": miss,
                "final_yaw_error_rad": abs(math.remainder(tyaw - gyaw, 2 * math.pi)),
                "driven_m": stack.driven - driven_before,
                "shortest_m": shortest,
                "contacts": len(stack.contacts) - contacts_before,
                **timing,
            }
        )
        print(
            f"goal {index + 1:2d}/{goals}: ({gx:5.2f}, {gy:5.2f}) "
            f"{'reached' if reached else 'MISSED '} in {stack.world.time - t_start:5.1f} s, "
            f"{rows[-1]['driven_m']:5.2f} m driven / {shortest:5.2f} m shortest, "
            f"off by {miss:.3f} m, {rows[-1]['contacts']} contacts ({rows[-1]['text']})",
            flush=True,
        )
    return {
        "rows": rows,
        "samples": samples,
        "simulated_s": stack.world.time - begin,
        "wall_s": stack.wall_s - wall,
        "cpu_s": stack.cpu_s - cpu,
        "start_s": begin,
    }


def replay(commands: list[tuple[float, float, float]], start: float, end: float) -> dict:
    """The simulator alone (with robot_state_publisher) driven by the recorded commands."""
    from workbench.msgs.geometry_msgs import Twist

    stack = Stack(None)
    try:
        pub = stack.me.create_publisher("/cmd_vel", Twist, 10)
        stack.run_for(start)
        stack.wall_s = stack.cpu_s = 0.0
        for t, vx, wz in commands:
            if t > stack.world.time:
                stack.run_until(t)
            twist = Twist()
            twist.linear.x, twist.angular.z = vx, wz
            pub.publish(twist)
        stack.run_until(end)
    finally:
        stack.close()
    return {"simulated_s": end - start, "wall_s": stack.wall_s, "cpu_s": stack.cpu_s}


def pose_errors(samples: list[tuple[float, ...]]) -> dict[str, Any]:
    data = np.asarray(samples, dtype=float).reshape(-1, 8)
    late = data[data[:, 1] >= CONVERGED_AFTER]
    out: dict[str, Any] = {"samples": len(data), "after_convergence": len(late)}
    for name, part in (("all", data), ("converged", late)):
        if len(part) == 0:
            out[name] = None
            continue
        xy = np.hypot(part[:, 5] - part[:, 2], part[:, 6] - part[:, 3])
        yaw = np.abs(np.remainder(part[:, 7] - part[:, 4] + np.pi, 2 * np.pi) - np.pi)
        out[name] = {
            "median_m": float(np.median(xy)),
            "p95_m": float(np.percentile(xy, 95)),
            "max_m": float(xy.max()),
            "yaw_median_rad": float(np.median(yaw)),
            "yaw_max_rad": float(yaw.max()),
        }
    return out


def summarise(run: dict, alone: dict | None) -> dict[str, Any]:
    rows = run["rows"]
    ok = [r for r in rows if r["success"]]
    ratio = [r["driven_m"] / r["shortest_m"] for r in ok if r["shortest_m"] > 0]
    navfn = np.array([r["navfn_ms"] for r in rows])
    astar = np.array([r["astar_ms"] for r in rows])
    summary = {
        "goals": len(rows),
        "reached": len(ok),
        "success_rate": len(ok) / max(len(rows), 1),
        "collisions": int(sum(r["contacts"] for r in rows)),
        "time_to_goal_s": _stats([r["time_s"] for r in ok]),
        "path_ratio": _stats(ratio),
        "amcl": pose_errors(run["samples"]),
        "navfn_ms": {"median": float(np.median(navfn)), "p95": float(np.percentile(navfn, 95))},
        "astar_ms": {"median": float(np.median(astar)), "p95": float(np.percentile(astar, 95))},
        "simulated_s": run["simulated_s"],
        "wall_s": run["wall_s"],
        "cpu_s": run["cpu_s"],
        "rtf_full_stack": run["simulated_s"] / run["wall_s"],
        "rtf_full_stack_cpu": run["simulated_s"] / run["cpu_s"],
        "rtf_sim_alone": None if alone is None else alone["simulated_s"] / alone["wall_s"],
        "rtf_sim_alone_cpu": None if alone is None else alone["simulated_s"] / alone["cpu_s"],
    }
    return summary


def _stats(values: list[float]) -> dict[str, float] | None:
    if not values:
        return None
    a = np.asarray(values, dtype=float)
    return {
        "median": float(np.median(a)),
        "p95": float(np.percentile(a, 95)),
        "max": float(a.max()),
    }


def report(result: dict[str, Any]) -> None:
    m, s = result["machine"], result["summary"]
    print(f"machine: {m['cpu']}, {m['usable_cores']} cores, load {m['load_average']}")
    print(
        f"navigation in the house: {s['goals']} goals, seed {result['seed']}, "
        f"{s['simulated_s']:.0f} simulated s, map {result['map']}"
    )
    print("| measure | result | target |\n|---|---|---|")
    print(
        f"| goals reached | {s['reached']} / {s['goals']} ({100 * s['success_rate']:.0f} %) "
        f"| ≥ {100 * TARGETS['success']:.0f} % |"
    )
    print(f"| collisions | {s['collisions']} | {TARGETS['collisions']} |")
    t, p = s["time_to_goal_s"], s["path_ratio"]
    if t is not None:
        print(f"| time to goal (median / p95 / max) | {t['median']:.1f} / {t['p95']:.1f} / "
              f"{t['max']:.1f} s | — |")  # fmt: skip
    if p is not None:
        print(f"| driven / shortest path (median / p95 / max) | {p['median']:.2f} / "
              f"{p['p95']:.2f} / {p['max']:.2f} | — |")  # fmt: skip
    amcl = s["amcl"]["converged"]
    if amcl is not None:
        print(
            f"| AMCL error after {CONVERGED_AFTER:g} m (median / p95 / max) | "
            f"{amcl['median_m']:.3f} / {amcl['p95_m']:.3f} / {amcl['max_m']:.3f} m | "
            f"≤ {TARGETS['amcl_error_m']} m |"
        )
    print(
        f"| global plan, navfn (median / p95) | {s['navfn_ms']['median']:.1f} / "
        f"{s['navfn_ms']['p95']:.1f} ms | — |"
    )
    print(
        f"| global plan, heapq A* (median / p95) | {s['astar_ms']['median']:.1f} / "
        f"{s['astar_ms']['p95']:.1f} ms | — |"
    )
    alone, alone_cpu = s["rtf_sim_alone"], s["rtf_sim_alone_cpu"]
    print(
        f"| real-time factor, full stack: wall / CPU | {s['rtf_full_stack']:.1f}× / "
        f"{s['rtf_full_stack_cpu']:.1f}× | ≥ {TARGETS['rtf']:g}× |"
    )
    if alone is not None:
        print(
            f"| real-time factor, simulator alone: wall / CPU | {alone:.1f}× / "
            f"{alone_cpu:.1f}× | — |"
        )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--goals", type=int, default=50, help="number of goals")
    parser.add_argument("--seed", type=int, default=0, help="seed of the goals and plugins")
    parser.add_argument("--map", type=Path, default=default_map(), help="saved map YAML")
    parser.add_argument("--no-replay", action="store_true", help="skip the simulator-alone run")
    parser.add_argument("--out", type=Path, default=HERE / "results" / "navigation.json")
    args = parser.parse_args(argv)
    map_yaml = args.map.resolve()
    saved = saved_map_clearance(map_yaml)
    stack = Stack(map_yaml, seed=args.seed)
    try:
        run = navigate(stack, args.goals, args.seed, saved)
        commands, end = stack.commands, stack.world.time
    finally:
        stack.close()
    alone = None
    if not args.no_replay:
        alone = replay(commands, run["start_s"], end)
    result = {
        "machine": describe(("drake", "numpy", "scipy")),
        "seed": args.seed,
        "map": display_path(map_yaml),
        "summary": summarise(run, alone),
        "goals": run["rows"],
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=1) + "\n")
    report(result)
    return 0


if __name__ == "__main__":
    sys.exit(main())
