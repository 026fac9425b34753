"""From a plan to primitives: walls split around their openings, slabs around stairwells, steps, furniture."""

from __future__ import annotations

import math

import numpy as np

from workbench.sim.building.plan import EPS, BuildingPlan, Item, Level, Piece, Stairs, Wall
from workbench.sim.building.rectangles import rectangles

#: A table's top thickness and leg width, m.
TABLE_TOP = 0.04
TABLE_LEG = 0.05


def plan_pieces(plan: BuildingPlan) -> list[Piece]:
    """Every box and cylinder of ``plan`` in world coordinates (walls, slabs, steps, furniture)."""
    pieces: list[Piece] = []
    for level in plan.levels:
        for wall in level.walls:
            pieces += wall_pieces(wall, level.elevation)
        pieces += floor_pieces(plan, level)
    for stairs in plan.stairs:
        bottom = plan.level(stairs.bottom).elevation
        pieces += stair_pieces(stairs, bottom, plan.level(stairs.top).elevation - bottom)
    for item in plan.items:
        pieces += item_pieces(item, plan.level(item.level).elevation)
    return pieces


def wall_pieces(wall: Wall, elevation: float) -> list[Piece]:
    """The boxes of ``wall``: full height between openings, below sills and above lintels."""
    length = wall.length
    cap = wall.thickness / 2 if wall.square_ends else 0.0
    spans: list[tuple[float, float, float, float]] = []  # along (from, to), up (from, to)
    edge = -cap
    for opening in sorted(wall.openings, key=lambda o: o.at):
        low, high = opening.at - opening.width / 2, opening.at + opening.width / 2
        spans.append((edge, low, 0.0, wall.height))
        spans.append((low, high, 0.0, opening.sill))
        spans.append((low, high, opening.sill + opening.height, wall.height))
        edge = high
    spans.append((edge, length + cap, 0.0, wall.height))
    yaw = wall.yaw
    cos, sin = math.cos(yaw), math.sin(yaw)
    pieces: list[Piece] = []
    for u0, u1, z0, z1 in spans:
        if u1 - u0 < EPS or z1 - z0 < EPS:
            continue
        u = (u0 + u1) / 2
        pieces.append(
            Piece(
                group=wall.name,
                name=f"{wall.name}_{len(pieces)}",
                shape="box",
                size=(u1 - u0, wall.thickness, z1 - z0),
                pose=(
                    wall.start[0] + u * cos,
                    wall.start[1] + u * sin,
                    elevation + (z0 + z1) / 2,
                    yaw,
                ),
                colour=wall.colour,
            )
        )
    return pieces


def stair_footprint(stairs: Stairs) -> tuple[tuple[float, float], tuple[float, float]]:
    """The axis-aligned rectangle (min, max corners) the flight covers, m."""
    cos, sin = math.cos(stairs.direction), math.sin(stairs.direction)
    x0, y0 = stairs.start
    corners = [
        (x0 + u * cos - v * sin, y0 + u * sin + v * cos)
        for u in (0.0, stairs.length)
        for v in (-stairs.width / 2, stairs.width / 2)
    ]
    xs, ys = [c[0] for c in corners], [c[1] for c in corners]
    return (min(xs), min(ys)), (max(xs), max(ys))


def floor_pieces(plan: BuildingPlan, level: Level) -> list[Piece]:
    """The slab of ``level`` as boxes, with a hole over every flight of stairs arriving there."""
    floor = level.floor
    if floor is None:
        return []
    holes = [stair_footprint(s) for s in plan.stairs if s.top == level.name]
    xs = sorted(
        {
            floor.low[0],
            floor.high[0],
            *_clip([h[i][0] for h in holes for i in (0, 1)], floor.low[0], floor.high[0]),
        }
    )
    ys = sorted(
        {
            floor.low[1],
            floor.high[1],
            *_clip([h[i][1] for h in holes for i in (0, 1)], floor.low[1], floor.high[1]),
        }
    )
    solid = np.ones((len(ys) - 1, len(xs) - 1), dtype=bool)
    cx = ((np.asarray(xs[:-1]) + np.asarray(xs[1:])) / 2)[None, :]
    cy = ((np.asarray(ys[:-1]) + np.asarray(ys[1:])) / 2)[:, None]
    for (hx0, hy0), (hx1, hy1) in holes:
        solid &= ~((hx0 < cx) & (cx < hx1) & (hy0 < cy) & (cy < hy1))
    group = f"floor_{level.name}"
    pieces: list[Piece] = []
    for r0, r1, c0, c1 in rectangles(solid):
        x0, x1, y0, y1 = xs[c0], xs[c1], ys[r0], ys[r1]
        pieces.append(
            Piece(
                group=group,
                name=f"{group}_{len(pieces)}",
                shape="box",
                size=(x1 - x0, y1 - y0, floor.thickness),
                pose=((x0 + x1) / 2, (y0 + y1) / 2, level.elevation - floor.thickness / 2, 0.0),
                colour=floor.colour,
            )
        )
    return pieces


def stair_pieces(stairs: Stairs, elevation: float, rise: float) -> list[Piece]:
    """Solid steps from ``elevation`` up by ``rise`` m: step i is a block (i+1) risers high."""
    run, step_rise = stairs.length / stairs.steps, rise / stairs.steps
    cos, sin = math.cos(stairs.direction), math.sin(stairs.direction)
    pieces: list[Piece] = []
    for i in range(stairs.steps):
        u, height = (i + 0.5) * run, (i + 1) * step_rise
        pieces.append(
            Piece(
                group=stairs.name,
                name=f"{stairs.name}_step_{i}",
                shape="box",
                size=(run, stairs.width, height),
                pose=(
                    stairs.start[0] + u * cos,
                    stairs.start[1] + u * sin,
                    elevation + height / 2,
                    stairs.direction,
                ),
                colour=stairs.colour,
            )
        )
    return pieces


def item_pieces(item: Item, elevation: float) -> list[Piece]:
    """A box or cylinder standing on the floor; a table is a top on four legs."""
    x, y = item.position
    sx, sy, sz = item.size
    if item.shape == "cylinder":
        return [
            Piece(
                item.name,
                item.name,
                "cylinder",
                item.size,
                (x, y, elevation + sz / 2, 0.0),
                item.colour,
                radius=item.radius,
                furniture=True,
            )
        ]
    if item.shape == "box":
        return [
            Piece(
                item.name,
                item.name,
                "box",
                item.size,
                (x, y, elevation + sz / 2, item.yaw),
                item.colour,
                furniture=True,
            )
        ]
    top = min(TABLE_TOP, sz / 2)
    leg = min(TABLE_LEG, sx / 3, sy / 3)
    pieces = [
        Piece(
            item.name,
            f"{item.name}_top",
            "box",
            (sx, sy, top),
            (x, y, elevation + sz - top / 2, item.yaw),
            item.colour,
            furniture=True,
        )
    ]
    cos, sin = math.cos(item.yaw), math.sin(item.yaw)
    for i, (u, v) in enumerate(
        (su * (sx - leg) / 2, sv * (sy - leg) / 2) for su in (-1, 1) for sv in (-1, 1)
    ):
        pieces.append(
            Piece(
                item.name,
                f"{item.name}_leg_{i}",
                "box",
                (leg, leg, sz - top),
                (
                    x + u * cos - v * sin,
                    y + u * sin + v * cos,
                    elevation + (sz - top) / 2,
                    item.yaw,
                ),
                item.colour,
                furniture=True,
            )
        )
    return pieces


def _clip(values: list[float], low: float, high: float) -> list[float]:
    return [min(max(v, low), high) for v in values]
