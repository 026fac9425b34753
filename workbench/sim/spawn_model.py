"""``spawn_model``: gazebo_ros's spawner, as ``workbench run gazebo_ros spawn_model ...``.

Takes gazebo_ros's arguments: a source (``-file FILE``, ``-param NAME``,
``-stdin``), its format (``-urdf`` or ``-sdf``), ``-model NAME``, the pose
``-x -y -z -R -P -Y`` (m, rad), ``-J JOINT VALUE`` (repeatable),
``-reference_frame``, ``-robot_namespace`` (the plugins' namespace; default
the node's, ``/``, as gazebo_ros), ``-gazebo_namespace`` (default ``/gazebo``), ``-unpause``, ``-wait MODEL`` and ``-timeout``. It waits for the
spawn service, calls it, prints Gazebo's status and exits 0 on success, 1 on a
refusal. A ``.xacro`` file is expanded first (a convenience: gazebo_ros reads
the file as it is).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from workbench.errors import WorkbenchError

NODE_NAME = "spawn_model"


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="spawn_model",
        prefix_chars="-",
        description="spawn a URDF or SDF model into a running workbench sim",
    )
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("-file", metavar="FILE", help="read the model from FILE")
    source.add_argument("-param", metavar="PARAM", help="read the model from a parameter")
    source.add_argument("-stdin", action="store_true", help="read the model from standard input")
    source.add_argument("-database", metavar="NAME", help="a model from urdf/ or GAZEBO_MODEL_PATH")
    kind = parser.add_mutually_exclusive_group()
    kind.add_argument("-urdf", action="store_true", help="the model is URDF")
    kind.add_argument("-sdf", action="store_true", help="the model is SDF")
    kind.add_argument("-gazebo", action="store_true", help="old name of -sdf")
    parser.add_argument("-model", required=True, metavar="NAME", help="the model's name")
    for axis in ("x", "y", "z", "R", "P", "Y"):
        parser.add_argument(f"-{axis}", type=float, default=0.0, metavar="VALUE")
    parser.add_argument(
        "-J",
        nargs=2,
        action="append",
        default=[],
        metavar=("JOINT", "VALUE"),
        help="initial position of a joint (repeatable)",
    )
    parser.add_argument("-reference_frame", default="", metavar="FRAME")
    parser.add_argument(
        "-robot_namespace",
        default=None,
        metavar="NS",
        help="namespace of the model's plugins (default: this node's, as gazebo_ros)",
    )
    parser.add_argument("-gazebo_namespace", default="/gazebo", metavar="NS")
    parser.add_argument("-unpause", action="store_true", help="unpause physics after spawning")
    parser.add_argument("-wait", metavar="MODEL", help="wait for MODEL to exist first")
    parser.add_argument("-timeout", type=float, default=60.0, metavar="SECONDS")
    parser.add_argument("-package_to_model", action="store_true", help="accepted, no effect")
    parser.add_argument("-b", action="store_true", help="accepted, no effect (bond)")
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """The node: spawn one model and exit (0: spawned, 1: refused or failed)."""
    from workbench.bus import Node

    raw = list(sys.argv[1:] if argv is None else argv)
    node = Node(NODE_NAME, argv=raw, anonymous=True)
    try:
        args = _parser().parse_args(node.argv)
        return spawn(node, args)
    except WorkbenchError as error:
        print(f"[ERROR] spawn_model: {error}", file=sys.stderr)
        return 1
    finally:
        node.shutdown()


def spawn(node: Any, args: argparse.Namespace) -> int:
    """Read the model, wait for the server, call the spawn service; Gazebo's messages."""
    from workbench.msgs.gazebo_msgs import GetWorldProperties, SetModelConfiguration, SpawnModel
    from workbench.msgs.std_srvs import Empty

    xml = _model_xml(node, args)
    pose = [args.x, args.y, args.z, args.R, args.P, args.Y]
    if not all(math.isfinite(value) for value in pose):
        print("[ERROR] spawn_model: the pose is not finite (NaN or infinite)", file=sys.stderr)
        return 1
    namespace = args.gazebo_namespace.rstrip("/")
    if args.wait:
        _wait_for_model(node, namespace, args.wait, args.timeout, GetWorldProperties)
    is_sdf = args.sdf or args.gazebo or (not args.urdf and _looks_like_sdf(xml))
    service = f"{namespace}/spawn_sdf_model" if is_sdf else f"{namespace}/spawn_urdf_model"
    print(f"[INFO] Waiting for service {service}", flush=True)
    client = node.create_client(service, SpawnModel)
    client.wait_for_service(timeout=args.timeout)
    print(f"[INFO] Calling service {service}", flush=True)
    request = SpawnModel.Request(
        model_name=args.model,
        model_xml=xml,
        robot_namespace=node.namespace if args.robot_namespace is None else args.robot_namespace,
        reference_frame=args.reference_frame,
    )
    request.initial_pose = _pose_message(pose)
    response = client.call(request, timeout=args.timeout)
    print(f"[INFO] Spawn status: {response.status_message}", flush=True)
    if not response.success:
        print("[ERROR] Spawn service failed. Exiting.", file=sys.stderr)
        return 1
    if args.J:
        configure = node.create_client(
            f"{namespace}/set_model_configuration", SetModelConfiguration
        )
        configure.wait_for_service(timeout=args.timeout)
        reply = configure.call(
            SetModelConfiguration.Request(
                model_name=args.model,
                joint_names=[name for name, _ in args.J],
                joint_positions=[float(value) for _, value in args.J],
            ),
            timeout=args.timeout,
        )
        print(f"[INFO] Set model configuration status: {reply.status_message}", flush=True)
        if not reply.success:
            return 1
    if args.unpause:
        unpause = node.create_client(f"{namespace}/unpause_physics", Empty)
        unpause.wait_for_service(timeout=args.timeout)
        unpause.call(Empty.Request(), timeout=args.timeout)
    return 0


