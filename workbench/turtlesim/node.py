"""The turtlesim node: :class:`~workbench.turtlesim.sim.TurtleSim` on the bus.

Names, types and behaviour follow ROS Noetic's ``turtlesim_node``:

* global services (in the node's namespace): ``clear``, ``reset``
  (``std_srvs/Empty``), ``spawn`` (``turtlesim/Spawn``), ``kill`` (``turtlesim/Kill``);
* per turtle: ``<name>/cmd_vel`` (``geometry_msgs/Twist``, subscribed),
  ``<name>/pose`` (``turtlesim/Pose``) and ``<name>/color_sensor``
  (``turtlesim/Color``) published every update, services ``<name>/set_pen``,
  ``<name>/teleport_absolute``, ``<name>/teleport_relative``;
* private parameters ``~background_r/g/b``, set to the defaults only when
  absent, read again on ``clear`` and ``reset``;
* one update every 16 ms of wall time.

Extra (not in ROS): a ``~save_png`` service (``std_srvs/Trigger``) and the
``png`` option write snapshots of the canvas; ``view`` serves it live to a
browser (see :mod:`workbench.turtlesim.view`).
"""

from __future__ import annotations

import logging
import os
import threading
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from workbench.turtlesim.sim import (
    DEFAULT_BACKGROUND,
    UPDATE_PERIOD,
    TurtleError,
    TurtleSim,
    write_png,
)

NODE_NAME = "turtlesim"


