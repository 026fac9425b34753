"""A building as Gazebo's building editor draws it: levels of walls with doors and windows, stairs, furniture.

All lengths are metres, all positions are in the world frame (x east, y north,
z up), angles are radians here (the plan files take degrees). A wall is a
straight segment from ``start`` to ``end`` with a thickness and a height above
its level's elevation; its openings are measured along it from ``start``. A
wall's ends are square and reach half its thickness past its end points, so two
walls meeting at an end point close their corner. :meth:`BuildingPlan.validate`
checks everything a student can get wrong and raises a one-line
:class:`PlanError` naming the element.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

from workbench.errors import SimulationError

Point = tuple[float, float]
Colour = tuple[float, float, float, float]

#: Wall colour when none is given: a light plaster grey.
WALL_COLOUR: Colour = (0.85, 0.85, 0.8, 1.0)
#: Floor slabs, stairs and furniture without a colour.
FLOOR_COLOUR: Colour = (0.6, 0.6, 0.6, 1.0)
STAIRS_COLOUR: Colour = (0.55, 0.5, 0.45, 1.0)
FURNITURE_COLOUR: Colour = (0.62, 0.44, 0.26, 1.0)
DEFAULT_THICKNESS = 0.15
DEFAULT_HEIGHT = 2.5
#: The world's physics step, s: Gazebo's default.
DEFAULT_STEP = 0.001
DEFAULT_DOOR_HEIGHT = 2.0
#: A door narrower than this is reported by :meth:`BuildingPlan.notes` (a robot may not fit).
MIN_DOOR_WIDTH = 0.8
#: Lengths below this are zero.
EPS = 1e-6


class PlanError(SimulationError):
    """A building plan (file or image) that cannot become a building."""


@dataclass(frozen=True)
class Opening:
    """A door or window in a wall: centred ``at`` m from the wall's start, ``sill`` m above its foot."""

    kind: Literal["door", "window"]
    name: str
    at: float
    width: float
    height: float
    sill: float = 0.0


@dataclass
class Wall:
    """A straight wall from ``start`` to ``end`` (m) on its level.

    ``square_ends``: the wall reaches ``thickness / 2`` past both end points (walls
    drawn as centre lines close their corners); False for walls traced from an image,
    whose rectangles are exact. ``polyline``/``segment``: the wall drawn as a chain of
    points it is a segment of, for messages.
    """

    name: str
    start: Point
    end: Point
    thickness: float = DEFAULT_THICKNESS
    height: float = DEFAULT_HEIGHT
    colour: Colour = WALL_COLOUR
    openings: list[Opening] = field(default_factory=list)
    square_ends: bool = True
    polyline: str | None = None
    segment: int = 0

    @property
    def length(self) -> float:
        """Distance from start to end, m."""
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])

    @property
    def yaw(self) -> float:
        """Direction from start to end, rad."""
        return math.atan2(self.end[1] - self.start[1], self.end[0] - self.start[0])

    @property
    def label(self) -> str:
        """How messages name the wall."""
        if self.polyline is not None:
            return f"wall '{self.polyline}' (segment {self.segment})"
        return f"wall '{self.name}'"


@dataclass
class Floor:
    """A level's floor slab: the rectangle ``low``..``high`` (m), ``thickness`` m below the elevation."""

    low: Point
    high: Point
    thickness: float = 0.15
    colour: Colour = FLOOR_COLOUR


@dataclass
class Level:
    """A storey: its walls stand on ``elevation`` (m); a slab below them unless ``floor`` is None."""

    name: str
    elevation: float = 0.0
    walls: list[Wall] = field(default_factory=list)
    floor: Floor | None = None


@dataclass
class Stairs:
    """A straight flight of solid steps up from level ``bottom`` to level ``top``.

    ``start`` is the middle of the first step's front edge; the flight rises along
    ``direction`` (rad) over ``length`` m with ``steps`` equal steps of ``width`` m.
    """

    name: str
    bottom: str
    top: str
    start: Point
    direction: float
    width: float
    length: float
    steps: int
    colour: Colour = STAIRS_COLOUR


