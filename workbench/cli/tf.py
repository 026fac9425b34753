"""``workbench tf``: tf_echo (echo), view_frames / rqt_tf_tree (frames), RViz's TF display (view),
static_transform_publisher (static)."""

from __future__ import annotations

import argparse
import math
import sys
import time
from typing import Any


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    echo = verbs.add_parser(
        "echo", help="print the pose of TARGET in SOURCE over and over (tf_echo)"
    )
    echo.add_argument("source", help="the reference frame (e.g. world)")
    echo.add_argument("target", help="the frame whose pose is printed (e.g. turtle1)")
    echo.add_argument("-r", "--rate", type=float, default=1.0, help="prints per second (1)")
    echo.add_argument("-n", "--count", type=int, help="exit after COUNT transforms")
    echo.add_argument(
        "--timeout", type=float, help="give up with an error if nothing arrives within SECS"
    )
    frames = verbs.add_parser(
        "frames", help="listen, then draw the frame tree with rates (view_frames)"
    )
    frames.add_argument(
        "--duration", type=float, default=5.0, help="seconds to listen (5, as view_frames)"
    )
    out = frames.add_mutually_exclusive_group()
    out.add_argument("--png", metavar="FILE", help="write a PNG")
    out.add_argument("--pdf", metavar="FILE", help="write a PDF (default frames.pdf)")
    out.add_argument("--svg", metavar="FILE", help="write an SVG")
    out.add_argument("--gv", metavar="FILE", help="write the graphviz source")
    frames.add_argument("--yaml", action="store_true", help="also print the frames as YAML")
    view = verbs.add_parser(
        "view", help="draw every frame as axes in the browser, live (RViz's TF display)"
    )
    view.add_argument("--fixed-frame", default="world", help="the frame to draw in (world)")
    view.add_argument("--robot", help="also draw this robot from tf (RViz's RobotModel display)")
    view.add_argument("--scale", type=float, default=0.2, help="axis length in metres (0.2)")
    view.add_argument("--rate", type=float, default=10.0, help="redraws per second (10)")
    view.add_argument("--duration", type=float, help="stop after SECS (default: Ctrl-C)")
    view.add_argument("--html", metavar="FILE", help="write a snapshot when stopping")
    static = verbs.add_parser(
        "static", help="publish one static transform (static_transform_publisher)"
    )
    static.add_argument(
        "values",
        nargs="+",
        metavar="ARG",
        help="x y z yaw pitch roll FRAME CHILD, or x y z qx qy qz qw FRAME CHILD",
    )
    static.add_argument("--once", action="store_true", help="publish, then exit (latched)")


def run(args: argparse.Namespace) -> int:
    if args.verb == "echo":
        return _echo(args)
    if args.verb == "frames":
        return _frames(args)
    if args.verb == "view":
        return _view(args)
    return _static(args)


def _listener() -> tuple[Any, Any, Any]:
    from workbench.introspect.session import cli_node
    from workbench.tf import Buffer, TransformListener

    node = cli_node("tf")
    buffer = Buffer()
    listener = TransformListener(buffer, node)
    return node, buffer, listener


def format_echo(st: Any) -> str:
    """tf_echo's block for one transform (a :class:`~workbench.tf.StampedTransform`)."""
    from workbench.tf.transformations import euler_from_quaternion

    x, y, z = st.translation
    qx, qy, qz, qw = st.rotation
    roll, pitch, yaw = euler_from_quaternion(st.rotation)
    deg = [math.degrees(v) for v in (roll, pitch, yaw)]
    return (
        f"At time {st.stamp_ns / 1e9:.3f}\n"
        f"- Translation: [{x:.3f}, {y:.3f}, {z:.3f}]\n"
        f"- Rotation: in Quaternion [{qx:.3f}, {qy:.3f}, {qz:.3f}, {qw:.3f}]\n"
        f"            in RPY (radian) [{roll:.3f}, {pitch:.3f}, {yaw:.3f}]\n"
        f"            in RPY (degree) [{deg[0]:.3f}, {deg[1]:.3f}, {deg[2]:.3f}]"
    )


