"""Types of the shape_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import geometry_msgs
from workbench.msgs import shape_msgs as msg
from workbench.msgs import shape_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "Mesh",
    "MeshTriangle",
    "Plane",
    "SolidPrimitive",
    "msg",
    "srv",
]

class Mesh(Message):
    """``shape_msgs/Mesh``."""

    @property
    def triangles(self) -> list[MeshTriangle]: ...
    @triangles.setter
    def triangles(self, value: Iterable[MeshTriangle | Mapping[str, Any]]) -> None: ...
    @property
    def vertices(self) -> list[geometry_msgs.Point]: ...
    @vertices.setter
    def vertices(self, value: Iterable[geometry_msgs.Point | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        triangles: Iterable[MeshTriangle | Mapping[str, Any]] = ...,
        vertices: Iterable[geometry_msgs.Point | Mapping[str, Any]] = ...,
    ) -> None: ...

class MeshTriangle(Message):
    """``shape_msgs/MeshTriangle``."""

    @property
    def vertex_indices(self) -> NDArray[np.uint32]: ...
    @vertex_indices.setter
    def vertex_indices(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        vertex_indices: ArrayLike = ...,
    ) -> None: ...

class Plane(Message):
    """``shape_msgs/Plane``."""

    @property
    def coef(self) -> NDArray[np.float64]: ...
    @coef.setter
    def coef(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        coef: ArrayLike = ...,
    ) -> None: ...

class SolidPrimitive(Message):
    """``shape_msgs/SolidPrimitive``."""

    BOX: Final = 1
    SPHERE: Final = 2
    CYLINDER: Final = 3
    CONE: Final = 4
    BOX_X: Final = 0
    BOX_Y: Final = 1
    BOX_Z: Final = 2
    SPHERE_RADIUS: Final = 0
    CYLINDER_HEIGHT: Final = 0
    CYLINDER_RADIUS: Final = 1
    CONE_HEIGHT: Final = 0
    CONE_RADIUS: Final = 1

    type: int
    @property
    def dimensions(self) -> NDArray[np.float64]: ...
    @dimensions.setter
    def dimensions(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        type: int = ...,
        dimensions: ArrayLike = ...,
    ) -> None: ...
