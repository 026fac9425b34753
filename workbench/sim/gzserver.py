"""Run the simulation server on the bus: ``workbench sim`` and the ``gazebo_ros gzserver`` node.

:func:`run_server` loads a world (an SDF file or a shipped name), starts the
node ``/gazebo`` with the Gazebo ROS API, a live Meshcat view (unless
headless), the world's and the command line's plugins, and steps until
``until`` or a stop signal; it then writes the ``--html`` recording.
"""

from __future__ import annotations

import argparse
import logging
import os
import random
import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.limits import MAX_OPTION_SECONDS, MAX_SEED

_LOG = logging.getLogger("workbench.sim")


@dataclass
class ServerOptions:
    """What ``workbench sim`` and ``gzserver`` take (see ``workbench sim --help``)."""

    world: str = "empty"
    paused: bool = False
    real_time_factor: float | None = None
    fast: bool = False
    max_step_size: float | None = None
    until: float | None = None
    html: str | None = None
    seed: int = 0
    plugins: list[str] = field(default_factory=list)
    view: bool = True
    contacts: bool = False
    port: int | None = None
    start_core: bool = True
    record: bool = False
    allow_spawn_plugins: bool = False


#: Largest ``--real-time-factor`` (faster than any machine steps a world).
MAX_REAL_TIME_FACTOR = 1_000_000.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The options of ``workbench sim`` (and of the ``gazebo_ros gzserver`` node)."""
    parser.add_argument(
        "world", nargs="?", default="empty", help="an SDF .world/.sdf file or a shipped world name"
    )
    parser.add_argument("--paused", "-u", action="store_true", help="start with physics paused")
    speed = parser.add_mutually_exclusive_group()
    speed.add_argument(
        "--real-time-factor", type=float, metavar="X", help="run X times real time (default 1)"
    )
    speed.add_argument("--fast", action="store_true", help="run as fast as possible")
    parser.add_argument(
        "--max-step-size",
        type=float,
        metavar="S",
        help="physics step, s (default: the world's <max_step_size>, else 0.001)",
    )
    parser.add_argument("--until", type=float, metavar="T", help="stop at simulated time T, s")
    parser.add_argument("--html", metavar="OUT", help="write an animated recording when it stops")
    parser.add_argument("--seed", type=int, default=0, help="seed for plugins' random numbers")
    parser.add_argument(
        "--plugin",
        action="append",
        default=[],
        metavar="[MODEL=]FILE",
        help="load a world plugin, or a model plugin for MODEL (repeatable)",
    )
    parser.add_argument(
        "--allow-spawn-plugins",
        action="store_true",
        help="let models spawned over the bus load any plugin file or declared class, not "
        "only those the world loads: anyone who can reach the bus can then run code here",
    )
    parser.add_argument("--headless", action="store_true", help="no Meshcat view")
    parser.add_argument("--contacts", action="store_true", help="draw contact forces")
    parser.add_argument("--port", type=int, help="Meshcat port (default: first free from 7000)")


def options_from(args: argparse.Namespace) -> ServerOptions:
    """:class:`ServerOptions` from parsed :func:`add_arguments` arguments."""
    return ServerOptions(
        world=args.world,
        paused=args.paused,
        real_time_factor=args.real_time_factor,
        fast=args.fast,
        max_step_size=args.max_step_size,
        until=args.until,
        html=args.html,
        seed=args.seed,
        plugins=list(args.plugin),
        view=not args.headless or bool(args.html),
        contacts=args.contacts,
        port=args.port,
        allow_spawn_plugins=args.allow_spawn_plugins,
    )


def check_options(options: ServerOptions) -> Any:
    """Check ``options`` and read the world file, touching nothing else (no bus, no core).

    Returns:
        The :class:`~workbench.sim.world_file.WorldFile` of ``options.world``.

    Raises:
        SimulationError: A bad option, an unknown or unreadable world.
    """
    from workbench.sim.world_file import load_world

    until = options.until
    if until is not None and not (0 <= until <= MAX_OPTION_SECONDS):
        raise SimulationError(
            f"--until must be a simulated time from 0 to {MAX_OPTION_SECONDS:,.0f} s, got {until:g}"
        )
    rtf = options.real_time_factor
    if rtf is not None and not (0 < rtf <= MAX_REAL_TIME_FACTOR):
        raise SimulationError(
            f"--real-time-factor must be above 0 and at most {MAX_REAL_TIME_FACTOR:g}, got {rtf:g}"
        )
    if not 0 <= options.seed <= MAX_SEED:
        raise SimulationError(f"--seed must be from 0 to {MAX_SEED} (2^32 - 1), got {options.seed}")
    if options.max_step_size is not None:
        from workbench.sim.bounds import check_step_size

        check_step_size(options.max_step_size, "--max-step-size")
    return load_world(options.world)


def build_server(
    options: ServerOptions, bus: Any = None, world_file: Any = None
) -> tuple[Any, Any, Any]:
    """The world, server and live view (or None) for ``options``, with its models and plugins.

    Args:
        options: What to run.
        bus: The bus plugins' nodes join (None: plugins get no node).
        world_file: The world :func:`check_options` read (None: checked and read here).

    Raises:
        SimulationError: An unreadable world, an unloadable model, bad options.
    """
    from workbench.sim.server import SERVER_PHYSICS, SimServer
    from workbench.sim.world import World

    if world_file is None:
        world_file = check_options(options)
    rtf = options.real_time_factor
    step = options.max_step_size
    random.seed(options.seed)
    np.random.seed(options.seed)
    physics = world_file.physics
    if step is None:
        step = physics.time_step or SERVER_PHYSICS["time_step"]
    world = World(
        time_step=step,
        ground=world_file.ground_plane,
        ground_z=world_file.ground_z,
        gravity=physics.gravity if physics.gravity is not None else 9.81,
        physics=SERVER_PHYSICS["physics"],
    )
    for item in world_file.models:
        world.add_model(
            item.model,
            {"xyz": item.pose[:3], "rpy": item.pose[3:]},
            joint_positions=item.joint_positions,
        )
        for warning in item.model.warnings:
            _LOG.warning("%s", warning)
    view = None
    if options.view:
        from workbench.sim.view import LiveView
        from workbench.viz import Viewer

        viewer = Viewer(port=options.port) if options.port else Viewer.instance()
        record = options.record or bool(options.html)
        view = LiveView(world, viewer.meshcat, contacts=options.contacts, record=record)
    if options.fast:
        speed = 0.0
    elif rtf is not None:
        speed = rtf
    else:
        speed = physics.real_time_factor or 1.0
    server = SimServer(
        world,
        bus=bus,
        paused=options.paused,
        real_time_factor=speed,
        allow_spawn_plugins=options.allow_spawn_plugins,
    )
    if view is not None:
        view.attach(server)
    for spec in world_file.plugins:
        server.load_plugin(spec)
    for item in world_file.models:
        for spec in item.model.plugins:
            if spec.kind == "model":
                server.load_plugin(spec, item.model.name)
    for text in options.plugins:
        model, _, filename = text.rpartition("=")
        server.load_plugin(_command_line_plugin(filename, model), model or None)
    return world, server, view


def _command_line_plugin(filename: str, model: str) -> Any:
    """The plugin ``--plugin`` names: the user typed it, so a file may be anywhere (one in
    the working folder is found first, then the plugin path's)."""
    from xml.sax.saxutils import quoteattr

    from workbench.sim.model_spec import PluginSpec

    file, colon, class_name = filename.partition(":")
    name = Path(file).stem
    try:
        here = file.endswith(".py") and Path(file).is_file()
    except (OSError, ValueError):
        here = False
    if here:
        filename = str(Path(file).resolve()) + colon + class_name
    return PluginSpec(
        name=name,
        filename=filename,
        element=f"<plugin name={quoteattr(name)} filename={quoteattr(filename)}/>",
        kind="model" if model else "world",
        base_dir=None,
        source="--plugin",
    )


def run_server(options: ServerOptions) -> int:
    """Serve until ``until`` or a stop signal; 0 when it ran.

    The options and the world are checked before anything joins the graph: a server
    that cannot start never registers as ``/gazebo`` (which would shut down a running
    one, as a ROS master does with a second node of the same name).

    Raises:
        SimulationError: It could not start, or a run to ``--until`` ended early
            because the physics failed (the message names the model).
    """
    from workbench.bus import Bus, Node
    from workbench.sim.gazebo_ros import GazeboRosApi

    world_file = check_options(options)
    core = None
    if options.start_core:
        core = _core_if_none()
    bus = Bus.auto(quiet=core is not None)
    node = None
    server = api = view = None
    try:
        world, server, view = build_server(options, bus, world_file)
        node = Node("gazebo", bus=bus)
        api = GazeboRosApi(server, node)
        if view is not None:
            print(f"[INFO] Meshcat: {view.meshcat.web_url()}", flush=True)
        for label in server.plugin_labels():
            print(f"[INFO] plugin loaded: {label}", flush=True)
        state = "paused" if server.paused else "running"
        print(
            f"[INFO] workbench sim: world '{options.world}' {state}, models: "
            f"{', '.join(world.model_names()) or 'none'}; /gazebo services ready",
            flush=True,
        )
        try:
            server.run(until=options.until)
        finally:
            print(f"[INFO] stopped at t = {world.time:.3f} s", flush=True)
        if server.error is not None and options.until is None:
            print(f"[ERROR] {server.error}", file=sys.stderr)
        elif server.error is not None:
            raise SimulationError(
                f"the simulation stopped before t = {options.until:g} s: {server.error}",
                hint="fix the model, or the plugin or request that pushed it",
            )
        return 0
    finally:
        if view is not None and options.html:
            path = view.save_html(options.html)
            print(f"[INFO] wrote {path}", flush=True)
        if api is not None:
            api.close()
        if server is not None:
            server.stop()
        if view is not None:
            view.close()
        if node is not None:
            node.shutdown()
        bus.shutdown()
        if core is not None:
            core.close()


def _core_if_none() -> Any:
    """A core of our own when none is reachable (as roslaunch starts a master), else None."""
    from workbench.bus.bus import master_uri
    from workbench.bus.core import Core
    from workbench.bus.zconfig import parse_uri, port_open

    uri = master_uri()
    if uri in ("inproc", "none"):
        return None
    _proto, host, port = parse_uri(uri)
    if port_open(host, port):
        return None
    try:
        core = Core(uri)
    except Exception as error:  # noqa: BLE001 - any failure means: run in-process
        _LOG.info("no core started (%s); running in-process", error)
        return None
    print(f"[INFO] started core service [{uri}]", flush=True)
    return core


def gzserver_main(argv: Sequence[str] | None = None) -> int:
    """``gazebo_ros gzserver`` / ``gazebo``: the server as launch files start it.

    Accepts gzserver's ``-u`` (paused) and a world file, plus ``workbench sim``'s options.
    """
    from workbench.bus.names import parse_command_line

    parser = argparse.ArgumentParser(prog="gzserver", description="the workbench sim server")
    add_arguments(parser)
    parser.add_argument("-e", metavar="ENGINE", help="accepted, ignored (physics engine)")
    parser.add_argument("--verbose", action="store_true", help="accepted, ignored")
    raw = list(sys.argv[1:] if argv is None else argv)
    args = parser.parse_args(parse_command_line(raw).others)
    options = options_from(args)
    options.start_core = False
    if os.environ.get("WORKBENCH_SIM_HEADLESS") == "1":
        options.view = bool(options.html)
    return run_server(options)
