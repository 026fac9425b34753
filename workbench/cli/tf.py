"""``workbench tf``: tf_echo (echo), view_frames / rqt_tf_tree (frames), RViz's TF display (view),
static_transform_publisher (static)."""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path
from typing import Any

from workbench.cli.values import check_rate, check_seconds
from workbench.errors import WorkbenchError

#: Longest axis ``tf view --scale`` draws, m.
MAX_SCALE = 1000.0


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
        return echo(
            args.source, args.target, rate=args.rate, count=args.count, timeout=args.timeout
        )
    if args.verb == "frames":
        out = args.png or args.pdf or args.svg or args.gv or "frames.pdf"
        return frames(duration=args.duration, out=out, yaml=args.yaml)
    if args.verb == "view":
        return view(
            fixed_frame=args.fixed_frame,
            robot=args.robot,
            scale=args.scale,
            rate=args.rate,
            duration=args.duration,
            html=args.html,
        )
    return static(args.values, once=args.once)


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


def echo(
    source: str,
    target: str,
    *,
    rate: float = 1.0,
    count: int | None = None,
    timeout: float | None = None,
) -> int:
    """tf_echo: print the pose of ``target`` in ``source`` ``rate`` times a second.

    Args:
        source: The reference frame.
        target: The frame whose pose is printed.
        rate: Prints per second.
        count: Return after this many transforms (default: until interrupted).
        timeout: Raise if no transform arrives within this many seconds.

    Raises:
        TransformError: A bad rate, count or timeout, or nothing within ``timeout``.
    """
    from workbench.tf.exceptions import TransformError

    source, target = source.lstrip("/"), target.lstrip("/")
    if not rate > 0:
        raise TransformError(f"--rate must be positive, got {rate}")
    if count is not None and count < 1:
        raise TransformError(f"--count must be at least 1, got {count}")
    if timeout is not None and not timeout > 0:
        raise TransformError(f"--timeout must be positive, got {timeout}")
    check_rate(rate, "--rate", TransformError)
    check_seconds(timeout, "--timeout", TransformError)
    node, buffer, _ = _listener()
    period = 1.0 / rate
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
                if count is not None and printed >= count:
                    return 0
            elif why != last_error:
                print(
                    f"Failure at {time.time():.3f}\nException thrown:{why}\n"
                    f"The current list of frames is:\n{buffer.all_frames_as_string()}",
                    file=sys.stderr,
                    flush=True,
                )
                last_error = why
            if timeout is not None and printed == 0 and time.monotonic() - started > timeout:
                raise TransformError(
                    f"no transform from '{source}' to '{target}' within {timeout:g} s: {why}",
                    hint="is a broadcaster running, joined to the same 'workbench core'?",
                )
            time.sleep(period)
    finally:
        node.shutdown()
    return 0


def frames(*, duration: float = 5.0, out: str = "frames.pdf", yaml: bool = False) -> int:
    """view_frames: listen for ``duration`` seconds, then draw the frame tree into ``out``.

    Args:
        duration: Seconds to listen.
        out: The picture (``.png``, ``.pdf``, ``.svg``) or graphviz source (``.gv``).
        yaml: Also print the frames as YAML.

    Raises:
        TransformError: A negative duration, or no tf data arrived.
    """
    from workbench.tf.exceptions import TransformError
    from workbench.tf.frames import frames_dot, write_frames

    if not duration >= 0:
        raise TransformError(f"--duration must not be negative, got {duration}")
    check_seconds(duration, "--duration", TransformError, zero=True)
    check_frames_output(out, TransformError)
    node, buffer, _ = _listener()
    try:
        print(f"Listening to tf data during {duration:g} seconds...", file=sys.stderr)
        time.sleep(duration)
        with buffer._lock:
            info = buffer.frames_info(time.time())
            text = buffer.all_frames_as_yaml(time.time())
    finally:
        node.shutdown()
    if not info:
        raise TransformError(
            f"no tf data received in {duration:g} s",
            hint="start the broadcasters first (and 'workbench core' to join their processes)",
        )
    if yaml:
        print(text, end="")
    written = write_frames(frames_dot(info, recorded_at=time.time()), out)
    print(f"Generating graph in {written} file...", file=sys.stderr)
    return 0


