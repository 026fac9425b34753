"""Types of the trajectory_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import builtin_interfaces, geometry_msgs, std_msgs
from workbench.msgs import trajectory_msgs as msg
from workbench.msgs import trajectory_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "JointTrajectory",
    "JointTrajectoryPoint",
    "MultiDOFJointTrajectory",
    "MultiDOFJointTrajectoryPoint",
    "msg",
    "srv",
]

class JointTrajectory(Message):
    """``trajectory_msgs/JointTrajectory``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def points(self) -> list[JointTrajectoryPoint]: ...
    @points.setter
    def points(self, value: Iterable[JointTrajectoryPoint | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        joint_names: Iterable[str] = ...,
        points: Iterable[JointTrajectoryPoint | Mapping[str, Any]] = ...,
    ) -> None: ...

class JointTrajectoryPoint(Message):
    """``trajectory_msgs/JointTrajectoryPoint``."""

    @property
    def positions(self) -> NDArray[np.float64]: ...
    @positions.setter
    def positions(self, value: ArrayLike) -> None: ...
    @property
    def velocities(self) -> NDArray[np.float64]: ...
    @velocities.setter
    def velocities(self, value: ArrayLike) -> None: ...
    @property
    def accelerations(self) -> NDArray[np.float64]: ...
    @accelerations.setter
    def accelerations(self, value: ArrayLike) -> None: ...
    @property
    def effort(self) -> NDArray[np.float64]: ...
    @effort.setter
    def effort(self, value: ArrayLike) -> None: ...
    @property
    def time_from_start(self) -> builtin_interfaces.Duration: ...
    @time_from_start.setter
    def time_from_start(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        positions: ArrayLike = ...,
        velocities: ArrayLike = ...,
        accelerations: ArrayLike = ...,
        effort: ArrayLike = ...,
        time_from_start: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...

class MultiDOFJointTrajectory(Message):
    """``trajectory_msgs/MultiDOFJointTrajectory``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def points(self) -> list[MultiDOFJointTrajectoryPoint]: ...
    @points.setter
    def points(self, value: Iterable[MultiDOFJointTrajectoryPoint | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        joint_names: Iterable[str] = ...,
        points: Iterable[MultiDOFJointTrajectoryPoint | Mapping[str, Any]] = ...,
    ) -> None: ...

class MultiDOFJointTrajectoryPoint(Message):
    """``trajectory_msgs/MultiDOFJointTrajectoryPoint``."""

    @property
    def transforms(self) -> list[geometry_msgs.Transform]: ...
    @transforms.setter
    def transforms(self, value: Iterable[geometry_msgs.Transform | Mapping[str, Any]]) -> None: ...
    @property
    def velocities(self) -> list[geometry_msgs.Twist]: ...
    @velocities.setter
    def velocities(self, value: Iterable[geometry_msgs.Twist | Mapping[str, Any]]) -> None: ...
    @property
    def accelerations(self) -> list[geometry_msgs.Twist]: ...
    @accelerations.setter
    def accelerations(self, value: Iterable[geometry_msgs.Twist | Mapping[str, Any]]) -> None: ...
    @property
    def time_from_start(self) -> builtin_interfaces.Duration: ...
    @time_from_start.setter
    def time_from_start(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        transforms: Iterable[geometry_msgs.Transform | Mapping[str, Any]] = ...,
        velocities: Iterable[geometry_msgs.Twist | Mapping[str, Any]] = ...,
        accelerations: Iterable[geometry_msgs.Twist | Mapping[str, Any]] = ...,
        time_from_start: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...