def _model_xml(node: Any, args: argparse.Namespace) -> str:
    from workbench.errors import SimulationError

    if args.file:
        from workbench.model.sources import read_description

        path = Path(args.file).expanduser()
        if not path.is_file():
            raise SimulationError(f"model file '{args.file}' not found")
        return read_description(path.resolve()).text
    if args.param:
        if not node.has_param(args.param):
            raise SimulationError(
                f"parameter '{args.param}' is not set", hint="load the model into it first"
            )
        return str(node.get_param(args.param))
    if args.database:
        from workbench.model.sources import read_description, resolve_robot_path

        return read_description(resolve_robot_path(args.database)).text
    return sys.stdin.read()


def _looks_like_sdf(xml: str) -> bool:
    head = xml.lstrip()[:2000]
    return "<sdf" in head.split("<robot")[0]


def _pose_message(pose: list[float]) -> Any:
    from scipy.spatial.transform import Rotation

    from workbench.msgs.geometry_msgs import Pose

    message = Pose()
    message.position.x, message.position.y, message.position.z = pose[:3]
    x, y, z, w = Rotation.from_euler("xyz", pose[3:]).as_quat()
    message.orientation.x, message.orientation.y = float(x), float(y)
    message.orientation.z, message.orientation.w = float(z), float(w)
    return message


def _wait_for_model(node: Any, namespace: str, model: str, timeout: float, kind: Any) -> None:
    from workbench.errors import SimulationError

    client = node.create_client(f"{namespace}/get_world_properties", kind)
    client.wait_for_service(timeout=timeout)
    print(f"[INFO] Waiting for model {model} before proceeding.", flush=True)
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if model in client.call(kind.Request(), timeout=timeout).model_names:
            return
        time.sleep(0.1)
    raise SimulationError(f"model '{model}' did not appear within {timeout:g} s")
