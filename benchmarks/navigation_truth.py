"""The house's true free space for benchmarks/navigation.py: where the robot fits, how far it is.

The walls and furniture come from the house's building plan (``mapping/plans/house.yaml``,
the same pieces the simulator builds the world from), rasterised at 5 cm in the height band
of the TurtleBot3 burger. A cell is free for the robot when its centre is at least the robot's
radius from every blocked cell. Shortest paths are a Dijkstra over the free cells
(16-connected, so grid paths are within 2.7 % of straight lines) shortened afterwards by
line of sight (string pulling), close to the true shortest collision-free path.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage, sparse
from scipy.sparse import csgraph

from workbench.paths import mapping_dir

#: Height band of the burger's body above the floor, m (it is 0.192 m tall).
BAND = (0.02, 0.19)
#: 16-connected moves (dx, dy).
MOVES = [
    (dx, dy)
    for dx in range(-2, 3)
    for dy in range(-2, 3)
    if (dx, dy) != (0, 0) and np.gcd(abs(dx), abs(dy)) == 1
]


@dataclass
class TrueMap:
    """The house's blocked cells and the robot's free space on a grid.

    Attributes:
        blocked: Cells holding a wall or furniture in the robot's height band.
        clearance: Distance from each cell centre to the nearest blocked cell, m.
        free: Cells where the robot (``radius``) fits.
        x0, y0: World position of cell (0, 0)'s centre, m.
        resolution: Cell size, m.
        radius: Robot radius used for ``free``, m.
    """

    blocked: np.ndarray
    clearance: np.ndarray
    free: np.ndarray
    x0: float
    y0: float
    resolution: float
    radius: float

    def cell(self, x: float, y: float) -> tuple[int, int]:
        """The (column, row) of world point (x, y), clipped to the grid."""
        h, w = self.free.shape
        c = int(np.clip(round((x - self.x0) / self.resolution), 0, w - 1))
        r = int(np.clip(round((y - self.y0) / self.resolution), 0, h - 1))
        return c, r

    def point(self, c: int, r: int) -> tuple[float, float]:
        return self.x0 + c * self.resolution, self.y0 + r * self.resolution

    def clearance_at(self, x: float, y: float) -> float:
        c, r = self.cell(x, y)
        return float(self.clearance[r, c])


def house_true_map(
    radius: float, resolution: float = 0.05, bounds=(-6.0, 6.0, -5.0, 5.0)
) -> TrueMap:
    """The house's true map (see the module docstring); ``bounds`` xmin, xmax, ymin, ymax."""
    from workbench.sim.building import blocked_cells, load_plan

    xmin, xmax, ymin, ymax = bounds
    xs = np.arange(xmin, xmax + 1e-9, resolution)
    ys = np.arange(ymin, ymax + 1e-9, resolution)
    plan = load_plan(mapping_dir() / "plans" / "house.yaml")
    blocked = blocked_cells(plan.pieces(), xs, ys, BAND)
    # a piece thinner than a cell may fall between cell centres: sample half a cell off too
    for dx, dy in ((0.5, 0.0), (0.0, 0.5), (0.5, 0.5)):
        blocked |= blocked_cells(plan.pieces(), xs + dx * resolution, ys + dy * resolution, BAND)
    clearance = ndimage.distance_transform_edt(~blocked) * resolution
    return TrueMap(
        blocked,
        clearance,
        clearance >= radius,
        float(xs[0]),
        float(ys[0]),
        resolution,
        radius,
    )


class ShortestPaths:
    """Shortest collision-free paths on a :class:`TrueMap`'s free cells."""

    def __init__(self, truth: TrueMap) -> None:
        self.truth = truth
        h, w = truth.free.shape
        index = np.arange(h * w).reshape(h, w)
        rows, cols, weights = [], [], []
        free = truth.free
        for dx, dy in MOVES:
            src = (slice(max(0, -dy), h - max(0, dy)), slice(max(0, -dx), w - max(0, dx)))
            dst = (slice(max(0, dy), h - max(0, -dy)), slice(max(0, dx), w - max(0, -dx)))
            ok = free[src] & free[dst]
            rows.append(index[src][ok])
            cols.append(index[dst][ok])
            weights.append(np.full(int(ok.sum()), np.hypot(dx, dy) * truth.resolution))
        self.graph = sparse.csr_matrix(
            (np.concatenate(weights), (np.concatenate(rows), np.concatenate(cols))),
            shape=(h * w, h * w),
        )
        self.shape = (h, w)

    def from_point(self, x: float, y: float) -> tuple[np.ndarray, np.ndarray, int]:
        """Distances (m, ``inf`` unreachable) and predecessors of every cell from (x, y)."""
        c, r = self.truth.cell(x, y)
        source = r * self.shape[1] + c
        dist, pred = csgraph.dijkstra(self.graph, indices=source, return_predecessors=True)
        return dist, pred, source

    def reachable(self, dist: np.ndarray, x: float, y: float) -> bool:
        c, r = self.truth.cell(x, y)
        return bool(np.isfinite(dist[r * self.shape[1] + c]))

    def path_length(
        self, pred: np.ndarray, source: int, x: float, y: float
    ) -> tuple[float, list[tuple[float, float]]]:
        """The shortest path's length to (x, y) (m) and its corners; ``inf`` if unreachable."""
        w = self.shape[1]
        c, r = self.truth.cell(x, y)
        k = r * w + c
        cells = [k]
        while k != source:
            k = int(pred[k])
            if k < 0:
                return float("inf"), []
            cells.append(k)
        cells.reverse()
        corners = [cells[0]]
        i = 0
        while i < len(cells) - 1:
            j = len(cells) - 1
            while j > i + 1 and not self._visible(corners[-1], cells[j]):
                j -= 1
            corners.append(cells[j])
            i = j
        points = [self.truth.point(k % w, k // w) for k in corners]
        length = float(
            sum(
                np.hypot(b[0] - a[0], b[1] - a[1])
                for a, b in zip(points[:-1], points[1:], strict=True)
            )
        )
        return length, points

    def _visible(self, a: int, b: int) -> bool:
        w = self.shape[1]
        (ax, ay), (bx, by) = (a % w, a // w), (b % w, b // w)
        n = int(max(abs(bx - ax), abs(by - ay)) * 2) + 1
        t = np.linspace(0.0, 1.0, n + 1)
        xs = np.rint(ax + t * (bx - ax)).astype(int)
        ys = np.rint(ay + t * (by - ay)).astype(int)
        return bool(self.truth.free[ys, xs].all())
