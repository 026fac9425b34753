"""Types of the visualization_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, Final

from workbench.msgs import builtin_interfaces, geometry_msgs, std_msgs
from workbench.msgs import visualization_msgs as msg
from workbench.msgs import visualization_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "ImageMarker",
    "InteractiveMarker",
    "InteractiveMarkerControl",
    "InteractiveMarkerFeedback",
    "InteractiveMarkerInit",
    "InteractiveMarkerPose",
    "InteractiveMarkerUpdate",
    "Marker",
    "MarkerArray",
    "MenuEntry",
    "msg",
    "srv",
]

class ImageMarker(Message):
    """``visualization_msgs/ImageMarker``."""

    CIRCLE: Final = 0
    LINE_STRIP: Final = 1
    LINE_LIST: Final = 2
    POLYGON: Final = 3
    POINTS: Final = 4
    ADD: Final = 0
    REMOVE: Final = 1

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    ns: str
    id: int
    type: int
    action: int
    @property
    def position(self) -> geometry_msgs.Point: ...
    @position.setter
    def position(self, value: geometry_msgs.Point | Mapping[str, Any]) -> None: ...
    scale: float
    @property
    def outline_color(self) -> std_msgs.ColorRGBA: ...
    @outline_color.setter
    def outline_color(self, value: std_msgs.ColorRGBA | Mapping[str, Any]) -> None: ...
    filled: int
    @property
    def fill_color(self) -> std_msgs.ColorRGBA: ...
    @fill_color.setter
    def fill_color(self, value: std_msgs.ColorRGBA | Mapping[str, Any]) -> None: ...
    @property
    def lifetime(self) -> builtin_interfaces.Duration: ...
    @lifetime.setter
    def lifetime(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    @property
    def points(self) -> list[geometry_msgs.Point]: ...
    @points.setter
    def points(self, value: Iterable[geometry_msgs.Point | Mapping[str, Any]]) -> None: ...
    @property
    def outline_colors(self) -> list[std_msgs.ColorRGBA]: ...
    @outline_colors.setter
    def outline_colors(self, value: Iterable[std_msgs.ColorRGBA | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        ns: str = ...,
        id: int = ...,
        type: int = ...,
        action: int = ...,
        position: geometry_msgs.Point | Mapping[str, Any] = ...,
        scale: float = ...,
        outline_color: std_msgs.ColorRGBA | Mapping[str, Any] = ...,
        filled: int = ...,
        fill_color: std_msgs.ColorRGBA | Mapping[str, Any] = ...,
        lifetime: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        points: Iterable[geometry_msgs.Point | Mapping[str, Any]] = ...,
        outline_colors: Iterable[std_msgs.ColorRGBA | Mapping[str, Any]] = ...,
    ) -> None: ...

class InteractiveMarker(Message):
    """``visualization_msgs/InteractiveMarker``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    name: str
    description: str
    scale: float
    @property
    def menu_entries(self) -> list[MenuEntry]: ...
    @menu_entries.setter
    def menu_entries(self, value: Iterable[MenuEntry | Mapping[str, Any]]) -> None: ...
    @property
    def controls(self) -> list[InteractiveMarkerControl]: ...
    @controls.setter
    def controls(self, value: Iterable[InteractiveMarkerControl | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        name: str = ...,
        description: str = ...,
        scale: float = ...,
        menu_entries: Iterable[MenuEntry | Mapping[str, Any]] = ...,
        controls: Iterable[InteractiveMarkerControl | Mapping[str, Any]] = ...,
    ) -> None: ...

class InteractiveMarkerControl(Message):
    """``visualization_msgs/InteractiveMarkerControl``."""

    INHERIT: Final = 0
    FIXED: Final = 1
    VIEW_FACING: Final = 2
    NONE: Final = 0
    MENU: Final = 1
    BUTTON: Final = 2
    MOVE_AXIS: Final = 3
    MOVE_PLANE: Final = 4
    ROTATE_AXIS: Final = 5
    MOVE_ROTATE: Final = 6
    MOVE_3D: Final = 7
    ROTATE_3D: Final = 8
    MOVE_ROTATE_3D: Final = 9

    name: str
    @property
    def orientation(self) -> geometry_msgs.Quaternion: ...
    @orientation.setter
    def orientation(self, value: geometry_msgs.Quaternion | Mapping[str, Any]) -> None: ...
    orientation_mode: int
    interaction_mode: int
    always_visible: bool
    @property
    def markers(self) -> list[Marker]: ...
    @markers.setter
    def markers(self, value: Iterable[Marker | Mapping[str, Any]]) -> None: ...
    independent_marker_orientation: bool
    description: str
    def __init__(
        self,
        name: str = ...,
        orientation: geometry_msgs.Quaternion | Mapping[str, Any] = ...,
        orientation_mode: int = ...,
        interaction_mode: int = ...,
        always_visible: bool = ...,
        markers: Iterable[Marker | Mapping[str, Any]] = ...,
        independent_marker_orientation: bool = ...,
        description: str = ...,
    ) -> None: ...

class InteractiveMarkerFeedback(Message):
    """``visualization_msgs/InteractiveMarkerFeedback``."""

    KEEP_ALIVE: Final = 0
    POSE_UPDATE: Final = 1
    MENU_SELECT: Final = 2
    BUTTON_CLICK: Final = 3
    MOUSE_DOWN: Final = 4
    MOUSE_UP: Final = 5

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    client_id: str
    marker_name: str
    control_name: str
    event_type: int
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    menu_entry_id: int
    @property
    def mouse_point(self) -> geometry_msgs.Point: ...
    @mouse_point.setter
    def mouse_point(self, value: geometry_msgs.Point | Mapping[str, Any]) -> None: ...
    mouse_point_valid: bool
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        client_id: str = ...,
        marker_name: str = ...,
        control_name: str = ...,
        event_type: int = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        menu_entry_id: int = ...,
        mouse_point: geometry_msgs.Point | Mapping[str, Any] = ...,
        mouse_point_valid: bool = ...,
    ) -> None: ...

