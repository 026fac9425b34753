"""The planning scene's obstacles as numpy arrays of primitives, with a distance table.

:class:`ObstacleSet` reads the world's fixed geometry from the collision
plant (spheres, boxes, cylinders; meshes by their bounding box; half spaces
as large boxes) and answers, for many spheres at once, which touch an
obstacle. Its distance table clears most spheres with one lookup.
"""

from __future__ import annotations

import numpy as np

from workbench.planning.collision import CollisionWorld
from workbench.planning.sphere_cover import hull_vertices
from workbench.spatial import matrix_from_rigid_transform

_transform = matrix_from_rigid_transform
#: Point-obstacle pairs one distance query holds in memory at once.
_CHUNK = 1_000_000


class ObstacleSet:
    """The world's fixed geometry as arrays of primitives (boxes include meshes' bounding boxes)."""

    def __init__(self, world: CollisionWorld):
        from pydrake.geometry import Box, Convex, Cylinder, HalfSpace, Mesh, Sphere

        plant = world.plant
        inspector = world.scene_graph.model_inspector()
        spheres, boxes, cylinders = [], [], []
        for gid in plant.GetCollisionGeometriesForBody(plant.world_body()):
            shape = inspector.GetShape(gid)
            X = _transform(inspector.GetPoseInFrame(gid))
            if isinstance(shape, Sphere):
                spheres.append((X[:3, 3], shape.radius()))
            elif isinstance(shape, Box):
                boxes.append((X, np.array([shape.width(), shape.depth(), shape.height()]) / 2))
            elif isinstance(shape, Cylinder):
                cylinders.append((X, shape.radius(), shape.length() / 2))
            elif isinstance(shape, Mesh | Convex):
                v = hull_vertices(shape)
                centre = (v.max(0) + v.min(0)) / 2
                Xc = X.copy()
                Xc[:3, 3] = X[:3, :3] @ centre + X[:3, 3]
                boxes.append((Xc, (v.max(0) - v.min(0)) / 2))
            elif isinstance(shape, HalfSpace):
                # A half space below z=0 in its frame: a very large box.
                Xc = X.copy()
                Xc[:3, 3] = X[:3, :3] @ np.array([0, 0, -50.0]) + X[:3, 3]
                boxes.append((Xc, np.array([100.0, 100.0, 50.0])))
            else:
                raise TypeError(f"no obstacle primitive for shape {type(shape).__name__}")
        self.sphere_c = np.array([s[0] for s in spheres]).reshape(-1, 3)
        self.sphere_r = np.array([s[1] for s in spheres])
        self.box_R = np.array([b[0][:3, :3] for b in boxes]).reshape(-1, 3, 3)
        self.box_p = np.array([b[0][:3, 3] for b in boxes]).reshape(-1, 3)
        self.box_h = np.array([b[1] for b in boxes]).reshape(-1, 3)
        self.cyl_R = np.array([c[0][:3, :3] for c in cylinders]).reshape(-1, 3, 3)
        self.cyl_p = np.array([c[0][:3, 3] for c in cylinders]).reshape(-1, 3)
        self.cyl_r = np.array([c[1] for c in cylinders])
        self.cyl_h = np.array([c[2] for c in cylinders])

        # Frames stacked for one matrix product: local = c @ R_k - p_k @ R_k for every k.
        self.any = bool(len(self.sphere_r) or len(self.box_h) or len(self.cyl_r))
        self.field = None
        self._box_Rcat = np.concatenate(list(self.box_R), axis=1) if len(self.box_h) else None
        self._box_off = np.einsum("kj,kji->ki", self.box_p, self.box_R)
        self._cyl_Rcat = np.concatenate(list(self.cyl_R), axis=1) if len(self.cyl_r) else None
        self._cyl_off = np.einsum("kj,kji->ki", self.cyl_p, self.cyl_R)

    def distance(self, points: np.ndarray) -> np.ndarray:
        """Distance (M,) from points (M, 3) to the nearest obstacle, m (0 inside one).

        Points go through in chunks, so memory stays near ``_CHUNK`` values however many
        obstacles the scene has.
        """
        count = max(1, len(self.sphere_r) + len(self.box_h) + len(self.cyl_r))
        step = max(1, _CHUNK // count)
        if len(points) <= step:
            return self._distance(points)
        parts = [self._distance(points[i : i + step]) for i in range(0, len(points), step)]
        return np.concatenate(parts)

    def _distance(self, points: np.ndarray) -> np.ndarray:
        best = np.full(len(points), np.inf)
        if len(self.sphere_r):
            d = np.linalg.norm(points[:, None, :] - self.sphere_c, axis=-1) - self.sphere_r
            best = np.minimum(best, d.min(axis=1))
        if self._box_Rcat is not None:
            local = (points @ self._box_Rcat).reshape(len(points), -1, 3) - self._box_off
            excess = np.maximum(np.abs(local) - self.box_h, 0.0)
            best = np.minimum(best, np.sqrt((excess * excess).sum(axis=-1)).min(axis=1))
        if self._cyl_Rcat is not None:
            local = (points @ self._cyl_Rcat).reshape(len(points), -1, 3) - self._cyl_off
            radial = np.maximum(np.hypot(local[..., 0], local[..., 1]) - self.cyl_r, 0.0)
            axial = np.maximum(np.abs(local[..., 2]) - self.cyl_h, 0.0)
            best = np.minimum(best, np.sqrt(radial * radial + axial * axial).min(axis=1))
        return np.maximum(best, 0.0)

    def build_field(self, lo: np.ndarray, hi: np.ndarray, spacing: float) -> None:
        """Tabulate :meth:`distance` on a grid over the box [lo, hi] (world frame, m).

        A sphere whose nearest grid value exceeds its radius plus half the cell
        diagonal cannot touch an obstacle (distance is 1-Lipschitz), so most
        spheres are cleared by one table lookup.
        """
        self.field_lo = np.asarray(lo, float)
        self.field_h = float(spacing)
        counts = np.maximum(1, np.ceil((np.asarray(hi) - self.field_lo) / spacing).astype(int) + 1)
        axes = [self.field_lo[i] + spacing * np.arange(counts[i]) for i in range(3)]
        field = np.empty(tuple(counts), dtype=np.float32)
        gy, gz = np.meshgrid(axes[1], axes[2], indexing="ij")
        plane = np.stack([np.zeros(gy.size), gy.ravel(), gz.ravel()], axis=1)
        for i, x in enumerate(axes[0]):
            plane[:, 0] = x
            field[i] = self.distance(plane).reshape(gy.shape)
        self.field = field
        self.field_slack = float(np.sqrt(3.0) * spacing / 2)

    def hit(self, centres: np.ndarray, radii: np.ndarray) -> np.ndarray:
        """Which spheres (centres (M, 3), radii (M,)) touch any obstacle; (M,) bool."""
        hit = np.zeros(len(centres), dtype=bool)
        r2 = (radii * radii)[:, None]
        if len(self.sphere_r):
            d = centres[:, None, :] - self.sphere_c
            reach = (radii[:, None] + self.sphere_r) ** 2
            hit |= np.any((d * d).sum(axis=-1) < reach, axis=1)
        if self._box_Rcat is not None:
            local = (centres @ self._box_Rcat).reshape(len(centres), -1, 3) - self._box_off
            excess = np.maximum(np.abs(local) - self.box_h, 0.0)
            hit |= np.any((excess * excess).sum(axis=-1) < r2, axis=1)
        if self._cyl_Rcat is not None:
            local = (centres @ self._cyl_Rcat).reshape(len(centres), -1, 3) - self._cyl_off
            radial = np.maximum(np.hypot(local[..., 0], local[..., 1]) - self.cyl_r, 0.0)
            axial = np.maximum(np.abs(local[..., 2]) - self.cyl_h, 0.0)
            hit |= np.any(radial * radial + axial * axial < r2, axis=1)
        return hit
