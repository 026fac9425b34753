"""The simulator: physics against analytic answers, and speed against bare Drake and PyBullet.

Run ``python benchmarks/sim.py`` (``--quick`` for shorter runs). Writes
``benchmarks/results/sim.json`` and prints two tables with the machine.

Accuracy (workbench's server physics: 1 ms, point contact, Drake's lagged solver):

* free fall: a 0.1 m box dropped from 2 m, z(t) before contact vs z0 - g t^2 / 2;
* resting: the box on the ground for 10 s, its height vs 0.05 m and its drift;
* sliding: a flat box launched at 2 m/s with mu = 0.5 on the ground's 1.0 (Drake
  combines them as 2ab/(a+b) = 0.667), stopping distance vs v^2 / (2 mu g);
* spinning top: ``urdf/spinning_top.urdf`` tilted 0.2 rad, spun at 150 rad/s
  about its axis, precession rate vs m g l / (I3 w).

Speed (real-time factor = simulated s / wall s, as fast as possible):

* ``table + 20 boxes``: the table and 20 0.1 m boxes dropped onto it, 5 s;
* ``two-wheeled robot``: ``urdf/two_wheeled_robot.sdf`` driving on the ground
  with constant wheel torques against joint damping, 10 s.

Each scene runs in workbench's server with the bus up (``/clock`` at 100 Hz; and
again with ``/gazebo/model_states`` at 100 Hz to a subscriber), in bare Drake (the same
plant and step, no bus, no server loop) and in PyBullet (same URDF/SDF files,
same 1 ms step) when ``pip install pybullet`` has been run. The spawn latency
is the time ``/gazebo/spawn_urdf_model`` takes to put a box into the running
table scene.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from machine import describe  # noqa: E402

from workbench.paths import urdf_dir  # noqa: E402
from workbench.sim import World  # noqa: E402
from workbench.sim.loading import load_sim_model, sim_model_from_xml  # noqa: E402
from workbench.sim.server import SERVER_PHYSICS, SimServer  # noqa: E402

G = 9.81
STEP = SERVER_PHYSICS["time_step"]
BOX = 0.1
BOX_MASS = 0.5
BOXES = 20
WHEEL_TORQUE = 0.3  # N m on each wheel
WHEEL_DAMPING = 0.5  # N m s / rad, written into the robot for every engine
ROBOT_POSE = [0.0, 0.0, -0.075]  # the manual's robot: its caster's bottom is 7.5 cm up


def box_urdf(
    name: str, mu: float | None = None, size: tuple[float, float, float] = (BOX, BOX, BOX)
) -> str:
    """A 0.5 kg box (default a 0.1 m cube); ``mu`` sets its Gazebo friction."""
    x, y, z = size
    ixx, iyy, izz = (BOX_MASS * (a * a + b * b) / 12.0 for a, b in ((y, z), (x, z), (x, y)))
    friction = (
        f'<gazebo reference="body"><mu1>{mu}</mu1><mu2>{mu}</mu2></gazebo>'
        if mu is not None
        else ""
    )
    return f"""<robot name="{name}"><link name="body">
  <inertial><mass value="{BOX_MASS}"/>
    <inertia ixx="{ixx}" iyy="{iyy}" izz="{izz}" ixy="0" ixz="0" iyz="0"/></inertial>
  <visual><geometry><box size="{x} {y} {z}"/></geometry></visual>
  <collision><geometry><box size="{x} {y} {z}"/></geometry></collision>
