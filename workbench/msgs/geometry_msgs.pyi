"""Types of the geometry_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import geometry_msgs as msg
from workbench.msgs import geometry_msgs as srv
from workbench.msgs import std_msgs
from workbench.msgs._classes import Message

__all__ = [
    "Accel",
    "AccelStamped",
    "AccelWithCovariance",
    "AccelWithCovarianceStamped",
    "Inertia",
    "InertiaStamped",
    "Point",
    "Point32",
    "PointStamped",
    "Polygon",
    "PolygonStamped",
    "Pose",
    "Pose2D",
    "PoseArray",
    "PoseStamped",
    "PoseWithCovariance",
    "PoseWithCovarianceStamped",
    "Quaternion",
    "QuaternionStamped",
    "Transform",
    "TransformStamped",
    "Twist",
    "TwistStamped",
    "TwistWithCovariance",
    "TwistWithCovarianceStamped",
    "Vector3",
    "Vector3Stamped",
    "Wrench",
    "WrenchStamped",
    "msg",
    "srv",
]

class Accel(Message):
    """``geometry_msgs/Accel``."""

    @property
    def linear(self) -> Vector3: ...
    @linear.setter
    def linear(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def angular(self) -> Vector3: ...
    @angular.setter
    def angular(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        linear: Vector3 | Mapping[str, Any] = ...,
        angular: Vector3 | Mapping[str, Any] = ...,
    ) -> None: ...

class AccelStamped(Message):
    """``geometry_msgs/AccelStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def accel(self) -> Accel: ...
    @accel.setter
    def accel(self, value: Accel | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        accel: Accel | Mapping[str, Any] = ...,
    ) -> None: ...

class AccelWithCovariance(Message):
    """``geometry_msgs/AccelWithCovariance``."""

    @property
    def accel(self) -> Accel: ...
    @accel.setter
    def accel(self, value: Accel | Mapping[str, Any]) -> None: ...
    @property
    def covariance(self) -> NDArray[np.float64]: ...
    @covariance.setter
    def covariance(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        accel: Accel | Mapping[str, Any] = ...,
        covariance: ArrayLike = ...,
    ) -> None: ...

class AccelWithCovarianceStamped(Message):
    """``geometry_msgs/AccelWithCovarianceStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def accel(self) -> AccelWithCovariance: ...
    @accel.setter
    def accel(self, value: AccelWithCovariance | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        accel: AccelWithCovariance | Mapping[str, Any] = ...,
    ) -> None: ...

class Inertia(Message):
    """``geometry_msgs/Inertia``."""

    m: float
    @property
    def com(self) -> Vector3: ...
    @com.setter
    def com(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    ixx: float
    ixy: float
    ixz: float
    iyy: float
    iyz: float
    izz: float
    def __init__(
        self,
        m: float = ...,
        com: Vector3 | Mapping[str, Any] = ...,
        ixx: float = ...,
        ixy: float = ...,
        ixz: float = ...,
        iyy: float = ...,
        iyz: float = ...,
        izz: float = ...,
    ) -> None: ...

class InertiaStamped(Message):
    """``geometry_msgs/InertiaStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def inertia(self) -> Inertia: ...
    @inertia.setter
    def inertia(self, value: Inertia | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        inertia: Inertia | Mapping[str, Any] = ...,
    ) -> None: ...

class Point(Message):
    """``geometry_msgs/Point``."""

    x: float
    y: float
    z: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        z: float = ...,
    ) -> None: ...

class Point32(Message):
    """``geometry_msgs/Point32``."""

    x: float
    y: float
    z: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        z: float = ...,
    ) -> None: ...

class PointStamped(Message):
    """``geometry_msgs/PointStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def point(self) -> Point: ...
    @point.setter
    def point(self, value: Point | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        point: Point | Mapping[str, Any] = ...,
    ) -> None: ...

class Polygon(Message):
    """``geometry_msgs/Polygon``."""

    @property
    def points(self) -> list[Point32]: ...
    @points.setter
    def points(self, value: Iterable[Point32 | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        points: Iterable[Point32 | Mapping[str, Any]] = ...,
    ) -> None: ...

class PolygonStamped(Message):
    """``geometry_msgs/PolygonStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def polygon(self) -> Polygon: ...
    @polygon.setter
    def polygon(self, value: Polygon | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        polygon: Polygon | Mapping[str, Any] = ...,
    ) -> None: ...

class Pose(Message):
    """``geometry_msgs/Pose``."""

    @property
    def position(self) -> Point: ...
    @position.setter
    def position(self, value: Point | Mapping[str, Any]) -> None: ...
    @property
    def orientation(self) -> Quaternion: ...
    @orientation.setter
    def orientation(self, value: Quaternion | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        position: Point | Mapping[str, Any] = ...,
        orientation: Quaternion | Mapping[str, Any] = ...,
    ) -> None: ...

class Pose2D(Message):
    """``geometry_msgs/Pose2D``."""

    x: float
    y: float
    theta: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        theta: float = ...,
    ) -> None: ...

