"""Types of the nav_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import actionlib_msgs, builtin_interfaces, geometry_msgs, std_msgs
from workbench.msgs import nav_msgs as msg
from workbench.msgs import nav_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "GetMap",
    "GetMapAction",
    "GetMapActionFeedback",
    "GetMapActionGoal",
    "GetMapActionResult",
    "GetMapFeedback",
    "GetMapGoal",
    "GetMapRequest",
    "GetMapResponse",
    "GetMapResult",
    "GetPlan",
    "GetPlanRequest",
    "GetPlanResponse",
    "GridCells",
    "LoadMap",
    "LoadMapRequest",
    "LoadMapResponse",
    "MapMetaData",
    "OccupancyGrid",
    "Odometry",
    "Path",
    "SetMap",
    "SetMapRequest",
    "SetMapResponse",
    "msg",
    "srv",
]

class GetMapAction(Message):
    """``nav_msgs/GetMapAction``."""

    @property
    def action_goal(self) -> GetMapActionGoal: ...
    @action_goal.setter
    def action_goal(self, value: GetMapActionGoal | Mapping[str, Any]) -> None: ...
    @property
    def action_result(self) -> GetMapActionResult: ...
    @action_result.setter
    def action_result(self, value: GetMapActionResult | Mapping[str, Any]) -> None: ...
    @property
    def action_feedback(self) -> GetMapActionFeedback: ...
    @action_feedback.setter
    def action_feedback(self, value: GetMapActionFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        action_goal: GetMapActionGoal | Mapping[str, Any] = ...,
        action_result: GetMapActionResult | Mapping[str, Any] = ...,
        action_feedback: GetMapActionFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class GetMapActionFeedback(Message):
    """``nav_msgs/GetMapActionFeedback``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def feedback(self) -> GetMapFeedback: ...
    @feedback.setter
    def feedback(self, value: GetMapFeedback | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        feedback: GetMapFeedback | Mapping[str, Any] = ...,
    ) -> None: ...

class GetMapActionGoal(Message):
    """``nav_msgs/GetMapActionGoal``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def goal_id(self) -> actionlib_msgs.GoalID: ...
    @goal_id.setter
    def goal_id(self, value: actionlib_msgs.GoalID | Mapping[str, Any]) -> None: ...
    @property
    def goal(self) -> GetMapGoal: ...
    @goal.setter
    def goal(self, value: GetMapGoal | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        goal_id: actionlib_msgs.GoalID | Mapping[str, Any] = ...,
        goal: GetMapGoal | Mapping[str, Any] = ...,
    ) -> None: ...

class GetMapActionResult(Message):
    """``nav_msgs/GetMapActionResult``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> actionlib_msgs.GoalStatus: ...
    @status.setter
    def status(self, value: actionlib_msgs.GoalStatus | Mapping[str, Any]) -> None: ...
    @property
    def result(self) -> GetMapResult: ...
    @result.setter
    def result(self, value: GetMapResult | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: actionlib_msgs.GoalStatus | Mapping[str, Any] = ...,
        result: GetMapResult | Mapping[str, Any] = ...,
    ) -> None: ...

class GetMapFeedback(Message):
    """``nav_msgs/GetMapFeedback``."""

    def __init__(self) -> None: ...

class GetMapGoal(Message):
    """``nav_msgs/GetMapGoal``."""

    def __init__(self) -> None: ...

class GetMapRequest(Message):
    """``nav_msgs/GetMapRequest``."""

    def __init__(self) -> None: ...

class GetMapResponse(Message):
    """``nav_msgs/GetMapResponse``."""

    @property
    def map(self) -> OccupancyGrid: ...
    @map.setter
    def map(self, value: OccupancyGrid | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        map: OccupancyGrid | Mapping[str, Any] = ...,
    ) -> None: ...

class GetMapResult(Message):
    """``nav_msgs/GetMapResult``."""

    @property
    def map(self) -> OccupancyGrid: ...
    @map.setter
    def map(self, value: OccupancyGrid | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        map: OccupancyGrid | Mapping[str, Any] = ...,
    ) -> None: ...

class GetPlanRequest(Message):
    """``nav_msgs/GetPlanRequest``."""

    @property
    def start(self) -> geometry_msgs.PoseStamped: ...
    @start.setter
    def start(self, value: geometry_msgs.PoseStamped | Mapping[str, Any]) -> None: ...
    @property
    def goal(self) -> geometry_msgs.PoseStamped: ...
    @goal.setter
    def goal(self, value: geometry_msgs.PoseStamped | Mapping[str, Any]) -> None: ...
    tolerance: float
    def __init__(
        self,
        start: geometry_msgs.PoseStamped | Mapping[str, Any] = ...,
        goal: geometry_msgs.PoseStamped | Mapping[str, Any] = ...,
        tolerance: float = ...,
    ) -> None: ...

class GetPlanResponse(Message):
    """``nav_msgs/GetPlanResponse``."""

    @property
    def plan(self) -> Path: ...
    @plan.setter
    def plan(self, value: Path | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        plan: Path | Mapping[str, Any] = ...,
    ) -> None: ...

