"""What every Gazebo ROS plugin shares: its namespace, ``tf_prefix`` and ``<parameter>`` reading.

This is gazebo_plugins' ``GazeboRos`` helper (``gazebo_ros_utils.h``, noetic):

* The namespace is ``<robotNamespace>``, or the model's name when the element is
  missing or empty; topics are relative to it (``cmd_vel`` of model ``bot`` is
  ``/bot/cmd_vel``). A spawn request's ``robot_namespace`` fills in
  ``<robotNamespace>`` (see :mod:`.robot_namespace`); ``spawn_model`` sends ``/``,
  so a spawned robot's topics are global (``/cmd_vel``). Some plugins default to
  the empty namespace instead (``planar_move``): they pass ``default_namespace``.
* Frames are resolved with ``tf::resolve(tf_prefix, frame)``: a name with a
  leading ``/`` loses it, otherwise the ``tf_prefix`` parameter (searched upward
  from the namespace, usually unset) is put in front.
* A missing parameter takes its default (Gazebo prints a warning for each; here
  they are logged at debug level); a boolean is ``true``/``1`` or
  ``false``/``0``, anything else keeps the default with a warning.
* ``<rosDebugLevel>`` (``Debug``, ``Info``, ``Warn``, ``Error``, ``Fatal``) sets
  the level of these plugins' log messages.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from typing import Any, TypeVar

from workbench.errors import SimulationError

_LOG = logging.getLogger("workbench.sim.gazebo_ros_plugins")

_LEVELS = {
    "debug": logging.DEBUG,
    "info": logging.INFO,
    "warn": logging.WARNING,
    "error": logging.ERROR,
    "fatal": logging.CRITICAL,
}

T = TypeVar("T")


class PluginRos:
    """A plugin's ROS side: namespace, frames and parameters.

    Args:
        plugin: The plugin's class name in Gazebo's messages (``DiffDrive``).
        sdf: The ``<plugin>`` element (:class:`workbench.sim.plugins.SdfElement`).
        model: The model's name (the default namespace).
        node: The plugin's bus node (None: nothing is published).
        default_namespace: The namespace without ``<robotNamespace>``; None: ``model``.
    """

    def __init__(
        self,
        plugin: str,
        sdf: Any,
        model: str,
        node: Any,
        default_namespace: str | None = None,
    ) -> None:
        self.sdf = sdf
        self.node = node
        self.model = model
        fallback = model if default_namespace is None else default_namespace
        written = self.text("robotNamespace")
        self.namespace = global_namespace(written if written else fallback)
        self.info = f"{plugin}(ns = {self.namespace})"
        level = self.text("rosDebugLevel")
        if level is not None and level.lower() in _LEVELS:
            _LOG.setLevel(_LEVELS[level.lower()])
            _LOG.info("%s: <rosDebugLevel> = %s", self.info, level)
        self.tf_prefix = self._tf_prefix()

    # --- names -----------------------------------------------------------------------

    def topic(self, name: str) -> str:
        """A topic name resolved against the namespace (a global name stays as it is)."""
        if name.startswith("/"):
            return "/" + name.strip("/")
        return self.namespace.rstrip("/") + "/" + name.strip("/")

    def frame(self, name: str) -> str:
        """``tf::resolve(tf_prefix, name)``."""
        return resolve_frame(self.tf_prefix, name)

    def _tf_prefix(self) -> str:
        if self.node is None:
            return ""
        params = self.node.bus.params
        found = params.search(self.namespace, "tf_prefix")
        if not found:
            return ""
        value = params.get(found)
        return value if isinstance(value, str) else ""

    # --- parameters --------------------------------------------------------------------

    def text(self, tag: str) -> str | None:
        """The element ``tag``'s text (stripped), or None when it is missing."""
        child = self.sdf.element.find(tag)
        if child is None:
            return None
        return (child.text or "").strip()

    def string(self, tag: str, default: str) -> str:
        """A text parameter."""
        value = self.text(tag)
        if value is None:
            _LOG.debug("%s: missing <%s> default is %s", self.info, tag, default)
            return default
        return value

    def number(self, tag: str, default: float) -> float:
        """A number parameter.

        Raises:
            SimulationError: The text is not a number (the model and plugin are named).
        """
        value = self.text(tag)
        if value is None:
            _LOG.debug("%s: missing <%s> default is %s", self.info, tag, default)
            return float(default)
        try:
            return float(value)
        except ValueError:
            raise SimulationError(
                f"model '{self.model}': plugin '{self.sdf.name}': <{tag}> must be a number, "
                f"got '{value}'"
            ) from None

    def boolean(self, tag: str, default: bool) -> bool:
        """A boolean parameter: ``true``/``1`` or ``false``/``0`` (any case)."""
        value = self.text(tag)
        if value is None:
            _LOG.debug("%s: missing <%s> default is %s", self.info, tag, default)
            return default
        if value.lower() in ("true", "1"):
            return True
        if value.lower() in ("false", "0"):
            return False
        _LOG.warning("%s: <%s> must be either true or false but is '%s'", self.info, tag, value)
        return default

    def choice(self, tag: str, options: Mapping[str, T], default: T) -> T:
        """A parameter that must be one of ``options``' keys (else the default, with a warning)."""
        value = self.text(tag)
        if value is None:
            _LOG.debug("%s: missing <%s> default is %s", self.info, tag, default)
            return default
        if value not in options:
            _LOG.warning("%s: <%s> no matching key to %s", self.info, tag, value)
            return default
        return options[value]


def global_namespace(namespace: str) -> str:
    """``bot`` -> ``/bot``; ``/`` or ``//`` -> ``/``; ``/a//b/`` -> ``/a/b``."""
    parts = [part for part in namespace.split("/") if part]
    return "/" + "/".join(parts)


def resolve_frame(prefix: str, frame: str) -> str:
    """tf's ``resolve(prefix, frame)``: ``/odom`` -> ``odom``; ``(r1, odom)`` -> ``r1/odom``."""
    if frame.startswith("/"):
        return frame[1:]
    if prefix:
        return prefix.lstrip("/") + "/" + frame
    return frame


def ros_stamp(seconds: float) -> Any:
    """A ``time`` for a header: ``seconds`` of simulated time (Gazebo's ``ros::Time::now()``)."""
    from workbench.msgs import Time

    nanos = int(round(seconds * 1e9))
    return Time(nanos // 1_000_000_000, nanos % 1_000_000_000)