class InteractiveMarkerInit(Message):
    """``visualization_msgs/InteractiveMarkerInit``."""

    server_id: str
    seq_num: int
    @property
    def markers(self) -> list[InteractiveMarker]: ...
    @markers.setter
    def markers(self, value: Iterable[InteractiveMarker | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        server_id: str = ...,
        seq_num: int = ...,
        markers: Iterable[InteractiveMarker | Mapping[str, Any]] = ...,
    ) -> None: ...

class InteractiveMarkerPose(Message):
    """``visualization_msgs/InteractiveMarkerPose``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    name: str
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        name: str = ...,
    ) -> None: ...

class InteractiveMarkerUpdate(Message):
    """``visualization_msgs/InteractiveMarkerUpdate``."""

    KEEP_ALIVE: Final = 0
    UPDATE: Final = 1

    server_id: str
    seq_num: int
    type: int
    @property
    def markers(self) -> list[InteractiveMarker]: ...
    @markers.setter
    def markers(self, value: Iterable[InteractiveMarker | Mapping[str, Any]]) -> None: ...
    @property
    def poses(self) -> list[InteractiveMarkerPose]: ...
    @poses.setter
    def poses(self, value: Iterable[InteractiveMarkerPose | Mapping[str, Any]]) -> None: ...
    @property
    def erases(self) -> list[str]: ...
    @erases.setter
    def erases(self, value: Iterable[str]) -> None: ...
    def __init__(
        self,
        server_id: str = ...,
        seq_num: int = ...,
        type: int = ...,
        markers: Iterable[InteractiveMarker | Mapping[str, Any]] = ...,
        poses: Iterable[InteractiveMarkerPose | Mapping[str, Any]] = ...,
        erases: Iterable[str] = ...,
    ) -> None: ...

class Marker(Message):
    """``visualization_msgs/Marker``."""

    ARROW: Final = 0
    CUBE: Final = 1
    SPHERE: Final = 2
    CYLINDER: Final = 3
    LINE_STRIP: Final = 4
    LINE_LIST: Final = 5
    CUBE_LIST: Final = 6
    SPHERE_LIST: Final = 7
    POINTS: Final = 8
    TEXT_VIEW_FACING: Final = 9
    MESH_RESOURCE: Final = 10
    TRIANGLE_LIST: Final = 11
    ADD: Final = 0
    MODIFY: Final = 0
    DELETE: Final = 2
    DELETEALL: Final = 3

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    ns: str
    id: int
    type: int
    action: int
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    @property
    def scale(self) -> geometry_msgs.Vector3: ...
    @scale.setter
    def scale(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def color(self) -> std_msgs.ColorRGBA: ...
    @color.setter
    def color(self, value: std_msgs.ColorRGBA | Mapping[str, Any]) -> None: ...
    @property
    def lifetime(self) -> builtin_interfaces.Duration: ...
    @lifetime.setter
    def lifetime(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    frame_locked: bool
    @property
    def points(self) -> list[geometry_msgs.Point]: ...
    @points.setter
    def points(self, value: Iterable[geometry_msgs.Point | Mapping[str, Any]]) -> None: ...
    @property
    def colors(self) -> list[std_msgs.ColorRGBA]: ...
    @colors.setter
    def colors(self, value: Iterable[std_msgs.ColorRGBA | Mapping[str, Any]]) -> None: ...
    text: str
    mesh_resource: str
    mesh_use_embedded_materials: bool
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        ns: str = ...,
        id: int = ...,
        type: int = ...,
        action: int = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        scale: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        color: std_msgs.ColorRGBA | Mapping[str, Any] = ...,
        lifetime: builtin_interfaces.Duration | Mapping[str, Any] = ...,
        frame_locked: bool = ...,
        points: Iterable[geometry_msgs.Point | Mapping[str, Any]] = ...,
        colors: Iterable[std_msgs.ColorRGBA | Mapping[str, Any]] = ...,
        text: str = ...,
        mesh_resource: str = ...,
        mesh_use_embedded_materials: bool = ...,
    ) -> None: ...

class MarkerArray(Message):
    """``visualization_msgs/MarkerArray``."""

    @property
    def markers(self) -> list[Marker]: ...
    @markers.setter
    def markers(self, value: Iterable[Marker | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        markers: Iterable[Marker | Mapping[str, Any]] = ...,
    ) -> None: ...

class MenuEntry(Message):
    """``visualization_msgs/MenuEntry``."""

    FEEDBACK: Final = 0
    ROSRUN: Final = 1
    ROSLAUNCH: Final = 2

    id: int
    parent_id: int
    title: str
    command: str
    command_type: int
    def __init__(
        self,
        id: int = ...,
        parent_id: int = ...,
        title: str = ...,
        command: str = ...,
        command_type: int = ...,
    ) -> None: ...
