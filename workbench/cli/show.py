"""``workbench show FILE``: the model in the browser with joint sliders (display.launch)."""

from __future__ import annotations

import argparse
import sys
import threading

#: Largest --width or --height of a PNG, pixels.
MAX_PIXELS = 16_384


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
    import math

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
        if not math.isfinite(values[name.strip()]):
            raise ModelError(
                f"--q {item!r}: {text.strip()} is not a finite number",
                hint="give the joint position in rad, or in m for a prismatic joint",
            )
    return values


def run(args: argparse.Namespace) -> int:
    return show(
        args.file,
        positions=parse_positions(args.q),
        html=args.html,
        png=args.png,
        width=args.width,
        height=args.height,
        floating=args.floating,
        port=args.port,
    )


def show(
    file: str,
    *,
    positions: dict[str, float] | None = None,
    html: str | None = None,
    png: str | None = None,
    width: int = 1024,
    height: int = 768,
    floating: bool = False,
    port: int | None = None,
) -> int:
    """Draw a robot in Meshcat: write ``html``/``png`` and return, or serve sliders until stopped.

    Args:
        file: A description path or a name from ``urdf/``.
        positions: Joint name -> position (rad or m); others keep their default.
        html: Write a self-contained HTML snapshot here and return.
        png: Render a PNG here with headless Chromium and return.
        width, height: PNG size in pixels.
        floating: Do not weld the root link to the world.
        port: Meshcat port (default: the first free one from 7000).

    Raises:
        ModelError: A bad size, port or joint name, an unreadable description, or an
            output that may not be written (a missing folder, someone else's file).
    """
    import tempfile
    from pathlib import Path

    from workbench.cli.signals import stop_event_on_signals
    from workbench.errors import ModelError

    if width < 1 or height < 1:
        raise ModelError(f"--width and --height must be positive, got {width} x {height}")
    if width > MAX_PIXELS or height > MAX_PIXELS:
        raise ModelError(
            f"--width and --height must be at most {MAX_PIXELS:,} pixels, got {width} x {height}"
        )
    if port is not None and not 0 < port < 65536:
        raise ModelError(f"--port must be in 1..65535, got {port}")
    from workbench.output_files import check_output

    for option, value in (("--html", html), ("--png", png)):
        if value is not None and not str(value).strip():
            raise ModelError(f"{option} needs a file name")
    if html:
        check_output(html, "html-snapshot", option="--html", error=ModelError)
    if png:
        check_output(png, "png", option="--png", error=ModelError)
    from workbench.model import load_robot
    from workbench.viz import Viewer

    robot = load_robot(file, floating_base=floating)
    q = robot.positions_from(positions or {})
    viewer = Viewer(port=port) if port else Viewer.instance()
    viewer.show_robot(robot, q)
    viewer.frame_robot(robot, q)

    if html or png:
        if html:
            print(f"Wrote {viewer.save_html(html)}")
        if png:
            with tempfile.TemporaryDirectory(prefix="workbench-show-") as tmp:
                source = Path(html) if html else viewer.save_html(Path(tmp) / "scene.html")
                written = viewer.render_png(source, png, width, height)
            print(f"Wrote {written}")
        return 0

    viewer.add_joint_sliders(robot)
    joints = len(robot.joint_names)
    # SIGINT and SIGTERM set a flag instead of raising, so a stop cannot land inside a
    # Drake call (or inside the print that tells the user to press Ctrl-C).
    stop = threading.Event()
    with stop_event_on_signals(stop):
        print(f"{robot.name}: {len(robot.links)} links, {joints} movable joints")
        print(f"Open {viewer.url} in a browser (joint sliders under Open Controls). Ctrl-C stops.")
        sys.stdout.flush()
        while not stop.is_set():
            viewer.poll_sliders()
            stop.wait(0.05)
    print("stopped")
    return 0
