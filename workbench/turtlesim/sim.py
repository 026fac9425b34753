"""Turtlesim as a pure simulation: turtles, their motion, pens and the canvas.

The behaviour follows ROS Noetic's ``turtlesim`` (``turtle.cpp`` and
``turtle_frame.cpp`` in ros/ros_tutorials, noetic-devel):

* the canvas is 500 x 500 pixels; one metre is 45 pixels (the height of the
  turtle images), so the world is ``(500 - 1) / 45 = 11.0889`` m on a side;
* ``turtle1`` spawns in the centre, ``(5.544445, 5.544445, 0)``;
* the frame updates every 16 ms (62.5 Hz) with ``dt = 0.016`` s;
* a velocity command holds for 1 s, after which the turtle stops;
* the heading is integrated first and wrapped into ``[-pi, pi)``, then the
  position moves along the new heading;
* a turtle leaving the canvas is clamped to it with the warning
  ``Oh no! I hit the wall! (Clamping from [x=..., y=...])`` (in canvas
  coordinates, y down);
* pens are on by default, colour ``(0xb3, 0xb8, 0xff)``, 3 px wide;
* the background is ``(0x45, 0x56, 0xff)`` unless the parameters
  ``background_r/g/b`` say otherwise, and is re-read on ``clear``.

Coordinates: world poses are metres in the turtlesim frame (x right, y up,
origin bottom-left, theta counter-clockwise from +x). Internally each turtle
keeps its position in canvas metres (y down) as the original does, because
the wall warning prints those numbers.
"""

from __future__ import annotations

import logging
import math
import os
import random
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

from workbench.errors import SimulationError
from workbench.turtlesim.drawing import TURTLE_STYLES, draw_turtle

CANVAS_PX = 500
METER_PX = 45.0
WORLD_SIZE = (CANVAS_PX - 1) / METER_PX  # 11.0888... m
UPDATE_PERIOD = 0.016  # s, the QTimer interval of turtle_frame.cpp
UPDATE_RATE = 1.0 / UPDATE_PERIOD  # 62.5 Hz
COMMAND_TIMEOUT = 1.0  # s
DEFAULT_BACKGROUND = (0x45, 0x56, 0xFF)
DEFAULT_PEN = (0xB3, 0xB8, 0xFF)
DEFAULT_PEN_WIDTH = 3

#: ``log(level, text)``: level is a ``logging`` level number.
LogFunction = Callable[[int, str], None]
#: ``get_param(name, default)`` for the background parameters.
ParamFunction = Callable[[str, int], int]

_logger = logging.getLogger("workbench.turtlesim")


class TurtleError(SimulationError):
    """A turtle that does not exist, or a name that is taken."""


def _f32(value: float) -> float:
    """Round to float32 as the C++ service arguments do (``float x``)."""
    return float(np.float32(value))


@dataclass
class TurtlePose:
    """A turtle's pose as ``turtlesim/Pose`` carries it.

    Attributes:
        x, y: Position in metres, world frame (origin bottom-left, y up).
        theta: Heading in radians, counter-clockwise from +x, in ``[-pi, pi)``.
        linear_velocity: m/s along the heading.
        angular_velocity: rad/s.
    """

    x: float
    y: float
    theta: float
    linear_velocity: float = 0.0
    angular_velocity: float = 0.0


@dataclass
class _Teleport:
    x: float
    y: float
    theta: float
    linear: float
    relative: bool


@dataclass
class Turtle:
    """One turtle: pose, velocity command, pen and pending teleports.

    Create turtles with :meth:`TurtleSim.spawn`, not directly.
    """

    name: str
    qx: float  # canvas metres, x right
    qy: float  # canvas metres, y down
    theta: float
    style: int = 0
    lin_vel: float = 0.0
    ang_vel: float = 0.0
    last_command_time: float = 0.0
    pen_on: bool = True
    pen_color: tuple[int, int, int] = DEFAULT_PEN
    pen_width: int = DEFAULT_PEN_WIDTH
    _teleports: list[_Teleport] = field(default_factory=list)

    @property
    def pose(self) -> TurtlePose:
        """The pose as published on ``<name>/pose`` (world frame)."""
        return TurtlePose(self.qx, WORLD_SIZE - self.qy, self.theta, self.lin_vel, self.ang_vel)

    def command_velocity(self, linear_x: float, angular_z: float, now: float) -> None:
        """Take a ``cmd_vel`` command (only ``linear.x`` and ``angular.z`` matter).

        Args:
            linear_x: m/s along the heading.
            angular_z: rad/s, counter-clockwise.
            now: The time of arrival in seconds (the simulation's clock).
        """
        self.last_command_time = now
        self.lin_vel = float(linear_x)
        self.ang_vel = float(angular_z)

    def set_pen(self, r: int, g: int, b: int, width: int, off: bool) -> None:
        """``set_pen``: ``off`` lifts the pen and keeps the old colour and width.

        A ``width`` of 0 gives a 1 px pen, as a fresh ``QPen`` has in the original.
        """
        self.pen_on = not off
        if off:
            return
        self.pen_color = (int(r) & 0xFF, int(g) & 0xFF, int(b) & 0xFF)
        self.pen_width = int(width) if width != 0 else 1

    def teleport_absolute(self, x: float, y: float, theta: float) -> None:
        """Queue a jump to ``(x, y, theta)`` (world frame); done on the next update."""
        self._teleports.append(_Teleport(_f32(x), _f32(y), _f32(theta), 0.0, False))

    def teleport_relative(self, linear: float, angular: float) -> None:
        """Queue a turn by ``angular`` rad then a move of ``linear`` m along the new heading."""
        self._teleports.append(_Teleport(0.0, 0.0, _f32(angular), _f32(linear), True))


