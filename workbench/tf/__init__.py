"""Frames over time: tf2's buffer, broadcasters and listeners (numpy/scipy only).

::

    from workbench.tf import Buffer, TransformListener, TransformBroadcaster
    buffer = Buffer()
    listener = TransformListener(buffer, node)     # fills it from /tf and /tf_static
    t = buffer.lookup_transform("turtle2", "turtle1", 0, timeout=1.0)

``Buffer`` and the exceptions import nothing beyond numpy; the bus-facing
classes are imported on first use.
"""

from __future__ import annotations

from typing import Any

from workbench.tf.buffer import Buffer
from workbench.tf.core import BufferCore, StampedTransform
from workbench.tf.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformDataWarning,
    TransformException,
)

_LAZY = {
    "TransformBroadcaster": "workbench.tf.broadcaster",
    "StaticTransformBroadcaster": "workbench.tf.broadcaster",
    "TransformListener": "workbench.tf.listener",
}

__all__ = [
    "Buffer",
    "BufferCore",
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "StampedTransform",
    "StaticTransformBroadcaster",
    "TimeoutException",
    "TransformBroadcaster",
    "TransformDataWarning",
    "TransformException",
    "TransformListener",
]


def __getattr__(name: str) -> Any:
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'workbench.tf' has no attribute '{name}'")
    import importlib

    return getattr(importlib.import_module(module), name)
