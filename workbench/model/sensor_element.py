"""A ``<sensor>`` element for :class:`workbench.model.ModelBuilder` (SDF, or URDF ``<gazebo>``).

A sensor's type-specific settings are nested mappings written as elements, in
the order given::

    SensorElement("camera", "depth", settings={
        "camera": {"horizontal_fov": 1.047, "image": {"width": 320, "height": 240}},
    })

writes ``<sensor name="camera" type="depth"><camera><horizontal_fov>1.047</horizontal_fov>
<image><width>320</width>...``. Values are numbers, booleans (``true``/``false``),
text, or sequences of numbers (space-separated, as SDF vectors).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any
from xml.sax.saxutils import quoteattr

from workbench.errors import ModelError

#: Sensor types SDF knows (workbench simulates ray, gpu_ray, camera, depth and imu).
SENSOR_TYPES = (
    "altimeter",
    "camera",
    "contact",
    "depth",
    "force_torque",
    "gps",
    "gpu_ray",
    "imu",
    "logical_camera",
    "magnetometer",
    "multicamera",
    "ray",
    "rfid",
    "rfidtag",
    "sonar",
    "wireless_receiver",
    "wireless_transmitter",
)


@dataclass
class SensorElement:
    """One sensor: name, type, pose in its link, the common elements and the type's settings."""

    name: str
    kind: str
    pose: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    update_rate: float = 0.0
    always_on: bool = False
    visualize: bool = False
    settings: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in SENSOR_TYPES:
            raise ModelError(
                f"sensor '{self.name}': unknown type '{self.kind}'",
                hint="one of " + ", ".join(SENSOR_TYPES),
            )
        if not (math.isfinite(self.update_rate) and self.update_rate >= 0):
            raise ModelError(f"sensor '{self.name}': update_rate must be >= 0 Hz")
        _lines(self.settings, 0, f"sensor '{self.name}'")  # checks the values now

    def lines(self, indent: int, pose: Sequence[float] | None = None) -> list[str]:
        """The element as lines indented by ``indent`` spaces (``pose``: written instead of
        the sensor's own, e.g. moved into another frame)."""
        pad = " " * indent
        where = f"sensor '{self.name}'"
        out = [f"{pad}<sensor name={quoteattr(self.name)} type={quoteattr(self.kind)}>"]
        out.append(
            f"{pad}  <pose>{_text(tuple(pose if pose is not None else self.pose), where)}</pose>"
        )
        out += _lines(self.settings, indent + 2, where)
        out.append(f"{pad}  <always_on>{_text(self.always_on, where)}</always_on>")
        out.append(f"{pad}  <update_rate>{_text(self.update_rate, where)}</update_rate>")
        out.append(f"{pad}  <visualize>{_text(self.visualize, where)}</visualize>")
        out.append(f"{pad}</sensor>")
        return out


def _lines(settings: Mapping[str, Any], indent: int, where: str) -> list[str]:
    pad = " " * indent
    out = []
    for key, value in settings.items():
        if not key or any(c in key for c in "<>&\"' \t\n/"):
            raise ModelError(f"{where}: {key!r} is not an element name")
        if isinstance(value, Mapping):
            out.append(f"{pad}<{key}>")
            out += _lines(value, indent + 2, f"{where} <{key}>")
            out.append(f"{pad}</{key}>")
        else:
            out.append(f"{pad}<{key}>{_text(value, f'{where} <{key}>')}</{key}>")
    return out


def _text(value: Any, where: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            raise ModelError(f"{where}: {value} is not a finite number")
        return f"{0.0 if abs(value) < 1e-12 else value:.9g}"
    if isinstance(value, str):
        if any(c in value for c in "<>&"):
            raise ModelError(f"{where}: {value!r} has characters XML text cannot hold")
        return value
    if isinstance(value, Sequence):
        return " ".join(_text(v, where) for v in value)
    raise ModelError(f"{where}: cannot write {type(value).__name__} {value!r}")