class TurtleSim:
    """The turtlesim frame: a canvas, its turtles and the update step.

    Args:
        get_param: Reads ``background_r/g/b`` (the node's private parameters);
            ``None`` uses :attr:`params`, a plain dict.
        log: Receives ``(level, text)`` for each log line; ``None`` logs to
            the ``workbench.turtlesim`` Python logger.
        seed: Seeds the choice of turtle drawing style (ROS picks an image at random).
        node_name: Printed in the start-up line.
        spawn_first: Spawn ``turtle1`` in the centre, as the node does at start.
    """

    def __init__(
        self,
        *,
        get_param: ParamFunction | None = None,
        log: LogFunction | None = None,
        seed: int = 0,
        node_name: str = "/turtlesim",
        spawn_first: bool = True,
    ) -> None:
        self.params: dict[str, int] = {}
        self._get_param = get_param or (lambda name, default: self.params.get(name, default))
        self._log = log or (lambda level, text: _logger.log(level, text))
        self._rng = random.Random(seed)
        self.time = 0.0
        self.turtles: dict[str, Turtle] = {}
        self._id_counter = 0
        self.background = DEFAULT_BACKGROUND
        self.path_image = Image.new("RGB", (CANVAS_PX, CANVAS_PX), DEFAULT_BACKGROUND)
        self._painter = ImageDraw.Draw(self.path_image)
        self.clear(log=False)
        self._log(logging.INFO, f"Starting turtlesim with node name {node_name}")
        if spawn_first:
            self.spawn("", WORLD_SIZE / 2.0, WORLD_SIZE / 2.0, 0.0)

    # --- the global services -------------------------------------------------

    def spawn(self, name: str, x: float, y: float, theta: float) -> str:
        """Add a turtle at ``(x, y, theta)`` (world frame); returns its name.

        An empty name picks ``turtleN`` with the next free N.

        Raises:
            TurtleError: ``name`` is already taken (and logs the original's error line).
        """
        real_name = name
        if not real_name:
            while True:
                self._id_counter += 1
                real_name = f"turtle{self._id_counter}"
                if real_name not in self.turtles:
                    break
        elif real_name in self.turtles:
            self._log(logging.ERROR, f"A turtled named [{name}] already exists")
            raise TurtleError(
                f"a turtle named '{name}' already exists",
                hint="choose another name or leave it empty for turtleN",
            )
        x, y, theta = _f32(x), _f32(y), _f32(theta)
        style = self._rng.randrange(len(TURTLE_STYLES))
        self.turtles[real_name] = Turtle(
            real_name, x, WORLD_SIZE - y, theta, style=style, last_command_time=self.time
        )
        self._log(
            logging.INFO,
            f"Spawning turtle [{real_name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]",
        )
        return real_name

    def kill(self, name: str) -> None:
        """Remove a turtle.

        Raises:
            TurtleError: no turtle has that name (and logs the original's error line).
        """
        if name not in self.turtles:
            self._log(logging.ERROR, f"Tried to kill turtle [{name}], which does not exist")
            known = ", ".join(sorted(self.turtles)) or "none"
            raise TurtleError(f"no turtle named '{name}' (turtles: {known})")
        del self.turtles[name]

    def clear(self, *, log: bool = True) -> None:
        """Fill the canvas with the background colour, re-reading the parameters."""
        if log:
            self._log(logging.INFO, "Clearing turtlesim.")
        r, g, b = (
            int(self._get_param(f"background_{c}", d))
            for c, d in zip("rgb", DEFAULT_BACKGROUND, strict=True)
        )
        self.background = (r & 0xFF, g & 0xFF, b & 0xFF)
        self._painter.rectangle((0, 0, CANVAS_PX, CANVAS_PX), fill=self.background)

    def reset(self) -> None:
        """Remove every turtle, respawn ``turtle1`` in the centre and clear."""
        self._log(logging.INFO, "Resetting turtlesim.")
        self.turtles.clear()
        self._id_counter = 0
        self.spawn("", WORLD_SIZE / 2.0, WORLD_SIZE / 2.0, 0.0)
        self.clear(log=False)

    def turtle(self, name: str) -> Turtle:
        """The turtle called ``name``; :class:`TurtleError` if there is none."""
        try:
            return self.turtles[name]
        except KeyError:
            known = ", ".join(sorted(self.turtles)) or "none"
            raise TurtleError(f"no turtle named '{name}' (turtles: {known})") from None

    # --- the update step -----------------------------------------------------

    def step(self, dt: float = UPDATE_PERIOD) -> dict[str, tuple[TurtlePose, tuple[int, int, int]]]:
        """Advance every turtle by ``dt`` seconds.

        Returns:
            For each turtle (in name order, as ``std::map`` iterates), its pose and the
            colour under it, which the node publishes on ``pose`` and ``color_sensor``.
        """
        self.time += dt
        out: dict[str, tuple[TurtlePose, tuple[int, int, int]]] = {}
        for name in sorted(self.turtles):
            turtle = self.turtles[name]
            self._update_turtle(turtle, dt)
            out[name] = (turtle.pose, self.color_under(turtle))
        return out

    def _update_turtle(self, t: Turtle, dt: float) -> None:
        for req in t._teleports:
            old = (t.qx, t.qy)
            if req.relative:
                t.theta += req.theta
                t.qx += math.cos(t.theta) * req.linear
                t.qy -= math.sin(t.theta) * req.linear
            else:
                t.qx = req.x
                t.qy = max(0.0, WORLD_SIZE - req.y)
                t.theta = req.theta
            if t.pen_on:
                self._line(t, old)
        t._teleports.clear()

        if self.time - t.last_command_time > COMMAND_TIMEOUT:
            t.lin_vel = 0.0
            t.ang_vel = 0.0

        old = (t.qx, t.qy)
        theta = t.theta + t.ang_vel * dt
        t.theta = theta - 2.0 * math.pi * math.floor((theta + math.pi) / (2.0 * math.pi))
        t.qx += math.cos(t.theta) * t.lin_vel * dt
        t.qy -= math.sin(t.theta) * t.lin_vel * dt

        if t.qx < 0 or t.qx > WORLD_SIZE or t.qy < 0 or t.qy > WORLD_SIZE:
            self._log(
                logging.WARNING,
                f"Oh no! I hit the wall! (Clamping from [x={t.qx:f}, y={t.qy:f}])",
            )
        t.qx = min(max(t.qx, 0.0), WORLD_SIZE)
        t.qy = min(max(t.qy, 0.0), WORLD_SIZE)
        if (t.qx, t.qy) != old and t.pen_on:
            self._line(t, old)

    def _line(self, t: Turtle, old: tuple[float, float]) -> None:
        a = (old[0] * METER_PX, old[1] * METER_PX)
        b = (t.qx * METER_PX, t.qy * METER_PX)
        width = max(1, t.pen_width)
        self._painter.line((a, b), fill=t.pen_color, width=width)
        if width > 2:  # round the joints so short segments make a continuous trail
            r = (width - 1) / 2.0
            for cx, cy in (a, b):
                self._painter.ellipse((cx - r, cy - r, cx + r, cy + r), fill=t.pen_color)

    def color_under(self, turtle: Turtle) -> tuple[int, int, int]:
        """The canvas colour (background and trails, not turtles) under ``turtle``."""
        px = min(max(round(turtle.qx * METER_PX), 0), CANVAS_PX - 1)
        py = min(max(round(turtle.qy * METER_PX), 0), CANVAS_PX - 1)
        pixel = self.path_image.getpixel((px, py))
        assert isinstance(pixel, tuple)  # the canvas is an RGB image
        r, g, b = pixel[:3]
        return int(r), int(g), int(b)

    # --- pictures ------------------------------------------------------------

    def render(self) -> Image.Image:
        """The canvas with every turtle drawn on it (a new 500 x 500 RGB image)."""
        image = self.path_image.copy()
        for name in sorted(self.turtles):
            t = self.turtles[name]
            draw_turtle(image, t.qx * METER_PX, t.qy * METER_PX, t.theta, t.style)
        return image

    def render_array(self) -> np.ndarray:
        """:meth:`render` as a ``(500, 500, 3)`` uint8 array (row 0 is the top)."""
        return np.asarray(self.render(), dtype=np.uint8)

    def save_png(self, path) -> None:
        """Write :meth:`render` to ``path`` as PNG (atomically: readers never see half a file).

        Raises:
            SimulationError: the file cannot be written.
        """
        write_png(self.render(), path)


def write_png(image: Image.Image, path: str | os.PathLike[str]) -> Path:
    """Write ``image`` to ``path`` as PNG through a temporary file and a rename.

    A viewer or a test polling the snapshot never reads a half-written file.

    Raises:
        SimulationError: the file cannot be written.
    """
    target = Path(path)
    partial = target.with_name(f".{target.name}.partial")
    try:
        image.save(partial, format="PNG")
        os.replace(partial, target)
    except OSError as error:
        partial.unlink(missing_ok=True)
        raise SimulationError(
            f"cannot write the turtlesim snapshot: {error.strerror or error}",
            path=path,
            hint="choose a writable path",
        ) from None
    return target