class GridCells(Message):
    """``nav_msgs/GridCells``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    cell_width: float
    cell_height: float
    @property
    def cells(self) -> list[geometry_msgs.Point]: ...
    @cells.setter
    def cells(self, value: Iterable[geometry_msgs.Point | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        cell_width: float = ...,
        cell_height: float = ...,
        cells: Iterable[geometry_msgs.Point | Mapping[str, Any]] = ...,
    ) -> None: ...

class LoadMapRequest(Message):
    """``nav_msgs/LoadMapRequest``."""

    map_url: str
    def __init__(
        self,
        map_url: str = ...,
    ) -> None: ...

class LoadMapResponse(Message):
    """``nav_msgs/LoadMapResponse``."""

    RESULT_SUCCESS: Final = 0
    RESULT_MAP_DOES_NOT_EXIST: Final = 1
    RESULT_INVALID_MAP_DATA: Final = 2
    RESULT_INVALID_MAP_METADATA: Final = 3
    RESULT_UNDEFINED_FAILURE: Final = 255

    @property
    def map(self) -> OccupancyGrid: ...
    @map.setter
    def map(self, value: OccupancyGrid | Mapping[str, Any]) -> None: ...
    result: int
    def __init__(
        self,
        map: OccupancyGrid | Mapping[str, Any] = ...,
        result: int = ...,
    ) -> None: ...

class MapMetaData(Message):
    """``nav_msgs/MapMetaData``."""

    @property
    def map_load_time(self) -> builtin_interfaces.Time: ...
    @map_load_time.setter
    def map_load_time(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    resolution: float
    width: int
    height: int
    @property
    def origin(self) -> geometry_msgs.Pose: ...
    @origin.setter
    def origin(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        map_load_time: builtin_interfaces.Time | Mapping[str, Any] = ...,
        resolution: float = ...,
        width: int = ...,
        height: int = ...,
        origin: geometry_msgs.Pose | Mapping[str, Any] = ...,
    ) -> None: ...

class OccupancyGrid(Message):
    """``nav_msgs/OccupancyGrid``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def info(self) -> MapMetaData: ...
    @info.setter
    def info(self, value: MapMetaData | Mapping[str, Any]) -> None: ...
    @property
    def data(self) -> NDArray[np.int8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        info: MapMetaData | Mapping[str, Any] = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Odometry(Message):
    """``nav_msgs/Odometry``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    child_frame_id: str
    @property
    def pose(self) -> geometry_msgs.PoseWithCovariance: ...
    @pose.setter
    def pose(self, value: geometry_msgs.PoseWithCovariance | Mapping[str, Any]) -> None: ...
    @property
    def twist(self) -> geometry_msgs.TwistWithCovariance: ...
    @twist.setter
    def twist(self, value: geometry_msgs.TwistWithCovariance | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        child_frame_id: str = ...,
        pose: geometry_msgs.PoseWithCovariance | Mapping[str, Any] = ...,
        twist: geometry_msgs.TwistWithCovariance | Mapping[str, Any] = ...,
    ) -> None: ...

class Path(Message):
    """``nav_msgs/Path``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def poses(self) -> list[geometry_msgs.PoseStamped]: ...
    @poses.setter
    def poses(self, value: Iterable[geometry_msgs.PoseStamped | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        poses: Iterable[geometry_msgs.PoseStamped | Mapping[str, Any]] = ...,
    ) -> None: ...

class SetMapRequest(Message):
    """``nav_msgs/SetMapRequest``."""

    @property
    def map(self) -> OccupancyGrid: ...
    @map.setter
    def map(self, value: OccupancyGrid | Mapping[str, Any]) -> None: ...
    @property
    def initial_pose(self) -> geometry_msgs.PoseWithCovarianceStamped: ...
    @initial_pose.setter
    def initial_pose(
        self, value: geometry_msgs.PoseWithCovarianceStamped | Mapping[str, Any]
    ) -> None: ...
    def __init__(
        self,
        map: OccupancyGrid | Mapping[str, Any] = ...,
        initial_pose: geometry_msgs.PoseWithCovarianceStamped | Mapping[str, Any] = ...,
    ) -> None: ...

class SetMapResponse(Message):
    """``nav_msgs/SetMapResponse``."""

    success: bool
    def __init__(
        self,
        success: bool = ...,
    ) -> None: ...

class GetMap(ServiceType):
    """``nav_msgs/GetMap``: ``GetMap.Request(...)``, ``GetMap.Response(...)``."""

    Request: ClassVar[type[GetMapRequest]]
    Response: ClassVar[type[GetMapResponse]]

class GetPlan(ServiceType):
    """``nav_msgs/GetPlan``: ``GetPlan.Request(...)``, ``GetPlan.Response(...)``."""

    Request: ClassVar[type[GetPlanRequest]]
    Response: ClassVar[type[GetPlanResponse]]

class LoadMap(ServiceType):
    """``nav_msgs/LoadMap``: ``LoadMap.Request(...)``, ``LoadMap.Response(...)``."""

    Request: ClassVar[type[LoadMapRequest]]
    Response: ClassVar[type[LoadMapResponse]]

class SetMap(ServiceType):
    """``nav_msgs/SetMap``: ``SetMap.Request(...)``, ``SetMap.Response(...)``."""

    Request: ClassVar[type[SetMapRequest]]
    Response: ClassVar[type[SetMapResponse]]