@dataclass
class Item:
    """A piece of furniture: a ``box`` or a ``table`` (top and four legs) of ``size`` (x, y, z),
    or a ``cylinder`` of ``radius`` and height ``size[2]``, standing on its level at ``position``."""

    name: str
    shape: Literal["box", "cylinder", "table"]
    position: Point
    size: tuple[float, float, float]
    level: str
    yaw: float = 0.0
    radius: float = 0.0
    colour: Colour = FURNITURE_COLOUR


@dataclass
class BuildingPlan:
    """A building: levels, stairs between them and furniture; ``source`` names its file.

    ``description``: a line for the world file's comment (``workbench world list``).
    ``max_step_size``: the world's physics step, s.

    ``traced``: the walls were traced from an image (disjoint rectangles, which
    cannot cross, so :meth:`validate` skips that check, quadratic in the walls).
    """

    name: str
    levels: list[Level] = field(default_factory=list)
    stairs: list[Stairs] = field(default_factory=list)
    items: list[Item] = field(default_factory=list)
    source: str | None = None
    traced: bool = False
    description: str = ""
    max_step_size: float = DEFAULT_STEP

    @property
    def walls(self) -> list[Wall]:
        """Every wall of every level."""
        return [wall for level in self.levels for wall in level.walls]

    def level(self, name: str) -> Level:
        """The level called ``name``.

        Raises:
            PlanError: No such level.
        """
        for level in self.levels:
            if level.name == name:
                return level
        raise self.error(
            f"no level named '{name}'",
            hint="levels: " + (", ".join(lv.name for lv in self.levels) or "none"),
        )

    def error(self, message: str, hint: str | None = None) -> PlanError:
        """A :class:`PlanError` about this plan, naming its file."""
        return PlanError(message, path=self.source, hint=hint)

    def validate(self) -> None:
        """Check the plan.

        Raises:
            PlanError: The first problem, naming the element: a zero-length or
                crossing wall, an opening wider than its wall, past its ends,
                taller than it or overlapping another, a bad size, duplicate
                names, stairs between unknown levels.
        """
        from workbench.sim.building.checks import check_plan

        check_plan(self, crossings=not self.traced)

    def notes(self) -> list[str]:
        """Things that are allowed but worth knowing (doors a robot may not fit through)."""
        return [
            f"door '{o.name}' of {wall.label} is {o.width:g} m wide (under {MIN_DOOR_WIDTH:g} m)"
            for wall in self.walls
            for o in wall.openings
            if o.kind == "door" and o.width < MIN_DOOR_WIDTH
        ]

    def summary(self) -> str:
        """One line: how many levels, walls, doors, windows, stairs and items."""
        openings = [o for wall in self.walls for o in wall.openings]
        doors = sum(o.kind == "door" for o in openings)
        parts = [
            _count(len(self.levels), "level"),
            _count(len(self.walls), "wall"),
            _count(doors, "door"),
            _count(len(openings) - doors, "window"),
            _count(len(self.stairs), "flight") + " of stairs",
            _count(len(self.items), "piece") + " of furniture",
        ]
        return f"building '{self.name}': " + ", ".join(parts)

    def pieces(self) -> list[Piece]:
        """Every box and cylinder of the building, in world coordinates."""
        from workbench.sim.building.geometry import plan_pieces

        return plan_pieces(self)

    def to_sdf(self, kind: Literal["world", "model"] = "world") -> str:
        """The building as an SDF world (ground, sun, building, furniture) or one static model.

        Raises:
            PlanError: The plan is not valid (see :meth:`validate`).
        """
        from workbench.sim.building.sdf import plan_to_sdf

        return plan_to_sdf(self, kind)

    def save(self, path: str | Path, kind: Literal["world", "model"] | None = None) -> list[Path]:
        """Write the building to ``path`` (see :func:`workbench.sim.building.sdf.save_building`)."""
        from workbench.sim.building.sdf import save_building

        return save_building(self, path, kind)


@dataclass(frozen=True)
class Piece:
    """One primitive of the building: a box of ``size`` or a cylinder of ``radius`` and ``size[2]``.

    ``pose`` is the centre and yaw in the world (x, y, z, yaw); ``group`` is the
    element it belongs to (a wall, slab, flight or item: an SDF link or model).
    """

    group: str
    name: str
    shape: Literal["box", "cylinder"]
    size: tuple[float, float, float]
    pose: tuple[float, float, float, float]
    colour: Colour
    radius: float = 0.0
    furniture: bool = False


def _count(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"