class TurtlesimNode:
    """Run a turtlesim on a bus node.

    Args:
        node: The ``workbench.bus.Node`` (usually named ``turtlesim``).
        seed: Seeds the turtle drawing styles.
        png: Write a snapshot here about once a second and when closing.
        start_timer: Step on a bus timer every 16 ms (False: call :meth:`step` yourself).
    """

    def __init__(
        self,
        node: Any,
        *,
        seed: int = 0,
        png: str | os.PathLike[str] | None = None,
        start_timer: bool = True,
    ) -> None:
        from workbench.msgs.std_srvs import Empty, Trigger
        from workbench.msgs.turtlesim import Kill, Spawn

        self.node = node
        self.lock = threading.RLock()
        self.png = Path(png) if png is not None else None
        self._turtle_io: dict[str, list[Any]] = {}
        self._publishers: dict[str, tuple[Any, Any]] = {}
        for channel, default in zip("rgb", DEFAULT_BACKGROUND, strict=True):
            name = f"~background_{channel}"
            if not node.has_param(name):
                node.set_param(name, default)
        logger = node.get_logger()
        levels = {
            logging.INFO: logger.info,
            logging.WARNING: getattr(logger, "warning", None) or logger.warn,
            logging.ERROR: logger.error,
        }
        self.sim = TurtleSim(
            get_param=lambda name, default: node.get_param(f"~{name}", default),
            log=lambda level, text: levels.get(level, logger.info)(text),
            seed=seed,
            node_name=node.name if node.name.startswith("/") else f"/{node.name}",
            spawn_first=False,
        )
        self._services = [
            node.create_service("clear", Empty, self._on_clear),
            node.create_service("reset", Empty, self._on_reset),
            node.create_service("spawn", Spawn, self._on_spawn),
            node.create_service("kill", Kill, self._on_kill),
            node.create_service("~save_png", Trigger, self._on_save_png),
        ]
        with self.lock:
            self._spawn("", self.sim_center(), self.sim_center(), 0.0)
        self._steps = 0
        self.timer = node.create_timer(UPDATE_PERIOD, self._on_timer) if start_timer else None

    @staticmethod
    def sim_center() -> float:
        from workbench.turtlesim.sim import WORLD_SIZE

        return WORLD_SIZE / 2.0

    # --- turtles on the bus ------------------------------------------------------------

    def spawn(self, name: str, x: float, y: float, theta: float) -> str:
        """Spawn a turtle with its topics and services (as the ``spawn`` service does)."""
        with self.lock:
            return self._spawn(name, x, y, theta)

    def _spawn(self, name: str, x: float, y: float, theta: float) -> str:
        if name:  # its topics and services are named after it: refuse what they cannot be
            from workbench.bus.names import check_name

            check_name(name, "turtle name")
            self.node.resolve_name(f"{name}/teleport_absolute", "turtle's service name")
        real = self.sim.spawn(name, x, y, theta)
        self._advertise(real)
        return real

    def _advertise(self, name: str) -> None:
        from workbench.msgs.geometry_msgs import Twist
        from workbench.msgs.turtlesim import Color, Pose, SetPen, TeleportAbsolute, TeleportRelative

        node = self.node
        pose_pub = node.create_publisher(f"{name}/pose", Pose, queue_size=7)
        color_pub = node.create_publisher(f"{name}/color_sensor", Color, queue_size=7)
        self._publishers[name] = (pose_pub, color_pub)
        self._turtle_io[name] = [
            pose_pub,
            color_pub,
            node.create_subscription(
                f"{name}/cmd_vel", Twist, self._on_cmd_vel, queue_size=7, callback_args=name
            ),
            node.create_service(
                f"{name}/set_pen", SetPen, lambda req, n=name: self._on_set_pen(n, req)
            ),
            node.create_service(
                f"{name}/teleport_absolute",
                TeleportAbsolute,
                lambda req, n=name: self._on_teleport_absolute(n, req),
            ),
            node.create_service(
                f"{name}/teleport_relative",
                TeleportRelative,
                lambda req, n=name: self._on_teleport_relative(n, req),
            ),
        ]

    def _retire(self, name: str) -> None:
        self._publishers.pop(name, None)
        for handle in self._turtle_io.pop(name, []):
            for method in ("unregister", "shutdown", "destroy", "close"):
                stop = getattr(handle, method, None)
                if callable(stop):
                    stop()
                    break

    # --- callbacks ---------------------------------------------------------------------

    def _on_cmd_vel(self, msg: Any, name: str) -> None:
        with self.lock:
            turtle = self.sim.turtles.get(name)
            if turtle is not None:
                turtle.command_velocity(msg.linear.x, msg.angular.z, self.sim.time)

    def _on_set_pen(self, name: str, req: Any) -> Any:
        from workbench.msgs.turtlesim import SetPen

        with self.lock:
            self.sim.turtle(name).set_pen(req.r, req.g, req.b, req.width, bool(req.off))
        return SetPen.Response()

    def _on_teleport_absolute(self, name: str, req: Any) -> Any:
        from workbench.msgs.turtlesim import TeleportAbsolute

        with self.lock:
            self.sim.turtle(name).teleport_absolute(req.x, req.y, req.theta)
        return TeleportAbsolute.Response()

    def _on_teleport_relative(self, name: str, req: Any) -> Any:
        from workbench.msgs.turtlesim import TeleportRelative

        with self.lock:
            self.sim.turtle(name).teleport_relative(req.linear, req.angular)
        return TeleportRelative.Response()

    def _on_clear(self, req: Any) -> Any:
        from workbench.msgs.std_srvs import Empty

        with self.lock:
            self.sim.clear()
        return Empty.Response()

    def _on_reset(self, req: Any) -> Any:
        from workbench.msgs.std_srvs import Empty

        with self.lock:
            for name in list(self.sim.turtles):
                self._retire(name)
            self.sim.reset()
            self._advertise("turtle1")
        return Empty.Response()

    def _on_spawn(self, req: Any) -> Any:
        from workbench.msgs.turtlesim import Spawn

        with self.lock:
            name = self._spawn(req.name, req.x, req.y, req.theta)
        return Spawn.Response(name=name)

    def _on_kill(self, req: Any) -> Any:
        from workbench.msgs.turtlesim import Kill

        with self.lock:
            self.sim.kill(req.name)
            self._retire(req.name)
        return Kill.Response()

    def _on_save_png(self, req: Any) -> Any:
        from workbench.msgs.std_srvs import Trigger

        if self.png is None:
            return Trigger.Response(success=False, message="no --png path was given")
        self.save_png(self.png)
        return Trigger.Response(success=True, message=str(self.png))

    def _on_timer(self, event: Any = None) -> None:
        self.step()

    # --- stepping and pictures ---------------------------------------------------------

    def step(self) -> None:
        """One 16 ms update: move the turtles and publish their poses and colours."""
        from workbench.msgs.turtlesim import Color, Pose

        with self.lock:
            out = self.sim.step(UPDATE_PERIOD)
            publishers = dict(self._publishers)
        for name, (pose, colour) in out.items():
            pubs = publishers.get(name)
            if pubs is None:
                continue
            pubs[0].publish(
                Pose(
                    x=pose.x,
                    y=pose.y,
                    theta=pose.theta,
                    linear_velocity=pose.linear_velocity,
                    angular_velocity=pose.angular_velocity,
                )
            )
            pubs[1].publish(Color(r=colour[0], g=colour[1], b=colour[2]))
        self._steps += 1
        if self.png is not None and self._steps % 63 == 0:
            self.save_png(self.png)

    def advance(self, seconds: float) -> int:
        """Step for ``seconds`` of simulated time, running the bus's callbacks between steps.

        For notebooks and tests on a bus made with ``threaded=False`` (nothing else
        steps it); returns the number of 16 ms steps taken. When the bus clock is
        simulated (``bus.clock.use_sim_time()``), it follows the simulation's time, so
        stamps (and bags) carry simulated seconds.
        """
        steps = max(0, round(seconds / UPDATE_PERIOD))
        bus = self.node.bus
        for _ in range(steps):
            while bus.spin_once(0.0):
                pass
            self.step()
            if bus.clock.is_simulated:
                bus.clock.set_time(round(self.sim.time * 1e9))
        while bus.spin_once(0.0):
            pass
        return steps

    def save_png(self, path: str | os.PathLike[str]) -> Path:
        """Write the canvas with the turtles to ``path``."""
        with self.lock:
            image = self.sim.render()
        return write_png(image, path)

    def close(self) -> None:
        """Stop the timer and write a last snapshot if asked to."""
        if self.timer is not None:
            for method in ("shutdown", "cancel", "stop"):
                stop = getattr(self.timer, method, None)
                if callable(stop):
                    stop()
                    break
        if self.png is not None:
            self.save_png(self.png)