</link>{friction}</robot>"""


def server_world() -> World:
    return World(**SERVER_PHYSICS)


# --- accuracy -----------------------------------------------------------------------


def free_fall() -> dict[str, float]:
    world = server_world()
    world.add_model(sim_model_from_xml(box_urdf("box"), name="box", source="bench"), [0, 0, 2.0])
    world.build()
    errors = []
    for k in range(1, 51):  # until 0.5 s, well before contact at ~0.63 s
        t = k * 0.01
        world.advance_to(t)
        z = world.get_model_pose("box").translation()[2]
        errors.append(abs(z - (2.0 - 0.5 * G * t * t)))
    return {"max_error_m": max(errors), "at_s": 0.5}


def resting(duration: float) -> dict[str, float]:
    world = server_world()
    world.add_model(sim_model_from_xml(box_urdf("box"), name="box", source="bench"), [0, 0, 0.05])
    world.build()
    world.advance_to(1.0)
    start = world.get_model_pose("box").translation()
    world.advance_to(1.0 + duration)
    end = world.get_model_pose("box").translation()
    return {
        "height_error_m": float(end[2] - BOX / 2),
        "drift_m": float(np.linalg.norm(end - start)),
        "over_s": duration,
    }


def sliding(mu: float = 0.5, speed: float = 2.0) -> dict[str, float]:
    # a flat box (0.2 x 0.2 x 0.05 m): a cube launched this fast tips over
    world = server_world()
    flat = box_urdf("box", mu=mu, size=(0.2, 0.2, 0.05))
    world.add_model(sim_model_from_xml(flat, name="box", source="bench"), [0, 0, 0.025])
    world.build()
    world.advance_to(0.2)
    start = world.get_model_pose("box").translation()
    world.set_model_state("box", start, linear=[speed, 0.0, 0.0])
    # Drake combines the box's mu with the ground's 1.0 as 2ab/(a+b).
    effective = 2 * mu * 1.0 / (mu + 1.0)
    t = world.time
    while world.get_model_twist("box")[0][0] > 1e-3 and world.time < t + 5.0:
        world.advance_to(world.time + 0.01)
    distance = world.get_model_pose("box").translation()[0] - start[0]
    expected = speed**2 / (2 * effective * G)
    return {
        "mu_effective": effective,
        "distance_m": float(distance),
        "expected_m": expected,
        "relative_error": float(distance / expected - 1.0),
    }


def spinning_top(omega: float = 150.0, tilt: float = 0.2, seconds: float = 3.0) -> dict[str, float]:
    from pydrake.math import RigidTransform, RollPitchYaw

    world = server_world()
    X = RigidTransform(RollPitchYaw(tilt, 0.0, 0.0), [0.0, 0.0, 0.001])
    world.add_model(load_sim_model("spinning_top", name="top"), X)
    world.build()
    world.set_model_state("top", X, angular=omega * X.rotation().col(2))
    times, azimuths = [], []
    for k in range(1, int(seconds / 0.01) + 1):
        world.advance_to(k * 0.01)
        axis = world.get_model_pose("top").rotation().col(2)
        times.append(world.time)
        azimuths.append(math.atan2(axis[1], axis[0]))
    rate = float(np.polyfit(times, np.unwrap(azimuths), 1)[0])
    mass, lever, spin_inertia = 0.21, 0.05, 0.00026
    predicted = mass * G * lever / (spin_inertia * omega)
    return {
        "precession_rad_s": rate,
        "predicted_rad_s": predicted,
        "relative_error": rate / predicted - 1.0,
    }


# --- speed --------------------------------------------------------------------------


def table_scene(world: World) -> None:
    world.add_model(load_sim_model("table", name="table"), [0, 0, 0.01])
    rng = np.random.default_rng(0)
    for i in range(BOXES):
        x, y = -0.3 + 0.2 * (i % 4), -0.8 + 0.4 * (i // 4)
        z = 1.0 + 0.15 * rng.random()
        model = sim_model_from_xml(box_urdf(f"box_{i}"), name=f"box_{i}", source="bench")
        world.add_model(model, [x, y, z])


def robot_scene(world: World) -> None:
    model = load_sim_model(urdf_dir() / "two_wheeled_robot.sdf", name="robot")
    world.add_model(model, ROBOT_POSE)


def wheel_joints(world: World) -> list[str]:
    from workbench.sim.scene import joint_names

    return [n for n in joint_names(world.plant, world.model_instance("robot")) if "wheel" in n]


def damp_wheels(world: World) -> None:
    context = world.plant.GetMyMutableContextFromRoot(world.context)
    for name in wheel_joints(world):
        world.joint("robot", name).SetDampingVector(context, [WHEEL_DAMPING])


def time_server(scene, seconds: float, robot: bool, listener: bool = True) -> float:
    from workbench.bus import Bus, Node
    from workbench.msgs.gazebo_msgs import ModelStates
    from workbench.sim.gazebo_ros import GazeboRosApi

    bus = Bus()
    world = server_world()
    scene(world)
    server = SimServer(world, bus=bus, real_time_factor=0)
    api = GazeboRosApi(server, Node("gazebo", bus=bus))
    received: list = []
    if listener:
        Node("listener", bus=bus).create_subscription(
            "/gazebo/model_states", ModelStates, received.append
        )
    if robot:
        damp_wheels(world)
        for name in wheel_joints(world):
            server.apply_joint_effort(f"robot::{name}", WHEEL_TORQUE, 0.0, -1.0)
    start = time.perf_counter()
    server.run(until=seconds)
    wall = time.perf_counter() - start
    api.close()
    server.stop()
    bus.shutdown()
    if listener and not received:
        raise RuntimeError("the model states never arrived")
    return seconds / wall


def time_bare_drake(scene, seconds: float, robot: bool) -> float:
    world = server_world()
    scene(world)
    world.build()
    if robot:
        damp_wheels(world)
        world.set_joint_efforts({("robot", n): WHEEL_TORQUE for n in wheel_joints(world)})
    start = time.perf_counter()
    world.simulator.AdvanceTo(seconds)
    return seconds / (time.perf_counter() - start)


def time_pybullet(files: list[tuple[str, list[float]]], seconds: float, robot: bool) -> float:
    import pybullet

    client = pybullet.connect(pybullet.DIRECT)
    pybullet.setGravity(0, 0, -G, physicsClientId=client)
    pybullet.setTimeStep(STEP, physicsClientId=client)
    plane = pybullet.createCollisionShape(pybullet.GEOM_PLANE, physicsClientId=client)
    pybullet.createMultiBody(0, plane, physicsClientId=client)
    bodies = []
    for path, pose in files:
        if path.endswith(".sdf"):
            bodies += list(pybullet.loadSDF(path, physicsClientId=client))
            pybullet.resetBasePositionAndOrientation(
                bodies[-1], pose, [0, 0, 0, 1], physicsClientId=client
            )
        else:
            bodies.append(pybullet.loadURDF(path, pose, physicsClientId=client))
    if robot:
        body = bodies[-1]
        for j in range(pybullet.getNumJoints(body, physicsClientId=client)):
            name = pybullet.getJointInfo(body, j, physicsClientId=client)[1].decode()
            if "wheel" in name:
                pybullet.setJointMotorControl2(
                    body, j, pybullet.VELOCITY_CONTROL, force=0, physicsClientId=client
                )
                pybullet.changeDynamics(body, j, jointDamping=WHEEL_DAMPING, physicsClientId=client)
                pybullet.setJointMotorControl2(
                    body, j, pybullet.TORQUE_CONTROL, force=WHEEL_TORQUE, physicsClientId=client
                )
    steps = int(round(seconds / STEP))
    start = time.perf_counter()
    for _ in range(steps):
        pybullet.stepSimulation(physicsClientId=client)
    wall = time.perf_counter() - start
    pybullet.disconnect(client)
    return seconds / wall


def spawn_latency(repeats: int) -> float:
    from workbench.bus import Bus, Node
    from workbench.msgs.gazebo_msgs import SpawnModel
    from workbench.sim.gazebo_ros import GazeboRosApi

    bus = Bus()
    world = server_world()
    table_scene(world)
    server = SimServer(world, bus=bus, real_time_factor=1.0)
    api = GazeboRosApi(server, Node("gazebo", bus=bus))
    server.start()
    client = Node("spawner", bus=bus).create_client("/gazebo/spawn_urdf_model", SpawnModel)
    times = []
    for i in range(repeats):
        request = SpawnModel.Request(model_name=f"extra_{i}", model_xml=box_urdf(f"extra_{i}"))
        request.initial_pose.position.z = 2.0
        request.initial_pose.position.x = 3.0 + i * 0.3
        request.initial_pose.orientation.w = 1.0
        start = time.perf_counter()
        reply = client.call(request, timeout=30)
        times.append(time.perf_counter() - start)
        if not reply.success:
            raise RuntimeError(reply.status_message)
    api.close()
    server.stop()
    bus.shutdown()
    return statistics.median(times)


def pybullet_files(tmp: Path) -> tuple[list, list]:
    table = [(str(urdf_dir() / "table.urdf"), [0, 0, 0.01])]
    rng = np.random.default_rng(0)
    for i in range(BOXES):
        path = tmp / f"box_{i}.urdf"
        path.write_text(box_urdf(f"box_{i}"))
        x, y = -0.3 + 0.2 * (i % 4), -0.8 + 0.4 * (i // 4)
        table.append((str(path), [x, y, 1.0 + 0.15 * rng.random()]))
    # PyBullet's SDF reader wants limits on revolute joints: the same robot from
    # the same builder script as URDF (its ball caster fixed and frictionless, as
    # workbench simulates the SDF's).
    import runpy

    builder = runpy.run_path(
        str(urdf_dir().parent / "examples" / "gazebo" / "build_two_wheeled_robot.py")
    )
    robot_urdf = builder["build"]().save(tmp / "two_wheeled_robot.urdf")
    robot = [(str(robot_urdf), ROBOT_POSE)]
    return table, robot


def median_of(runs: int, fn, *args) -> float:
    return statistics.median(fn(*args) for _ in range(runs))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="short runs (a smoke test)")
    parser.add_argument("--runs", type=int, default=3, help="runs per speed measurement")
    options = parser.parse_args()
    runs = 1 if options.quick else options.runs
    table_seconds, robot_seconds = (1.0, 2.0) if options.quick else (5.0, 10.0)

    accuracy = {
        "free_fall": free_fall(),
        "resting": resting(2.0 if options.quick else 10.0),
        "sliding": sliding(),
        "spinning_top": spinning_top(seconds=1.0 if options.quick else 3.0),
    }
    try:
        import pybullet  # noqa: F401

        have_pybullet = True
    except ImportError:
        have_pybullet = False
    speed: dict[str, dict[str, float | None]] = {}
    with tempfile.TemporaryDirectory() as folder:
        table_files, robot_files = pybullet_files(Path(folder))
        for label, scene, seconds, files, robot in (
            ("table + 20 boxes", table_scene, table_seconds, table_files, False),
            ("two-wheeled robot", robot_scene, robot_seconds, robot_files, True),
        ):
            row: dict[str, float | None] = {
                "workbench_clock": median_of(runs, time_server, scene, seconds, robot, False),
                "workbench": median_of(runs, time_server, scene, seconds, robot),
                "bare_drake": median_of(runs, time_bare_drake, scene, seconds, robot),
                "pybullet": median_of(runs, time_pybullet, files, seconds, robot)
                if have_pybullet
                else None,
            }
            speed[label] = row
    latency = spawn_latency(3 if options.quick else 10)

    machine = describe(("drake", "pybullet", "numpy"))
    print(f"machine: {machine}")
    print("\naccuracy (1 ms, point contact, lagged)")
    print("| check | result | expected | error |\n|---|---|---|---|")
    ff, rest, slide, top = (
        accuracy[k] for k in ("free_fall", "resting", "sliding", "spinning_top")
    )
    print(f"| free fall z(t), t <= 0.5 s | max error | 0 | {ff['max_error_m'] * 1e3:.3f} mm |")
    print(
        f"| box resting {rest['over_s']:g} s | height {BOX / 2 + rest['height_error_m']:.5f} m, "
        f"drift {rest['drift_m'] * 1e3:.3f} mm | 0.05 m, 0 | {rest['height_error_m'] * 1e3:.3f} mm |"
    )
    print(
        f"| sliding, mu {slide['mu_effective']:.3f}, 2 m/s | {slide['distance_m']:.4f} m | "
        f"{slide['expected_m']:.4f} m | {slide['relative_error'] * 100:+.2f} % |"
    )
    print(
        f"| spinning top precession | {top['precession_rad_s']:.3f} rad/s | "
        f"{top['predicted_rad_s']:.3f} rad/s | {top['relative_error'] * 100:+.2f} % |"
    )
    print("\nspeed: real-time factor (as fast as possible), median of", runs)
    print(
        "| scene | server, /clock | server, /clock + model_states listener | bare Drake "
        "| PyBullet | bus cost (clock / + listener) | server vs PyBullet |"
    )
    print("|---|---|---|---|---|---|---|")
    for label, row in speed.items():
        clock, wb, bare, pb = (
            row[k] for k in ("workbench_clock", "workbench", "bare_drake", "pybullet")
        )
        assert clock is not None and wb is not None and bare is not None
        costs = f"{(1 - clock / bare) * 100:.1f} % / {(1 - wb / bare) * 100:.1f} %"
        versus = f"{clock / pb:.2f}x" if pb else "n/a (pip install pybullet)"
        pb_text = f"{pb:.1f}" if pb else "n/a"
        print(f"| {label} | {clock:.1f} | {wb:.1f} | {bare:.1f} | {pb_text} | {costs} | {versus} |")
    print(f"\nspawn into the running table scene (median): {latency * 1e3:.1f} ms")
    results = {
        "machine": machine,
        "seed": 0,
        "step_s": STEP,
        "accuracy": accuracy,
        "speed_rtf": speed,
        "spawn_latency_s": latency,
    }
    out = Path(__file__).resolve().parent / "results" / "sim.json"
    out.write_text(json.dumps(results, indent=2) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
