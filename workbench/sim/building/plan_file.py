"""Building plans written as YAML or JSON, read into a checked :class:`BuildingPlan`.

The format (lengths in m, angles in degrees; every key but the walls' ends is optional)::

    name: house                      # default: the file's name
    description: A house of five rooms.   # the world file's first comment line
    max_step_size: 0.001             # the world's physics step, s (Gazebo's default 0.001)
    thickness: 0.15                  # defaults for every wall
    height: 2.5
    colour: [0.85, 0.85, 0.8]        # r g b [a] in 0..1, '#d9d9cc', or a Gazebo name (Wood, Gazebo/Grey)
    levels:                          # or just 'walls:' for a one-storey building
      - name: ground
        elevation: 0                 # where its walls stand
        height: 2.5                  # its walls' default height
        floor: false                 # a slab below the level: true (under its walls), false,
                                     # or {min: [x, y], max: [x, y], thickness: 0.15, colour: ...};
                                     # default: true above the ground, false on it
        walls:
          - name: south
            start: [0, 0]
            end: [10, 0]
            thickness: 0.2
            colour: Wood
            doors:   [{name: front, at: 5, width: 0.9, height: 2.0}]     # at: centre, m from start
            windows: [{at: 2, width: 1.2, height: 1.0, sill: 0.9}]
          - name: outline            # a chain of walls; 'at' runs along the whole chain
            points: [[0, 0], [4, 0], [4, 3]]
            closed: false
    stairs:
      - {name: stairs, from: ground, to: first, start: [1, 1], direction: 90,
         width: 1.0, length: 3.0, steps: 12}
    furniture:
      - {name: table, type: table, at: [2, 3], size: [1.2, 0.8, 0.75], yaw: 0, level: ground}
      - {name: bin, type: cylinder, at: [4, 1], radius: 0.2, height: 0.6}
      - {name: shelf, type: box, at: [6, 1], size: [0.4, 1.6, 1.8]}
"""

from __future__ import annotations

import bisect
import difflib
import json
import math
import os
import reprlib
from pathlib import Path
from typing import Any

from workbench.sim.bounds import MAX_STEP_SIZE, MIN_STEP_SIZE
from workbench.sim.building.limits import (
    MAX_PLAN_ITEMS,
    MAX_PLAN_LEVELS,
    MAX_PLAN_NUMBER,
    MAX_PLAN_OPENINGS,
    MAX_PLAN_STAIRS,
    MAX_PLAN_WALLS,
    MAX_STEPS,
    PLAN_TREE_LIMITS,
)
from workbench.sim.building.plan import (
    DEFAULT_DOOR_HEIGHT,
    DEFAULT_HEIGHT,
    DEFAULT_STEP,
    DEFAULT_THICKNESS,
    EPS,
    FLOOR_COLOUR,
    FURNITURE_COLOUR,
    STAIRS_COLOUR,
    WALL_COLOUR,
    BuildingPlan,
    Colour,
    Floor,
    Item,
    Level,
    Opening,
    PlanError,
    Point,
    Stairs,
    Wall,
)

_PLAN_KEYS = {
    "name",
    "description",
    "max_step_size",
    "thickness",
    "height",
    "colour",
    "color",
    "levels",
    "walls",
    "stairs",
    "furniture",
}
_LEVEL_KEYS = {"name", "elevation", "height", "floor", "walls", "thickness", "colour", "color"}
_WALL_KEYS = {
    "name", "start", "end", "points", "closed", "thickness", "height", "colour", "color",
    "doors", "windows",
}  # fmt: skip
_OPENING_KEYS = {"name", "at", "width", "height", "sill"}
_FLOOR_KEYS = {"min", "max", "thickness", "colour", "color"}
_STAIRS_KEYS = {
    "name",
    "from",
    "to",
    "start",
    "direction",
    "width",
    "length",
    "steps",
    "colour",
    "color",
}
_ITEM_KEYS = {"name", "type", "at", "size", "radius", "height", "yaw", "level", "colour", "color"}
_ITEM_TYPES = ("box", "cylinder", "table")


