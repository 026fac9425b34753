"""``workbench rviz`` and the ``rviz rviz`` node: an RViz on the bus until Ctrl-C (or ``--after``)."""

from __future__ import annotations

import argparse
import logging
import sys
from collections.abc import Sequence
from typing import Any

_LOG = logging.getLogger("workbench.rviz")

#: Without a config: what a lab session usually wants to look at.
DEFAULT_DISPLAYS = ("Grid", "TF", "RobotModel", "Marker", "MarkerArray", "LaserScan", "Map")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "-d", "--display-config", metavar="CONFIG", help="an RViz .rviz config file"
    )
    parser.add_argument(
        "-f",
        "--fixed-frame",
        metavar="FRAME",
        help="the fixed frame (default: map, else the tf root)",
    )
    parser.add_argument(
        "--html", metavar="OUT", help="write a self-contained snapshot (with --after: then exit)"
    )
    parser.add_argument(
        "--png", metavar="OUT", help="render the view to PNG with headless Chromium (with --after)"
    )
    parser.add_argument(
        "--after", type=float, metavar="SECONDS", help="run this long, write --html/--png, exit"
    )
    parser.add_argument(
        "--port", type=int, help="Meshcat port (default: the first free one from 7000)"
    )


def build(args: argparse.Namespace, bus: Any = None, meshcat: Any = None) -> Any:
    """The :class:`~workbench.rviz.RViz` the options describe.

    Raises:
        ViewerError: A config that cannot be read.
    """
    from workbench.rviz.rviz import RViz

    fixed = args.fixed_frame
    displays: list[Any] = list(DEFAULT_DISPLAYS)
    specs = []
    tools = None
    if args.display_config:
        from workbench.rviz.config import load_config

        config = load_config(args.display_config)
        fixed = fixed or config.fixed_frame
        specs = config.displays
        tools = config.tools
        displays = []
        if config.unknown:
            _LOG.warning("not drawn here (unknown display classes): %s", ", ".join(config.unknown))
    if meshcat is None and args.port:
        from workbench.viz import Viewer

        meshcat = Viewer(port=args.port).meshcat
    rviz = RViz(bus, fixed_frame=fixed, displays=displays, meshcat=meshcat, tools=tools)
    for spec in specs:
        display = rviz.add_display(spec.class_name, name=spec.name, **spec.options)
        display.enabled = spec.enabled
    return rviz


def run(args: argparse.Namespace) -> int:
    """Draw until interrupted, or for ``--after`` seconds then write the snapshots."""
    from workbench.bus import default_bus

    rviz = build(args, default_bus())
    print(f"[INFO] rviz: {rviz.url} (fixed frame: {rviz.fixed_frame})", flush=True)
    try:
        # Meshcat is driven from this thread (it must be the one that created it)
        rviz.spin(max(args.after, 0.0) if args.after is not None else float("inf"))
    finally:
        for name, status in rviz.statuses().items():
            problems = {k: v for k, v in status.items() if k != "Topic" or v != "OK"}
            for key, text in problems.items():
                print(f"[WARN] {name}: {key}: {text.splitlines()[0]}", flush=True)
        html = args.html
        if args.png and not html:
            html = str(args.png) + ".html"
        if html:
            print(f"[INFO] snapshot: {rviz.save_html(html)}", flush=True)
        if args.png:
            from workbench.viz.render import render_png

            print(f"[INFO] image: {render_png(html, args.png)}", flush=True)
        rviz.close()
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """``rviz/rviz``: the node launch files start (``<node pkg="rviz" type="rviz"/>``)."""
    from workbench.bus.names import parse_command_line

    parser = argparse.ArgumentParser(prog="rviz", description="RViz in the browser")
    add_arguments(parser)
    raw = list(sys.argv[1:] if argv is None else argv)
    return run(parser.parse_args(parse_command_line(raw).others))
