"""Sensor descriptions read from SDF ``<sensor>`` elements (also those in URDF ``<gazebo>`` blocks).

:func:`parse_sensor` turns one ``<sensor>`` into a :class:`LaserSpec` (``ray``,
``gpu_ray``), :class:`CameraSpec` (``camera``, ``depth``) or :class:`ImuSpec`
(``imu``), with SDFormat's defaults for what is left out. A value that makes no
sense (a negative range, zero samples, ``min_angle > max_angle``, text where a
number belongs) raises one :class:`~workbench.errors.SimulationError` line that
names the model, the link, the sensor and the element, e.g.::

    model 'bot', link 'laser_scanner', sensor 'laser': <ray><range><min> must be a
    number >= 0, got '-1'

Units: m, rad, Hz. ``X_LS`` is the sensor frame S in its link L (the sensor's
``<pose>``); a laser's beams leave S's origin, a camera looks along S's +x with
+z up (Gazebo's convention).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from lxml import etree

from workbench.errors import SimulationError

LASER_TYPES = ("ray", "gpu_ray")
CAMERA_TYPES = ("camera", "depth")
IMU_TYPES = ("imu",)
CONTACT_TYPES = ("contact",)

#: Image formats of SDF's ``<image><format>`` workbench renders, and their ROS encodings.
IMAGE_ENCODINGS = {
    "R8G8B8": "rgb8",
    "RGB_INT8": "rgb8",
    "B8G8R8": "bgr8",
    "BGR_INT8": "bgr8",
    "L8": "mono8",
    "L_INT8": "mono8",
}


@dataclass(frozen=True)
class NoiseSpec:
    """Gaussian noise: ``value + N(mean, stddev)`` (plus a bias drawn once, IMU only)."""

    mean: float = 0.0
    stddev: float = 0.0
    bias_mean: float = 0.0
    bias_stddev: float = 0.0


@dataclass(frozen=True)
class ScanAxis:
    """One axis of a laser scan: ``samples`` beams from ``min_angle`` to ``max_angle``."""

    samples: int = 1
    resolution: float = 1.0
    min_angle: float = 0.0
    max_angle: float = 0.0

    @property
    def count(self) -> int:
        """Readings on this axis: ``samples * resolution`` (Gazebo's range count)."""
        return max(1, int(round(self.samples * self.resolution)))

    def angles(self) -> np.ndarray:
        """The readings' angles, rad: evenly from min to max (one reading: angle 0, as Gazebo)."""
        n = self.count
        if n == 1:
            return np.zeros(1)
        return self.min_angle + np.arange(n) * (self.max_angle - self.min_angle) / (n - 1)


@dataclass(frozen=True)
class SensorSpec:
    """What every sensor has.

    Attributes:
        name: The ``name`` attribute.
        type: The ``type`` attribute (``ray``, ``gpu_ray``, ``camera``, ``depth``, ``imu``).
        model: The model's name (for messages).
        link: The link the sensor is fixed to.
        X_LS: Pose of the sensor in the link, a ``(x, y, z, roll, pitch, yaw)`` tuple.
        update_rate: Measurements per second of simulated time (0: every step).
        always_on: SDF's ``<always_on>``.
        visualize: SDF's ``<visualize>`` (the live view may draw the sensor).
        topic: SDF's ``<topic>`` (Gazebo's own transport; unused by the ROS plugins).
        xml: The ``<sensor>`` element as text.
    """

    name: str
    type: str
    model: str
    link: str
    X_LS: tuple[float, float, float, float, float, float] = (0.0,) * 6
    update_rate: float = 0.0
    always_on: bool = False
    visualize: bool = False
    topic: str = ""
    xml: str = field(default="", repr=False, compare=False)

    def pose(self) -> Any:
        """``X_LS`` as a pydrake RigidTransform."""
        from workbench.spatial import rigid_transform

        return rigid_transform(list(self.X_LS[:3]), rpy=list(self.X_LS[3:]))


@dataclass(frozen=True)
class LaserSpec(SensorSpec):
    """A ``ray`` or ``gpu_ray`` sensor (SDF ``<ray>``); defaults are SDFormat's."""

    horizontal: ScanAxis = ScanAxis(samples=640)
    vertical: ScanAxis = ScanAxis()
    range_min: float = 0.0
    range_max: float = 0.0
    range_resolution: float = 0.0
    noise: NoiseSpec | None = None

    @property
    def count(self) -> int:
        """Readings per scan: horizontal count times vertical count."""
        return self.horizontal.count * self.vertical.count


@dataclass(frozen=True)
class CameraSpec(SensorSpec):
    """A ``camera`` or ``depth`` sensor (SDF ``<camera>``); defaults are SDFormat's."""

    horizontal_fov: float = 1.047
    width: int = 320
    height: int = 240
    format: str = "R8G8B8"
    near: float = 0.1
    far: float = 100.0
    noise: NoiseSpec | None = None

    @property
    def focal_length(self) -> float:
        """Focal length in pixels, ``width / (2 tan(hfov / 2))`` (square pixels)."""
        return self.width / (2.0 * math.tan(self.horizontal_fov / 2.0))

    @property
    def encoding(self) -> str:
        """The ROS image encoding of ``format``."""
        return IMAGE_ENCODINGS[self.format]


@dataclass(frozen=True)
class ImuSpec(SensorSpec):
    """An ``imu`` sensor (SDF ``<imu>``): noise of the gyroscope and accelerometer axes."""

    angular_velocity_noise: tuple[NoiseSpec | None, NoiseSpec | None, NoiseSpec | None] = (
        None,
        None,
        None,
    )
    linear_acceleration_noise: tuple[NoiseSpec | None, NoiseSpec | None, NoiseSpec | None] = (
        None,
        None,
        None,
    )


@dataclass(frozen=True)
class ContactSpec(SensorSpec):
    """A ``contact`` sensor (SDF ``<contact>``): the collisions of its link it watches."""

    collisions: tuple[str, ...] = ()


def parse_sensor(xml: str | Any, *, model: str, link: str) -> SensorSpec:
    """The spec of one ``<sensor>`` element (XML text or an lxml element).

    Raises:
        SimulationError: A bad value or an unsupported type, in one line naming the
            model, link, sensor and element.
    """
    element = etree.fromstring(xml.encode()) if isinstance(xml, str) else xml
    reader = _Reader(element, model, link)
    kind = reader.type
    common = reader.common()
    if kind in LASER_TYPES:
        return _laser(reader, common)
    if kind in CAMERA_TYPES:
        return _camera(reader, common)
    if kind in IMU_TYPES:
        return _imu(reader, common)
    if kind in CONTACT_TYPES:
        return _contact(reader, common)
    simulated = LASER_TYPES + CAMERA_TYPES + IMU_TYPES + CONTACT_TYPES
    raise reader.error("type", f"is '{kind}'; workbench simulates {', '.join(simulated)}")


def _contact(reader: _Reader, common: dict[str, Any]) -> ContactSpec:
    contact = reader.find("contact")
    if contact is None:
        raise reader.error("contact", "is missing")
    names = tuple((c.text or "").strip() for c in contact.findall("collision"))
    if not names or not all(names):
        raise reader.error("contact/collision", "must name a collision of the link")
    return ContactSpec(**common, collisions=names)


def _laser(reader: _Reader, common: dict[str, Any]) -> LaserSpec:
    if reader.find("ray") is None:
        raise reader.error("ray", "is missing")
    axes = {}
    for axis in ("horizontal", "vertical"):
        base = f"ray/scan/{axis}"
        samples = reader.integer(f"{base}/samples", 640 if axis == "horizontal" else 1, minimum=1)
        resolution = reader.number(f"{base}/resolution", 1.0, positive=True)
        low = reader.number(f"{base}/min_angle", 0.0)
        high = reader.number(f"{base}/max_angle", 0.0)
        if low > high:
            raise reader.error(
                f"{base}/min_angle", f"({low:g}) must not be greater than <max_angle> ({high:g})"
            )
        if samples * resolution < 0.5:
            raise reader.error(f"{base}/resolution", "gives no reading (samples x resolution < 1)")
        axes[axis] = ScanAxis(samples, resolution, low, high)
    range_min = reader.number("ray/range/min", 0.0, minimum=0.0)
    range_max = reader.number("ray/range/max", None, positive=True)
    if range_max <= range_min:
        raise reader.error(
            "ray/range/max", f"({range_max:g}) must be greater than <min> ({range_min:g})"
        )
    return LaserSpec(
        **common,
        horizontal=axes["horizontal"],
        vertical=axes["vertical"],
        range_min=range_min,
        range_max=range_max,
        range_resolution=reader.number("ray/range/resolution", 0.0, minimum=0.0),
        noise=reader.noise("ray/noise"),
    )


def _camera(reader: _Reader, common: dict[str, Any]) -> CameraSpec:
    if reader.find("camera") is None:
        raise reader.error("camera", "is missing")
    fov = reader.number("camera/horizontal_fov", 1.047, positive=True)
    if fov >= math.pi:
        raise reader.error("camera/horizontal_fov", f"must be less than pi, got {fov:g}")
    image_format = reader.text("camera/image/format", "R8G8B8")
    if image_format not in IMAGE_ENCODINGS:
        raise reader.error(
            "camera/image/format",
            f"is '{image_format}'; workbench renders {', '.join(IMAGE_ENCODINGS)}",
        )
    near = reader.number("camera/clip/near", 0.1, positive=True)
    far = reader.number("camera/clip/far", 100.0, positive=True)
    if far <= near:
        raise reader.error("camera/clip/far", f"({far:g}) must be greater than <near> ({near:g})")
    return CameraSpec(
        **common,
        horizontal_fov=fov,
        width=reader.integer("camera/image/width", 320, minimum=1),
        height=reader.integer("camera/image/height", 240, minimum=1),
        format=image_format,
        near=near,
        far=far,
        noise=reader.noise("camera/noise"),
    )


def _imu(reader: _Reader, common: dict[str, Any]) -> ImuSpec:
    rate: list[NoiseSpec | None] = [None, None, None]
    accel: list[NoiseSpec | None] = [None, None, None]
    legacy_rate = reader.noise("imu/noise/rate", typed_by="imu/noise/type")
    legacy_accel = reader.noise("imu/noise/accel", typed_by="imu/noise/type")
    for i, axis in enumerate("xyz"):
        rate[i] = reader.noise(f"imu/angular_velocity/{axis}/noise") or legacy_rate
        accel[i] = reader.noise(f"imu/linear_acceleration/{axis}/noise") or legacy_accel
    return ImuSpec(
        **common,
        angular_velocity_noise=(rate[0], rate[1], rate[2]),
        linear_acceleration_noise=(accel[0], accel[1], accel[2]),
    )


class _Reader:
    """Reads children of one ``<sensor>``; every error names model, link, sensor and element."""

    def __init__(self, element: Any, model: str, link: str) -> None:
        if element.tag != "sensor":
            raise SimulationError(
                f"model '{model}', link '{link}': expected a <sensor>, got <{element.tag}>"
            )
        self.element = element
        self.model = model
        self.link = link
        self.name = str(element.get("name", ""))
        self.type = str(element.get("type", "")).strip()
        if not self.name:
            raise self.error("name", "is missing (the name attribute)")

    def error(self, path: str, problem: str) -> SimulationError:
        tags = "".join(f"<{part}>" for part in path.split("/"))
        return SimulationError(
            f"model '{self.model}', link '{self.link}', sensor '{self.name}': {tags} {problem}"
        )

    def find(self, path: str) -> Any:
        return self.element.find(path)

    def text(self, path: str, default: str) -> str:
        child = self.element.find(path)
        if child is None or child.text is None or not child.text.strip():
            return default
        return str(child.text.strip())

    def number(
        self,
        path: str,
        default: float | None,
        *,
        minimum: float | None = None,
        positive: bool = False,
    ) -> float:
        child = self.element.find(path)
        text = (child.text or "").strip() if child is not None else ""
        if not text:
            if default is None:
                raise self.error(path, "is missing")
            return default
        try:
            value = float(text)
        except ValueError:
            raise self.error(path, f"must be a number, got '{text}'") from None
        if not math.isfinite(value):
            raise self.error(path, f"must be a finite number, got '{text}'")
        if positive and not value > 0:
            raise self.error(path, f"must be a number > 0, got '{text}'")
        if minimum is not None and value < minimum:
            raise self.error(path, f"must be a number >= {minimum:g}, got '{text}'")
        return value

    def integer(self, path: str, default: int, *, minimum: int) -> int:
        value = self.number(path, float(default))
        if value != int(value) or value < minimum:
            text = (self.element.findtext(path) or "").strip()
            raise self.error(path, f"must be a whole number >= {minimum}, got '{text}'")
        return int(value)

    def truth(self, path: str, default: bool) -> bool:
        text = self.text(path, "").lower()
        if not text:
            return default
        if text in ("1", "true"):
            return True
        if text in ("0", "false"):
            return False
        raise self.error(path, f"must be true or false, got '{text}'")

    def pose(self) -> tuple[float, float, float, float, float, float]:
        text = self.text("pose", "")
        if not text:
            return (0.0,) * 6
        try:
            values = [float(v) for v in text.split()]
        except ValueError:
            values = []
        if len(values) != 6 or not all(math.isfinite(v) for v in values):
            raise self.error("pose", f"must be six numbers 'x y z roll pitch yaw', got '{text}'")
        return (values[0], values[1], values[2], values[3], values[4], values[5])

    def common(self) -> dict[str, Any]:
        from workbench.sim.model_spec import element_text

        return {
            "name": self.name,
            "type": self.type,
            "model": self.model,
            "link": self.link,
            "X_LS": self.pose(),
            "update_rate": self.number("update_rate", 0.0, minimum=0.0),
            "always_on": self.truth("always_on", False),
            "visualize": self.truth("visualize", False),
            "topic": self.text("topic", ""),
            "xml": element_text(self.element),
        }

    def noise(self, path: str, typed_by: str | None = None) -> NoiseSpec | None:
        """``<noise>`` at ``path``: None when absent or of type none; gaussian read fully."""
        element = self.element.find(path)
        if element is None:
            return None
        type_path = typed_by or f"{path}/type"
        kind = self.text(type_path, "").lower() or str(element.get("type", "")).lower()
        if kind in ("", "none"):
            return None
        if kind not in ("gaussian", "gaussian_quantized"):
            raise self.error(type_path, f"is '{kind}'; workbench simulates gaussian noise")
        noise = NoiseSpec(
            mean=self.number(f"{path}/mean", 0.0),
            stddev=self.number(f"{path}/stddev", 0.0, minimum=0.0),
            bias_mean=self.number(f"{path}/bias_mean", 0.0),
            bias_stddev=self.number(f"{path}/bias_stddev", 0.0, minimum=0.0),
        )
        return (
            noise if (noise.stddev or noise.mean or noise.bias_mean or noise.bias_stddev) else None
        )