def _echo(args: argparse.Namespace) -> int:
    from workbench.tf.exceptions import TransformError

    source, target = args.source.lstrip("/"), args.target.lstrip("/")
    if args.rate <= 0:
        raise TransformError(f"--rate must be positive, got {args.rate}")
    node, buffer, _ = _listener()
    period = 1.0 / args.rate
    started = time.monotonic()
    printed = 0
    last_error = ""
    try:
        while not node.bus.is_shutdown:
            with buffer._lock:
                ok, why = buffer.can_lookup(source, target, 0)
                st = buffer.lookup(source, target, 0) if ok else None
            if st is not None:
                print(format_echo(st), flush=True)
                printed += 1
                if args.count is not None and printed >= args.count:
                    return 0
            elif why != last_error:
                print(
                    f"Failure at {time.time():.3f}\nException thrown:{why}\n"
                    f"The current list of frames is:\n{buffer.all_frames_as_string()}",
                    file=sys.stderr,
                    flush=True,
                )
                last_error = why
            if (
                args.timeout is not None
                and printed == 0
                and time.monotonic() - started > args.timeout
            ):
                raise TransformError(
                    f"no transform from '{source}' to '{target}' within {args.timeout:g} s: {why}",
                    hint="is a broadcaster running, joined to the same 'workbench core'?",
                )
            time.sleep(period)
    finally:
        node.shutdown()
    return 0


def _frames(args: argparse.Namespace) -> int:
    from workbench.tf.frames import frames_dot, write_frames

    node, buffer, _ = _listener()
    try:
        print(f"Listening to tf data during {args.duration:g} seconds...", file=sys.stderr)
        time.sleep(max(args.duration, 0.0))
        with buffer._lock:
            info = buffer.frames_info(time.time())
            text = buffer.all_frames_as_yaml(time.time())
    finally:
        node.shutdown()
    if not info:
        from workbench.tf.exceptions import TransformError

        raise TransformError(
            f"no tf data received in {args.duration:g} s",
            hint="start the broadcasters first (and 'workbench core' to join their processes)",
        )
    if args.yaml:
        print(text, end="")
    path = args.png or args.pdf or args.svg or args.gv or "frames.pdf"
    written = write_frames(frames_dot(info, recorded_at=time.time()), path)
    print(f"Generating graph in {written} file...", file=sys.stderr)
    return 0


def _view(args: argparse.Namespace) -> int:
    from workbench.viz import Viewer
    from workbench.viz.frames import TfDisplay

    node, buffer, _ = _listener()
    viewer = Viewer.instance()
    try:
        robot_display = None
        if args.robot:
            from workbench.model import load_robot
            from workbench.robot_state import RobotModelDisplay

            robot = load_robot(args.robot)
            robot_display = RobotModelDisplay(robot, buffer, viewer, fixed_frame=args.fixed_frame)
        display = TfDisplay(buffer, viewer, fixed_frame=args.fixed_frame, scale=args.scale)
        print(f"tf frames in {args.fixed_frame}: {viewer.url}", flush=True)
        started = time.monotonic()
        while not node.bus.is_shutdown:
            display.update()
            if robot_display is not None:
                robot_display.update()
            if args.duration is not None and time.monotonic() - started >= args.duration:
                break
            time.sleep(1.0 / max(args.rate, 0.1))
        with buffer._lock:
            frames = buffer.get_frame_strings()
        print(f"{len(frames)} frames: {', '.join(frames) or 'none received'}", flush=True)
        if args.html:
            print(f"snapshot: {viewer.save_html(args.html)}", flush=True)
    finally:
        node.shutdown()
    return 0


def _static(args: argparse.Namespace) -> int:
    from workbench.introspect.session import cli_node
    from workbench.tf.broadcaster import StaticTransformBroadcaster, make_transform
    from workbench.tf.nodes import parse_static_args

    parent, child, xyz, q = parse_static_args(args.values)
    node = cli_node("static_transform_publisher")
    try:
        StaticTransformBroadcaster(node).send_transform(make_transform(parent, child, xyz, q))
        print(f"publishing {parent} -> {child} on /tf_static (latched)", file=sys.stderr)
        if not args.once:
            node.bus.spin()
    finally:
        node.shutdown()
    return 0
