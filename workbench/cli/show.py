"""``workbench show FILE``: the model in the browser with joint sliders (display.launch)."""

from __future__ import annotations

import argparse
import signal
import sys
import threading


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="a .urdf, .sdf or .xacro file, or a name from urdf/")
    parser.add_argument(
        "--q",
        nargs="+",
        default=[],
        metavar="JOINT=VALUE",
        help="joint positions (rad or m), e.g. --q shoulder_pan_joint=0.5 finger_joint1=0.02",
    )
    parser.add_argument(
        "--html", metavar="OUT", help="write a self-contained HTML snapshot and exit"
    )
    parser.add_argument("--png", metavar="OUT", help="render a PNG with headless Chromium and exit")
    parser.add_argument("--width", type=int, default=1024, help="PNG width in pixels")
    parser.add_argument("--height", type=int, default=768, help="PNG height in pixels")
    parser.add_argument("--floating", action="store_true", help="do not weld the root to the world")
    parser.add_argument("--port", type=int, default=None, help="Meshcat port (default: from 7000)")


def parse_positions(items: list[str]) -> dict[str, float]:
    """``["a=0.5", "b=-1"]`` -> ``{"a": 0.5, "b": -1.0}``.

    Raises:
        ModelError: An item is not ``NAME=NUMBER``.
    """
    from workbench.errors import ModelError

    values: dict[str, float] = {}
    for item in items:
        name, sep, text = item.partition("=")
        try:
            if not sep or not name:
                raise ValueError
            values[name.strip()] = float(text)
        except ValueError:
            raise ModelError(
                f"--q {item!r} is not JOINT=VALUE", hint="e.g. --q elbow_pitch_joint=0.5"
            ) from None
    return values


def run(args: argparse.Namespace) -> int:
    import tempfile
    from pathlib import Path

    from workbench.model import load_robot
    from workbench.viz import Viewer

    robot = load_robot(args.file, floating_base=args.floating)
    q = robot.positions_from(parse_positions(args.q))
    viewer = Viewer(port=args.port) if args.port else Viewer.instance()
    viewer.show_robot(robot, q)
    viewer.frame_robot(robot, q)

    if args.html or args.png:
        if args.html:
            html = viewer.save_html(args.html)
            print(f"Wrote {html}")
        if args.png:
            with tempfile.TemporaryDirectory(prefix="workbench-show-") as tmp:
                source = (
                    Path(args.html) if args.html else viewer.save_html(Path(tmp) / "scene.html")
                )
                png = viewer.render_png(source, args.png, args.width, args.height)
            print(f"Wrote {png}")
        return 0

    viewer.add_joint_sliders(robot)
    joints = len(robot.joint_names)
    # Ctrl-C sets a flag instead of raising, so it cannot land inside a Drake call
    # (or inside the print that tells the user to press it) and turn a clean stop
    # into an interrupted one.
    stop = threading.Event()
    previous = signal.signal(signal.SIGINT, lambda *_: stop.set())
    try:
        print(f"{robot.name}: {len(robot.links)} links, {joints} movable joints")
        print(f"Open {viewer.url} in a browser (joint sliders under Open Controls). Ctrl-C stops.")
        sys.stdout.flush()
        while not stop.is_set():
            viewer.poll_sliders()
            stop.wait(0.05)
    finally:
        signal.signal(signal.SIGINT, previous)
    print("stopped")
    return 0