class PoseArray(Message):
    """``geometry_msgs/PoseArray``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def poses(self) -> list[Pose]: ...
    @poses.setter
    def poses(self, value: Iterable[Pose | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        poses: Iterable[Pose | Mapping[str, Any]] = ...,
    ) -> None: ...

class PoseStamped(Message):
    """``geometry_msgs/PoseStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def pose(self) -> Pose: ...
    @pose.setter
    def pose(self, value: Pose | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        pose: Pose | Mapping[str, Any] = ...,
    ) -> None: ...

class PoseWithCovariance(Message):
    """``geometry_msgs/PoseWithCovariance``."""

    @property
    def pose(self) -> Pose: ...
    @pose.setter
    def pose(self, value: Pose | Mapping[str, Any]) -> None: ...
    @property
    def covariance(self) -> NDArray[np.float64]: ...
    @covariance.setter
    def covariance(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        pose: Pose | Mapping[str, Any] = ...,
        covariance: ArrayLike = ...,
    ) -> None: ...

class PoseWithCovarianceStamped(Message):
    """``geometry_msgs/PoseWithCovarianceStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def pose(self) -> PoseWithCovariance: ...
    @pose.setter
    def pose(self, value: PoseWithCovariance | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        pose: PoseWithCovariance | Mapping[str, Any] = ...,
    ) -> None: ...

class Quaternion(Message):
    """``geometry_msgs/Quaternion``."""

    x: float
    y: float
    z: float
    w: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        z: float = ...,
        w: float = ...,
    ) -> None: ...

class QuaternionStamped(Message):
    """``geometry_msgs/QuaternionStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def quaternion(self) -> Quaternion: ...
    @quaternion.setter
    def quaternion(self, value: Quaternion | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        quaternion: Quaternion | Mapping[str, Any] = ...,
    ) -> None: ...

class Transform(Message):
    """``geometry_msgs/Transform``."""

    @property
    def translation(self) -> Vector3: ...
    @translation.setter
    def translation(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def rotation(self) -> Quaternion: ...
    @rotation.setter
    def rotation(self, value: Quaternion | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        translation: Vector3 | Mapping[str, Any] = ...,
        rotation: Quaternion | Mapping[str, Any] = ...,
    ) -> None: ...

class TransformStamped(Message):
    """``geometry_msgs/TransformStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    child_frame_id: str
    @property
    def transform(self) -> Transform: ...
    @transform.setter
    def transform(self, value: Transform | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        child_frame_id: str = ...,
        transform: Transform | Mapping[str, Any] = ...,
    ) -> None: ...

class Twist(Message):
    """``geometry_msgs/Twist``."""

    @property
    def linear(self) -> Vector3: ...
    @linear.setter
    def linear(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def angular(self) -> Vector3: ...
    @angular.setter
    def angular(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        linear: Vector3 | Mapping[str, Any] = ...,
        angular: Vector3 | Mapping[str, Any] = ...,
    ) -> None: ...

class TwistStamped(Message):
    """``geometry_msgs/TwistStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def twist(self) -> Twist: ...
    @twist.setter
    def twist(self, value: Twist | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        twist: Twist | Mapping[str, Any] = ...,
    ) -> None: ...

class TwistWithCovariance(Message):
    """``geometry_msgs/TwistWithCovariance``."""

    @property
    def twist(self) -> Twist: ...
    @twist.setter
    def twist(self, value: Twist | Mapping[str, Any]) -> None: ...
    @property
    def covariance(self) -> NDArray[np.float64]: ...
    @covariance.setter
    def covariance(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        twist: Twist | Mapping[str, Any] = ...,
        covariance: ArrayLike = ...,
    ) -> None: ...

class TwistWithCovarianceStamped(Message):
    """``geometry_msgs/TwistWithCovarianceStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def twist(self) -> TwistWithCovariance: ...
    @twist.setter
    def twist(self, value: TwistWithCovariance | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        twist: TwistWithCovariance | Mapping[str, Any] = ...,
    ) -> None: ...

class Vector3(Message):
    """``geometry_msgs/Vector3``."""

    x: float
    y: float
    z: float
    def __init__(
        self,
        x: float = ...,
        y: float = ...,
        z: float = ...,
    ) -> None: ...

class Vector3Stamped(Message):
    """``geometry_msgs/Vector3Stamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def vector(self) -> Vector3: ...
    @vector.setter
    def vector(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        vector: Vector3 | Mapping[str, Any] = ...,
    ) -> None: ...

class Wrench(Message):
    """``geometry_msgs/Wrench``."""

    @property
    def force(self) -> Vector3: ...
    @force.setter
    def force(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def torque(self) -> Vector3: ...
    @torque.setter
    def torque(self, value: Vector3 | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        force: Vector3 | Mapping[str, Any] = ...,
        torque: Vector3 | Mapping[str, Any] = ...,
    ) -> None: ...

class WrenchStamped(Message):
    """``geometry_msgs/WrenchStamped``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def wrench(self) -> Wrench: ...
    @wrench.setter
    def wrench(self, value: Wrench | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        wrench: Wrench | Mapping[str, Any] = ...,
    ) -> None: ...
