"""Types of the tf2_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any

from workbench.msgs import geometry_msgs
from workbench.msgs import tf2_msgs as msg
from workbench.msgs import tf2_msgs as srv
from workbench.msgs._classes import Message

__all__ = [
    "TFMessage",
    "msg",
    "srv",
]

class TFMessage(Message):
    """``tf2_msgs/TFMessage``."""

    @property
    def transforms(self) -> list[geometry_msgs.TransformStamped]: ...
    @transforms.setter
    def transforms(
        self, value: Iterable[geometry_msgs.TransformStamped | Mapping[str, Any]]
    ) -> None: ...
    def __init__(
        self,
        transforms: Iterable[geometry_msgs.TransformStamped | Mapping[str, Any]] = ...,
    ) -> None: ...