def load_plan(path: str | os.PathLike[str]) -> BuildingPlan:
    """Read and check a plan file (``.yaml``, ``.yml`` or ``.json``).

    Raises:
        PlanError: The file is missing or not YAML/JSON, or the plan is wrong; one
            line naming the file and the element.
    """
    from workbench.limits import check_tree, load_yaml, read_text_bounded

    file = Path(path)
    text = read_text_bounded(file, "plan file", PlanError)
    if file.suffix.lower() == ".json":
        limits = PLAN_TREE_LIMITS
        try:
            doc = json.loads(text)
        except json.JSONDecodeError as error:
            raise PlanError(f"not JSON: {error.msg}", path=file, line=error.lineno) from None
        except RecursionError:  # the C decoder's own depth guard, far below the text's end
            raise PlanError(
                f"plan file is nested more than {limits.max_depth} levels deep",
                path=file,
                hint="flatten it",
            ) from None
        except ValueError as error:  # a number of more digits than Python converts
            raise PlanError(
                f"plan file holds a value JSON cannot build: {str(error).split(';')[0]}",
                path=file,
            ) from None
        check_tree(doc, "plan file", limits, PlanError, file)
    else:
        doc = load_yaml(text, "plan file", PLAN_TREE_LIMITS, PlanError, file)
    return plan_from_dict(doc, source=str(file), name=file.stem)


def plan_from_dict(doc: Any, *, source: str | None = None, name: str = "building") -> BuildingPlan:
    """A checked plan from the parsed YAML/JSON (see the module docstring for the keys).

    Raises:
        PlanError: A missing or unknown key, a wrong value, or a plan that fails
            :meth:`BuildingPlan.validate`.
    """
    reader = _Reader(source)
    if isinstance(doc, dict) and "image" in doc and "resolution" in doc:
        raise reader.error(
            "this is a map_server map, not a building plan",
            hint="read it with plan_from_image (workbench world build MAP.yaml does)",
        )
    plan_doc = reader.mapping(doc, "the plan", _PLAN_KEYS)
    plan = BuildingPlan(name=reader.text(plan_doc, "name", "the plan", name), source=source)
    description = plan_doc.get("description", "")
    if not isinstance(description, str):
        raise reader.error(f"the plan: 'description' must be text, got {description!r}")
    plan.description = " ".join(description.split())
    plan.max_step_size = reader.number(plan_doc, "max_step_size", "the plan", DEFAULT_STEP)
    if not MIN_STEP_SIZE <= plan.max_step_size <= MAX_STEP_SIZE:  # the simulator's bounds
        raise reader.error(
            f"the plan: 'max_step_size' must be in [{MIN_STEP_SIZE:g}, {MAX_STEP_SIZE:g}] s, "
            f"got {plan.max_step_size:g}"
        )
    defaults = {
        "thickness": reader.number(plan_doc, "thickness", "the plan", DEFAULT_THICKNESS),
        "height": reader.number(plan_doc, "height", "the plan", DEFAULT_HEIGHT),
        "colour": reader.colour(plan_doc, "the plan", WALL_COLOUR),
    }
    if "levels" in plan_doc and "walls" in plan_doc:
        raise reader.error("the plan has both 'levels' and 'walls'", "put the walls into a level")
    if "levels" in plan_doc:
        level_docs = reader.sequence(plan_doc["levels"], "'levels'", MAX_PLAN_LEVELS)
    else:
        level_docs = [{"name": "ground", "walls": plan_doc.get("walls", [])}]
    counter = [0]
    for index, level_doc in enumerate(level_docs):
        plan.levels.append(reader.level(level_doc, index, defaults, counter))
    for index, stairs_doc in enumerate(
        reader.sequence(plan_doc.get("stairs", []), "'stairs'", MAX_PLAN_STAIRS)
    ):
        plan.stairs.append(reader.stairs(stairs_doc, index))
    first = plan.levels[0].name if plan.levels else "ground"
    for index, item_doc in enumerate(
        reader.sequence(plan_doc.get("furniture", []), "'furniture'", MAX_PLAN_ITEMS)
    ):
        plan.items.append(reader.item(item_doc, index, first))
    for level in plan.levels:
        if level.floor is not None and level.floor.high == (math.inf, math.inf):
            level.floor = _floor_under_walls(level, level.floor, reader)
    plan.validate()
    return plan