def view(
    *,
    fixed_frame: str = "world",
    robot: str | None = None,
    scale: float = 0.2,
    rate: float = 10.0,
    duration: float | None = None,
    html: str | None = None,
) -> int:
    """RViz's TF display: draw every frame as axes in Meshcat until ``duration`` or a stop.

    Args:
        fixed_frame: The frame everything is drawn in.
        robot: Also draw this robot (a ``urdf/`` name or path) posed from tf.
        scale: Axis length, m.
        rate: Redraws per second.
        duration: Stop after this many seconds (default: when interrupted).
        html: Write a snapshot here when stopping, also on Ctrl-C, SIGINT or SIGTERM.

    Raises:
        TransformError: A bad scale, rate or duration.
    """
    from workbench.tf.exceptions import TransformError

    if not scale > 0 or not rate > 0:
        raise TransformError(f"--scale and --rate must be positive, got {scale}, {rate}")
    if duration is not None and not duration > 0:
        raise TransformError(f"--duration must be positive, got {duration}")
    check_rate(rate, "--rate", TransformError)
    check_seconds(duration, "--duration", TransformError)
    if not scale <= MAX_SCALE:
        raise TransformError(f"--scale must be at most {MAX_SCALE:g}, got {scale:g}")
    from workbench.viz import Viewer
    from workbench.viz.frames import TfDisplay

    node, buffer, _ = _listener()
    viewer = Viewer.instance()
    interrupted: KeyboardInterrupt | None = None
    try:
        robot_display = None
        if robot:
            from workbench.model import load_robot
            from workbench.robot_state import RobotModelDisplay

            robot_display = RobotModelDisplay(
                load_robot(robot), buffer, viewer, fixed_frame=fixed_frame
            )
        display = TfDisplay(buffer, viewer, fixed_frame=fixed_frame, scale=scale)
        print(f"tf frames in {fixed_frame}: {viewer.url}", flush=True)
        started = time.monotonic()
        try:
            while not node.bus.is_shutdown:
                display.update()
                if robot_display is not None:
                    robot_display.update()
                if duration is not None and time.monotonic() - started >= duration:
                    break
                time.sleep(1.0 / rate)
        except KeyboardInterrupt as stop:  # also SIGTERM: write the snapshot first
            interrupted = stop
        with buffer._lock:
            names = buffer.get_frame_strings()
        print(f"{len(names)} frames: {', '.join(names) or 'none received'}", flush=True)
        if html:
            display.frame_camera()  # where the frames are now
            print(f"snapshot: {viewer.save_html(html)}", flush=True)
    finally:
        node.shutdown()
    if interrupted is not None:
        raise interrupted
    return 0


def static(values: list[str], *, once: bool = False) -> int:
    """static_transform_publisher: latch one transform on ``/tf_static`` until interrupted.

    Args:
        values: ``x y z yaw pitch roll FRAME CHILD`` or ``x y z qx qy qz qw FRAME CHILD``.
        once: Publish, then return.

    Raises:
        TransformError: The values cannot be read.
    """
    from workbench.introspect.session import cli_node
    from workbench.tf.broadcaster import StaticTransformBroadcaster, make_transform
    from workbench.tf.nodes import parse_static_args

    parent, child, xyz, q = parse_static_args(values)
    node = cli_node("static_transform_publisher")
    try:
        StaticTransformBroadcaster(node).send_transform(make_transform(parent, child, xyz, q))
        print(f"publishing {parent} -> {child} on /tf_static (latched)", file=sys.stderr)
        if not once:
            node.bus.spin()
    finally:
        node.shutdown()
    return 0


#: The output kind of each file name ``tf frames`` writes (see :mod:`workbench.output_files`).
_FRAME_KINDS = {"png": "png", "pdf": "pdf", "svg": "svg", "gv": "graphviz", "dot": "graphviz"}


def check_frames_output(out: str, error: type[WorkbenchError]) -> None:
    """Check, before listening, that the frame tree may be written to ``out``.

    Raises:
        error: An unknown extension, a missing folder, a pipe or device, or someone
            else's file.
    """
    from workbench.output_files import check_output

    kind = _FRAME_KINDS.get(Path(out).suffix.lower().lstrip("."))
    if kind is None:
        raise error(
            f"cannot write the frame tree as '{Path(out).name[:60]}'",
            hint="use a .png, .pdf, .svg or .gv file name",
        )
    check_output(out, kind, error=error)
