"""tf2's exceptions, with the same names and meanings, rooted at :class:`TransformError`.

The first line of a message is tf2's own text for the same failure; workbench may add
a second line with more detail (the known frames, the link without data).

* :class:`LookupException`: a frame does not exist (or the tree has a loop).
* :class:`ConnectivityException`: both frames exist but are in different trees.
* :class:`ExtrapolationException`: the path exists but not at the requested time
  (before the oldest or after the newest data of some link on the path).
* :class:`InvalidArgumentException`: an empty frame id, a frame id starting with ``/``,
  or a time that is not a time.
* :class:`TimeoutException`: a waiting lookup did not succeed within its timeout.

Refused data (NaN, denormalised quaternion, self transform, empty ids, data older
than the cache) is not an exception in tf2: ``set_transform`` returns ``False`` and
emits a :class:`TransformDataWarning`.
"""

from __future__ import annotations

from typing import Any

from workbench.errors import TransformError


class TransformException(TransformError):
    """Base of tf2's exceptions (``tf2.TransformException``).

    Args:
        message: tf2's text for the failure.
        detail: More detail from workbench, shown on a line of its own after ``message``.

    Attributes:
        tf2_message: ``message`` alone: the text tf2 gives (``can_transform`` reports it).
        detail: The added detail, ``""`` if none.
    """

    def __init__(self, message: str, detail: str = "", **kwargs: Any) -> None:
        self.tf2_message = message
        self.detail = detail
        super().__init__(f"{message}\n{detail}" if detail else message, **kwargs)


class LookupException(TransformException):
    """A frame named in a lookup is unknown, or the tree contains a loop."""


class ConnectivityException(TransformException):
    """The two frames are not part of the same tree."""


class ExtrapolationException(TransformException):
    """A lookup would need data before the oldest or after the newest stored transform."""


class InvalidArgumentException(TransformException):
    """An argument is malformed: empty frame id, a leading ``/``, a bad time."""


class TimeoutException(TransformException):
    """A waiting lookup gave up after its timeout; the message ends with the last reason."""


class TransformDataWarning(UserWarning):
    """Data refused by ``set_transform`` (tf2's TF_NAN_INPUT, TF_OLD_DATA, ...)."""


__all__ = [
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "TimeoutException",
    "TransformDataWarning",
    "TransformException",
]
