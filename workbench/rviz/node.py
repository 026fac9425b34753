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
    parser.add_argument(
        "--check",
        action="store_true",
        help="read the -d config, print its displays and exit (no viewer, no bus)",
    )


def read_config(args: argparse.Namespace) -> Any:
    """The :class:`~workbench.rviz.config.RvizConfig` of ``-d`` (None without one).

    Raises:
        ViewerError: A config that cannot be read or is past a bound.
    """
    if not args.display_config:
        return None
    from workbench.rviz.config import load_config

    return load_config(args.display_config)


def build(
    args: argparse.Namespace, bus: Any = None, meshcat: Any = None, config: Any = None
) -> Any:
    """The :class:`~workbench.rviz.RViz` the options describe.

    Args:
        args: The parsed options.
        bus: The bus (None: the process's default bus).
        meshcat: A Meshcat to draw in (None: the process viewer's, or one on ``--port``).
        config: The ``-d`` config already read (None: read it here).

    Raises:
        ViewerError: A config that cannot be read.
    """
    from workbench.rviz.rviz import RViz

    fixed = args.fixed_frame
    displays: list[Any] = list(DEFAULT_DISPLAYS)
    specs = []
    tools = None
    if config is None:
        config = read_config(args)
    if config is not None:
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
    """Draw until interrupted, or for ``--after`` seconds then write the snapshots.

    The ``-d`` config is read (and ``--check`` ends) before the node joins the bus.
    """
    _check_after(args.after)
    config = read_config(args)
    if getattr(args, "check", False):
        return check(args, config)
    from workbench.bus import default_bus

    rviz = build(args, default_bus(), config=config)
    print(f"[INFO] rviz: {rviz.url} (fixed frame: {rviz.fixed_frame})", flush=True)
    try:
        # Meshcat is driven from this thread (it must be the one that created it)
        rviz.spin(args.after if args.after is not None else float("inf"))
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


def _check_after(after: float | None) -> None:
    """Refuse an ``--after`` that is not a finite time from 0 to :data:`MAX_OPTION_SECONDS`."""
    from workbench.errors import ViewerError
    from workbench.limits import MAX_OPTION_SECONDS

    if after is not None and not 0 <= after <= MAX_OPTION_SECONDS:  # NaN fails both
        raise ViewerError(
            f"--after must be a number of seconds from 0 to {MAX_OPTION_SECONDS:,.0f}, "
            f"got {after:g}",
            hint="without --after, RViz runs until Ctrl-C",
        )


def check(args: argparse.Namespace, config: Any) -> int:
    """``--check``: print what the config would show; 0 (the config was read)."""
    from workbench.errors import ViewerError

    if config is None:
        raise ViewerError("--check reads a config: give it with -d CONFIG")
    if config.unknown:
        print(
            "[WARN] not drawn here (unknown display classes): " + ", ".join(config.unknown),
            file=sys.stderr,
            flush=True,
        )
    names = ", ".join(f"{spec.name} ({spec.class_name})" for spec in config.displays) or "none"
    fixed = args.fixed_frame or config.fixed_frame or "map, else the tf root"
    print(f"{args.display_config}: fixed frame {fixed}; displays: {names}", flush=True)
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """``rviz/rviz``: the node launch files start (``<node pkg="rviz" type="rviz"/>``)."""
    from workbench.bus.names import parse_command_line

    parser = argparse.ArgumentParser(prog="rviz", description="RViz in the browser")
    add_arguments(parser)
    raw = list(sys.argv[1:] if argv is None else argv)
    return run(parser.parse_args(parse_command_line(raw).others))
