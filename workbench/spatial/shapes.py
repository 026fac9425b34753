"""The shapes robots and scenes are made of: box, cylinder, sphere and mesh.

One vocabulary for URDF ``<geometry>``, planning-scene objects, simulator
obstacles and the viewer. Sizes are metres; a cylinder's axis is its z axis
and its origin its centre, as in URDF and Drake. pydrake is imported only by
:func:`drake_shape` and :func:`shape_from_drake`.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Union

import numpy as np
from numpy.typing import ArrayLike

from workbench.spatial.errors import SpatialError

#: The shape kinds and the fields each needs.
SHAPE_FIELDS: dict[str, tuple[str, ...]] = {
    "box": ("size",),
    "sphere": ("radius",),
    "cylinder": ("radius", "length"),
    "mesh": ("filename",),
}


@dataclass(frozen=True)
class Box:
    """A box centred on its frame; ``size`` is its (x, y, z) edge lengths, m."""

    size: tuple[float, float, float]
    kind = "box"

    def half_extents(self) -> np.ndarray:
        return np.asarray(self.size, dtype=float) / 2.0


@dataclass(frozen=True)
class Cylinder:
    """A cylinder centred on its frame with its axis along z; radius and length in m."""

    radius: float
    length: float
    kind = "cylinder"

    def half_extents(self) -> np.ndarray:
        return np.array([self.radius, self.radius, self.length / 2.0])


@dataclass(frozen=True)
class Sphere:
    """A sphere centred on its frame; radius in m."""

    radius: float
    kind = "sphere"

    def half_extents(self) -> np.ndarray:
        return np.full(3, float(self.radius))


@dataclass(frozen=True)
class Mesh:
    """A mesh file (OBJ, STL, DAE, glTF ...) scaled by ``scale`` (one factor or per axis)."""

    filename: str
    scale: float | tuple[float, float, float] = 1.0
    kind = "mesh"

    def scale3(self) -> np.ndarray:
        """The scale per axis (x, y, z)."""
        return np.broadcast_to(np.asarray(self.scale, dtype=float), (3,)).copy()

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper corner of the scaled vertices in the mesh frame, m (needs trimesh)."""
        import trimesh

        mesh: Any = trimesh.load(str(self.filename), force="mesh")
        vertices = np.asarray(mesh.vertices, dtype=np.float64) * self.scale3()
        return vertices.min(axis=0), vertices.max(axis=0)

    def half_extents(self) -> np.ndarray:
        low, high = self.bounds()
        return (high - low) / 2.0


Shape = Union[Box, Cylinder, Sphere, Mesh]  # noqa: UP007 (a runtime alias for 3.10)


def _positive(values: ArrayLike, n: int, what: str) -> list[float]:
    try:
        out = [float(v) for v in np.asarray(values, dtype=float).reshape(-1)]
    except (TypeError, ValueError):
        raise SpatialError(f"{what} must be {n} positive numbers, got {values!r}") from None
    if len(out) != n or not all(np.isfinite(v) and v > 0 for v in out):
        raise SpatialError(f"{what} must be {n} positive numbers, got {values!r}")
    return out


def box(size: ArrayLike) -> Box:
    """A :class:`Box`; raises :class:`SpatialError` unless ``size`` is 3 positive numbers."""
    sx, sy, sz = _positive(size, 3, "box size")
    return Box((sx, sy, sz))


def cylinder(radius: float, length: float) -> Cylinder:
    """A :class:`Cylinder`; raises :class:`SpatialError` unless both are positive."""
    r, length_ = _positive([radius, length], 2, "cylinder radius and length")
    return Cylinder(r, length_)


def sphere(radius: float) -> Sphere:
    """A :class:`Sphere`; raises :class:`SpatialError` unless ``radius`` is positive."""
    (r,) = _positive([radius], 1, "sphere radius")
    return Sphere(r)


