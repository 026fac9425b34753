"""Helpers for the building editor tests: worlds loaded into Drake, point queries, free space."""

from __future__ import annotations

import logging
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from workbench.sim import World
from workbench.sim.building import Piece, blocked_cells
from workbench.sim.server import SERVER_PHYSICS
from workbench.sim.world_file import load_world


def world_from_file(path: str | Path, caplog: Any) -> World:
    """Load a world file (or shipped name) into a built World; fail on any warning."""
    world_file = load_world(path)
    world = World(**SERVER_PHYSICS, ground=world_file.ground_plane)
    with caplog.at_level(logging.WARNING):
        for item in world_file.models:
            assert item.model.warnings == [], item.model.warnings
            world.add_model(item.model, {"xyz": item.pose[:3], "rpy": item.pose[3:]})
        world.build()
    assert [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING] == []
    return world


def distances(world: World, point: Sequence[float]) -> dict[str, float]:
    """Signed distance (m) from ``point`` to every collision geometry (Drake's scene graph)."""
    scene_graph = world.scene_graph
    query = scene_graph.get_query_output_port().Eval(
        scene_graph.GetMyContextFromRoot(world.context)
    )
    inspector = query.inspector()
    return {
        inspector.GetName(d.id_G): float(d.distance)
        for d in query.ComputeSignedDistanceToPoint(np.asarray(point, dtype=float), 100.0)
    }


def clearance(world: World, point: Sequence[float]) -> float:
    """Distance from ``point`` to the nearest geometry but the ground, m."""
    return min(d for name, d in distances(world, point).items() if name != "ground_plane")


def occupancy(
    pieces: list[Piece],
    low: tuple[float, float],
    high: tuple[float, float],
    cell: float = 0.05,
    band: tuple[float, float] = (0.05, 0.5),
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cells (rows along y, columns along x) blocked by a piece reaching into the height ``band``.

    Returns:
        The blocked mask and the x and y of the cell centres.
    """
    xs = np.arange(low[0] + cell / 2, high[0], cell)
    ys = np.arange(low[1] + cell / 2, high[1], cell)
    blocked = blocked_cells(pieces, xs, ys, band)
    return blocked, xs, ys


def reachable(blocked: np.ndarray, xs: np.ndarray, ys: np.ndarray, start: Sequence[float],
              robot_radius: float) -> np.ndarray:  # fmt: skip
    """Cells a disc robot of ``robot_radius`` can drive to from ``start`` (8-connected)."""
    from scipy import ndimage

    cell = float(xs[1] - xs[0])
    r = int(np.ceil(robot_radius / cell))
    yy, xx = np.mgrid[-r : r + 1, -r : r + 1]
    disc = (xx * xx + yy * yy) * cell * cell <= robot_radius**2
    inflated = ndimage.binary_dilation(blocked, structure=disc)
    labels, _ = ndimage.label(~inflated, structure=np.ones((3, 3), dtype=bool))
    row, col = int(np.argmin(np.abs(ys - start[1]))), int(np.argmin(np.abs(xs - start[0])))
    assert labels[row, col] != 0, f"the start {tuple(start)} is inside an obstacle"
    return np.asarray(labels == labels[row, col], dtype=bool)


def cell_of(xs: np.ndarray, ys: np.ndarray, point: Sequence[float]) -> tuple[int, int]:
    """The (row, column) of the cell holding ``point``."""
    return int(np.argmin(np.abs(ys - point[1]))), int(np.argmin(np.abs(xs - point[0])))
