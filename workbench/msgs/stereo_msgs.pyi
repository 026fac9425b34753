"""Types of the stereo_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Mapping
from typing import Any

from workbench.msgs import sensor_msgs, std_msgs
from workbench.msgs import stereo_msgs as msg
from workbench.msgs import stereo_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "DisparityImage",
    "msg",
    "srv",
]

class DisparityImage(Message):
    """``stereo_msgs/DisparityImage``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def image(self) -> sensor_msgs.Image: ...
    @image.setter
    def image(self, value: sensor_msgs.Image | Mapping[str, Any]) -> None: ...
    f: float
    T: float
    @property
    def valid_window(self) -> sensor_msgs.RegionOfInterest: ...
    @valid_window.setter
    def valid_window(self, value: sensor_msgs.RegionOfInterest | Mapping[str, Any]) -> None: ...
    min_disparity: float
    max_disparity: float
    delta_d: float
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        image: sensor_msgs.Image | Mapping[str, Any] = ...,
        f: float = ...,
        T: float = ...,
        valid_window: sensor_msgs.RegionOfInterest | Mapping[str, Any] = ...,
        min_disparity: float = ...,
        max_disparity: float = ...,
        delta_d: float = ...,
    ) -> None: ...