def mesh(filename: str | os.PathLike[str], scale: float | ArrayLike = 1.0) -> Mesh:
    """A :class:`Mesh`; the file is not opened here."""
    if not os.fspath(filename):
        raise SpatialError("a mesh needs a filename")
    values = _positive(np.atleast_1d(scale), np.atleast_1d(scale).size, "mesh scale")
    if len(values) not in (1, 3):
        raise SpatialError(f"mesh scale must be 1 or 3 positive numbers, got {scale!r}")
    scale_value: float | tuple[float, float, float] = (
        values[0] if len(values) == 1 else (values[0], values[1], values[2])
    )
    return Mesh(os.fspath(filename), scale_value)


def make_shape(kind: str, **fields: Any) -> Shape:
    """A shape from its kind and fields (``size``, ``radius``, ``length``, ``filename``, ``scale``).

    Raises:
        SpatialError: Unknown kind, or missing or bad fields.
    """
    if kind not in SHAPE_FIELDS:
        raise SpatialError(f"unknown shape '{kind}'", hint="use one of: " + ", ".join(SHAPE_FIELDS))
    missing = [name for name in SHAPE_FIELDS[kind] if fields.get(name) is None]
    if missing:
        raise SpatialError(f"a {kind} needs {', '.join(missing)}")
    if kind == "box":
        return box(fields["size"])
    if kind == "cylinder":
        return cylinder(fields["radius"], fields["length"])
    if kind == "sphere":
        return sphere(fields["radius"])
    scale = fields.get("scale")
    return mesh(fields["filename"], 1.0 if scale is None else scale)


def drake_shape(shape: Shape, *, convex_mesh: bool = False) -> Any:
    """The pydrake geometry of a shape.

    Args:
        shape: A :class:`Box`, :class:`Cylinder`, :class:`Sphere` or :class:`Mesh`.
        convex_mesh: Give a mesh as Drake's ``Convex`` (its convex hull, what
            point-pair collision queries use) rather than ``Mesh``.
    """
    from pydrake.geometry import Box as DrakeBox
    from pydrake.geometry import Convex
    from pydrake.geometry import Cylinder as DrakeCylinder
    from pydrake.geometry import Mesh as DrakeMesh
    from pydrake.geometry import Sphere as DrakeSphere

    if isinstance(shape, Box):
        return DrakeBox(*shape.size)
    if isinstance(shape, Cylinder):
        return DrakeCylinder(shape.radius, shape.length)
    if isinstance(shape, Sphere):
        return DrakeSphere(shape.radius)
    if isinstance(shape, Mesh):
        cls = Convex if convex_mesh else DrakeMesh
        return cls(str(Path(shape.filename)), shape.scale3())  # type: ignore[call-overload]
    raise SpatialError(f"not a workbench shape: {shape!r}")


def shape_from_drake(shape: Any) -> Shape | None:
    """The workbench shape of a pydrake Box, Cylinder, Sphere, Mesh or Convex (else None)."""
    from pydrake.geometry import Box as DrakeBox
    from pydrake.geometry import Convex
    from pydrake.geometry import Cylinder as DrakeCylinder
    from pydrake.geometry import Mesh as DrakeMesh
    from pydrake.geometry import Sphere as DrakeSphere

    if isinstance(shape, DrakeBox):
        return Box((shape.width(), shape.depth(), shape.height()))
    if isinstance(shape, DrakeCylinder):
        return Cylinder(shape.radius(), shape.length())
    if isinstance(shape, DrakeSphere):
        return Sphere(shape.radius())
    if isinstance(shape, DrakeMesh | Convex):
        scale = np.asarray(shape.scale3(), dtype=float)
        value = float(scale[0]) if np.all(scale == scale[0]) else tuple(float(v) for v in scale)
        return Mesh(mesh_filename(shape), value)  # type: ignore[arg-type]
    return None


def mesh_filename(shape: Any) -> str:
    """The file of a pydrake ``Mesh`` or ``Convex`` (older Drake: ``filename()``, newer: ``source()``)."""
    if hasattr(shape, "source"):
        return str(shape.source().path())
    return str(shape.filename())