def _floor_under_walls(level: Level, floor: Floor, reader: _Reader) -> Floor:
    """``floor: true``: the slab spans the level's walls (to their outer faces)."""
    if not level.walls:
        raise reader.error(f"level '{level.name}' has a floor but no walls to size it by")
    xs = [x for w in level.walls for x in (w.start[0], w.end[0])]
    ys = [y for w in level.walls for y in (w.start[1], w.end[1])]
    pad = max(w.thickness for w in level.walls) / 2
    return Floor(
        (min(xs) - pad, min(ys) - pad),
        (max(xs) + pad, max(ys) + pad),
        floor.thickness,
        floor.colour,
    )


class _Reader:
    """Typed access to the parsed document, every mistake a one-line PlanError."""

    def __init__(self, source: str | None) -> None:
        self.source = source
        self.walls_read = 0
        self.openings_read = 0

    def error(self, message: str, hint: str | None = None) -> PlanError:
        return PlanError(message, path=self.source, hint=hint)

    def mapping(self, value: Any, what: str, keys: set[str]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.error(f"{what} must be a mapping of keys to values, got {_kind(value)}")
        for key in value:
            if key not in keys:
                text = str(key) if isinstance(key, str) else _shown(key)
                close = difflib.get_close_matches(text[:100], sorted(keys), n=1)
                hint = (
                    f"did you mean '{close[0]}'?" if close else "keys: " + ", ".join(sorted(keys))
                )
                shown = text if len(text) <= 40 else text[:37] + "..."
                raise self.error(f"{what}: unknown key '{shown}'", hint)
        return value

    def sequence(self, value: Any, what: str, most: int | None = None) -> list[Any]:
        if value is None:
            return []
        if not isinstance(value, list):
            raise self.error(f"{what} must be a list, got {_kind(value)}")
        if most is not None and len(value) > most:
            raise self.error(
                f"{what} has {len(value):,} entries; a plan may have at most {most:,}",
                "split the building into several plans",
            )
        return value

    def count(self, attribute: str, added: int, what: str, most: int, *, keep: bool = True) -> None:
        """Add ``added`` to the plan's tally of ``what`` (only check, unless ``keep``);
        refuse it past ``most``."""
        total = getattr(self, attribute) + added
        if keep:
            setattr(self, attribute, total)
        if total > most:
            raise self.error(
                f"the plan has more than {most:,} {what}", "split the building into several plans"
            )

    def number(
        self, doc: dict[str, Any], key: str, what: str, default: float | None = None
    ) -> float:
        if key not in doc or doc[key] is None:
            if default is None:
                raise self.error(f"{what} needs '{key}'")
            return default
        value = doc[key]
        if (
            isinstance(value, bool)
            or not isinstance(value, int | float)
            or (isinstance(value, float) and not math.isfinite(value))
        ):
            raise self.error(f"{what}: '{key}' must be a number, got {_shown(value)}")
        if not _within(value):
            raise self.error(
                f"{what}: '{key}' is {_shown(value)}, beyond the {MAX_PLAN_NUMBER:,.0f} a plan "
                "allows"
            )
        return float(value)

    def text(self, doc: dict[str, Any], key: str, what: str, default: str) -> str:
        from workbench.model.limits import name_problem

        value = doc.get(key, default)
        if isinstance(value, int) and not isinstance(value, bool) and abs(value) < 10**256:
            value = str(value)
        if not isinstance(value, str) or not value.strip():
            raise self.error(f"{what}: '{key}' must be a name, got {_shown(value)}")
        text = value.strip()
        problem = name_problem(text)
        if problem is not None:
            raise self.error(f"{what}: '{key}' {_shown(text)} {problem}", "use a short name")
        return text

    def point(self, value: Any, what: str) -> Point:
        if (
            not isinstance(value, list | tuple)
            or len(value) != 2
            or not all(isinstance(v, int | float) and not isinstance(v, bool) for v in value)
            or not all(_within(v) for v in value)
        ):
            raise self.error(
                f"{what} must be a point [x, y] in m, each within {MAX_PLAN_NUMBER:,.0f}, "
                f"got {_shown(value)}"
            )
        return (float(value[0]), float(value[1]))

    def colour(self, doc: dict[str, Any], what: str, default: Colour) -> Colour:
        value = doc.get("colour", doc.get("color"))
        if value is None:
            return default
        return parse_colour(value, what, self.source)

    def level(self, doc: Any, index: int, defaults: dict[str, Any], counter: list[int]) -> Level:
        what = f"level {index}"
        doc = self.mapping(doc, what, _LEVEL_KEYS)
        name = self.text(doc, "name", what, f"level_{index}")
        what = f"level '{name}'"
        elevation = self.number(doc, "elevation", what, 0.0)
        own = {
            "thickness": self.number(doc, "thickness", what, defaults["thickness"]),
            "height": self.number(doc, "height", what, defaults["height"]),
            "colour": self.colour(doc, what, defaults["colour"]),
        }
        level = Level(name=name, elevation=elevation)
        level.floor = self.floor(doc.get("floor", elevation > EPS), what)
        for wall_doc in self.sequence(doc.get("walls", []), f"{what}: 'walls'"):
            level.walls += self.walls(wall_doc, counter[0], what, own)
            counter[0] += 1
        return level

    def floor(self, value: Any, what: str) -> Floor | None:
        if value is False or value is None:
            return None
        if value is True:
            return Floor((-math.inf, -math.inf), (math.inf, math.inf))  # sized by the walls
        doc = self.mapping(value, f"{what}: 'floor'", _FLOOR_KEYS)
        colour = self.colour(doc, f"{what}: 'floor'", FLOOR_COLOUR)
        thickness = self.number(doc, "thickness", f"{what}: 'floor'", 0.15)
        if "min" not in doc and "max" not in doc:
            return Floor((-math.inf, -math.inf), (math.inf, math.inf), thickness, colour)
        low = self.point(doc.get("min"), f"{what}: the floor's 'min'")
        high = self.point(doc.get("max"), f"{what}: the floor's 'max'")
        return Floor(low, high, thickness, colour)

    def walls(self, doc: Any, index: int, level: str, defaults: dict[str, Any]) -> list[Wall]:
        what = f"{level}, wall {index}"
        doc = self.mapping(doc, what, _WALL_KEYS)
        name = self.text(doc, "name", what, f"wall_{index}")
        what = f"{level}, wall '{name}'"
        thickness = self.number(doc, "thickness", what, defaults["thickness"])
        height = self.number(doc, "height", what, defaults["height"])
        colour = self.colour(doc, what, defaults["colour"])
        if "points" in doc:
            if "start" in doc or "end" in doc:
                raise self.error(f"{what} has both 'points' and 'start'/'end'", "give one of them")
            point_docs = self.sequence(doc["points"], f"{what}: 'points'")
            self.count("walls_read", len(point_docs) - 1, "walls", MAX_PLAN_WALLS, keep=False)
            points = [self.point(p, f"{what}: point {i}") for i, p in enumerate(point_docs)]
            if doc.get("closed", False) is True and points:
                points.append(points[0])
            if len(points) < 2:
                raise self.error(f"{what}: 'points' needs at least two points")
        else:
            if "start" not in doc or "end" not in doc:
                raise self.error(f"{what} needs 'start' and 'end' (or 'points')")
            points = [self.point(doc["start"], f"{what}: 'start'"),
                      self.point(doc["end"], f"{what}: 'end'")]  # fmt: skip
        chain = len(points) > 2
        self.count("walls_read", len(points) - 1, "walls", MAX_PLAN_WALLS)
        walls = [
            Wall(
                name=f"{name}_{i}" if chain else name,
                start=points[i],
                end=points[i + 1],
                thickness=thickness,
                height=height,
                colour=colour,
                polyline=name if chain else None,
                segment=i,
            )
            for i in range(len(points) - 1)
        ]
        ends = list(_chain_ends(walls))
        for kind in ("door", "window"):
            opening_docs = self.sequence(doc.get(f"{kind}s", []), f"{what}: '{kind}s'")
            self.count("openings_read", len(opening_docs), "doors and windows", MAX_PLAN_OPENINGS)
            for i, opening_doc in enumerate(opening_docs):
                opening = self.opening(opening_doc, kind, i, what, name)
                _place_opening(opening, walls, ends, what, self)
        return walls

    def opening(self, doc: Any, kind: str, index: int, what: str, wall: str) -> Opening:
        label = f"{what}, {kind} {index}"
        doc = self.mapping(doc, label, _OPENING_KEYS)
        name = self.text(doc, "name", label, f"{wall}_{kind}_{index}")
        label = f"{what}, {kind} '{name}'"
        if kind == "door" and "sill" in doc:
            raise self.error(f"{label}: a door has no 'sill'", "make it a window")
        return Opening(
            kind="door" if kind == "door" else "window",
            name=name,
            at=self.number(doc, "at", label),
            width=self.number(doc, "width", label, 0.9 if kind == "door" else 1.0),
            height=self.number(
                doc, "height", label, DEFAULT_DOOR_HEIGHT if kind == "door" else 1.0
            ),
            sill=0.0 if kind == "door" else self.number(doc, "sill", label, 0.9),
        )

    def stairs(self, doc: Any, index: int) -> Stairs:
        what = f"stairs {index}"
        doc = self.mapping(doc, what, _STAIRS_KEYS)
        name = self.text(doc, "name", what, f"stairs_{index}")
        what = f"stairs '{name}'"
        steps = doc.get("steps", 10)
        if isinstance(steps, bool) or not isinstance(steps, int):
            raise self.error(f"{what}: 'steps' must be a whole number, got {_shown(steps)}")
        if not 1 <= steps <= MAX_STEPS:
            raise self.error(
                f"{what}: 'steps' must be 1 to {MAX_STEPS:,}, got {_shown(steps)}",
                "a flight has a step every 15 to 20 cm",
            )
        for key in ("from", "to"):
            if key not in doc:
                raise self.error(f"{what} needs '{key}' (a level name)")
        return Stairs(
            name=name,
            bottom=self.text(doc, "from", what, ""),
            top=self.text(doc, "to", what, ""),
            start=self.point(doc.get("start"), f"{what}: 'start'"),
            direction=math.radians(self.number(doc, "direction", what, 0.0)),
            width=self.number(doc, "width", what, 1.0),
            length=self.number(doc, "length", what),
            steps=steps,
            colour=self.colour(doc, what, STAIRS_COLOUR),
        )

    def item(self, doc: Any, index: int, level: str) -> Item:
        what = f"furniture {index}"
        doc = self.mapping(doc, what, _ITEM_KEYS)
        shape = doc.get("type", "box")
        if shape not in _ITEM_TYPES:
            raise self.error(
                f"{what}: unknown type {_shown(shape)}", "types: " + ", ".join(_ITEM_TYPES)
            )
        name = self.text(doc, "name", what, f"{shape}_{index}")
        what = f"furniture '{name}'"
        if shape == "cylinder":
            if "size" in doc:
                raise self.error(f"{what}: a cylinder has 'radius' and 'height', not 'size'")
            height = self.number(doc, "height", what)
            radius = self.number(doc, "radius", what)
            size = (2 * radius, 2 * radius, height)
        else:
            for key in ("radius", "height"):
                if key in doc:
                    raise self.error(f"{what}: a {shape} has 'size: [x, y, z]', not '{key}'")
            raw = doc.get("size")
            if (
                not isinstance(raw, list)
                or len(raw) != 3
                or not all(isinstance(v, int | float) and not isinstance(v, bool) for v in raw)
                or not all(_within(v) for v in raw)
            ):
                raise self.error(
                    f"{what} needs 'size: [x, y, z]' in m, each within {MAX_PLAN_NUMBER:,.0f}, "
                    f"got {_shown(raw)}"
                )
            size = (float(raw[0]), float(raw[1]), float(raw[2]))
            radius = 0.0
        return Item(
            name=name,
            shape="cylinder" if shape == "cylinder" else ("table" if shape == "table" else "box"),
            position=self.point(doc.get("at"), f"{what}: 'at'"),
            size=size,
            level=self.text(doc, "level", what, level),
            yaw=math.radians(self.number(doc, "yaw", what, 0.0)),
            radius=radius,
            colour=self.colour(doc, what, FURNITURE_COLOUR),
        )


def _chain_ends(walls: list[Wall]) -> list[float]:
    """How far along the chain each wall ends, m."""
    ends, offset = [], 0.0
    for wall in walls:
        offset += wall.length
        ends.append(offset)
    return ends


def _place_opening(
    opening: Opening, walls: list[Wall], ends: list[float], what: str, reader: _Reader
) -> None:
    """Put ``opening`` (``at`` along the whole chain) on the segment that holds its centre.

    ``ends``: :func:`_chain_ends` of ``walls``. One reaching past the chain's ends is left
    to :meth:`BuildingPlan.validate` to report.
    """
    index = min(bisect.bisect_left(ends, opening.at - EPS), len(walls) - 1)
    wall = walls[index]
    offset = ends[index - 1] if index else 0.0
    length = wall.length
    low, high = opening.at - opening.width / 2, opening.at + opening.width / 2
    before = low < offset - EPS and wall is not walls[0]
    after = high > offset + length + EPS and wall is not walls[-1]
    if before or after:
        corner = wall.start if before else wall.end
        raise reader.error(
            f"{what}: {opening.kind} '{opening.name}' reaches round the corner at "
            f"({corner[0]:g}, {corner[1]:g})",
            "an opening must lie within one straight segment of the wall",
        )
    wall.openings.append(
        Opening(
            opening.kind,
            opening.name,
            opening.at - offset,
            opening.width,
            opening.height,
            opening.sill,
        )
    )


def parse_colour(value: Any, what: str, source: str | None = None) -> Colour:
    """An RGBA colour from ``[r, g, b(, a)]`` in 0..1, ``'#rrggbb'`` or a Gazebo material name.

    Raises:
        PlanError: Anything else.
    """
    from workbench.sim.gazebo_urdf import GAZEBO_COLOURS

    if (
        isinstance(value, list | tuple)
        and len(value) in (3, 4)
        and all(
            isinstance(v, int | float) and not isinstance(v, bool) and 0 <= v <= 1 for v in value
        )
    ):
        rgba = [float(v) for v in value] + [1.0] * (4 - len(value))
        return (rgba[0], rgba[1], rgba[2], rgba[3])
    if isinstance(value, str):
        text = value.strip()
        if text.startswith("#") and len(text) == 7:
            try:
                r, g, b = (int(text[i : i + 2], 16) / 255 for i in (1, 3, 5))
                return (r, g, b, 1.0)
            except ValueError:
                pass
        names = {key.lower().removeprefix("gazebo/"): rgba for key, rgba in GAZEBO_COLOURS.items()}
        key = text.lower().removeprefix("gazebo/")
        if key in names:
            return names[key]
    names_list = ", ".join(k.removeprefix("Gazebo/") for k in GAZEBO_COLOURS)
    raise PlanError(
        f"{what}: colour {_shown(value)} is not [r, g, b(, a)] in 0..1, '#rrggbb' or a Gazebo colour",
        path=source,
        hint=f"names: {names_list}",
    )


_SHORT = reprlib.Repr()
_SHORT.maxlevel, _SHORT.maxlist, _SHORT.maxdict = 3, 4, 4
_SHORT.maxstring = _SHORT.maxother = _SHORT.maxlong = 40


def _within(value: float) -> bool:
    """A finite number of magnitude at most :data:`MAX_PLAN_NUMBER` (NaN is not; a 400-digit
    integer is compared exactly, never converted to a float)."""
    return abs(value) <= MAX_PLAN_NUMBER


def _shown(value: Any) -> str:
    """``repr(value)`` cut short, for messages: a plan's values may be huge or deep."""
    return _SHORT.repr(value)


def _kind(value: Any) -> str:
    return "nothing" if value is None else type(value).__name__