def main(argv: Sequence[str] | None = None) -> int:
    """``turtlesim/turtlesim_node``: run until interrupted (``rosrun``/launch entry point)."""
    import argparse

    parser = argparse.ArgumentParser(
        prog="turtlesim_node", description="run the turtlesim simulator"
    )
    add_arguments(parser)
    args, remaining = parser.parse_known_args(argv)
    return run_node(args, remaining)


def add_arguments(parser: Any) -> None:
    """The options of ``workbench turtlesim`` and of the registered node."""
    parser.add_argument(
        "--png", metavar="FILE", help="write the canvas to FILE every second and at exit"
    )
    parser.add_argument("--view", action="store_true", help="show the canvas live in the browser")
    parser.add_argument(
        "--port", type=int, default=0, help="port for --view (default: any free one)"
    )
    parser.add_argument("--seed", type=int, default=0, help="seed for the turtle drawings")


def run_node(args: Any, argv: Sequence[str] = ()) -> int:
    """Create the node on the default bus and spin until Ctrl-C."""
    from workbench.bus import Node

    node = Node(NODE_NAME, argv=list(argv))
    sim_node = TurtlesimNode(node, seed=args.seed, png=args.png)
    viewer = None
    if getattr(args, "view", False):
        from workbench.turtlesim.view import CanvasServer

        viewer = CanvasServer(sim_node, port=args.port)
        viewer.start()
        print(f"turtlesim canvas: {viewer.url}", flush=True)
    try:
        node.bus.spin()
    except KeyboardInterrupt:
        pass
    finally:
        if viewer is not None:
            viewer.stop()
        sim_node.close()
        node.shutdown()
    return 0


__all__ = ["TurtleError", "TurtlesimNode", "main"]
