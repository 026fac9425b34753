"""sensor_msgs messages of sensor readings, filled as gazebo_plugins (noetic) fills them."""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.sensors.spec import CameraSpec, LaserSpec


def stamp(seconds: float) -> Any:
    """A ROS time of simulated ``seconds``."""
    from workbench.msgs import Time

    nanos = int(round(seconds * 1e9))
    return Time(nanos // 1_000_000_000, nanos % 1_000_000_000)


def resolve_topic(namespace: str, name: str) -> str:
    """``name`` under ``namespace`` as a ROS NodeHandle resolves it (absolute names stay)."""
    if name.startswith("/"):
        return name
    parts = [p for p in namespace.split("/") if p] + [p for p in name.split("/") if p]
    return "/" + "/".join(parts)


def tf_frame(name: str) -> str:
    """A frame name as noetic's ``tf::resolve`` with no tf_prefix gives it: no leading slash."""
    return name.lstrip("/")


def laser_scan(spec: LaserSpec, ranges: np.ndarray, frame: str, seconds: float) -> Any:
    """``sensor_msgs/LaserScan`` of one scan, as gazebo_ros_laser / gpu_laser fill it.

    ``angle_increment`` is ``(max - min) / (count - 1)``; ``time_increment`` and
    ``scan_time`` are 0 (an instantaneous simulated scan); ``intensities`` are 0
    (no ``<laser_retro>``); a scan with vertical rows has them all in ``ranges``.
    """
    from workbench.msgs.sensor_msgs import LaserScan

    count = spec.horizontal.count
    h = spec.horizontal
    msg = LaserScan()
    msg.header.stamp = stamp(seconds)
    msg.header.frame_id = frame
    msg.angle_min = h.min_angle
    msg.angle_max = h.max_angle
    msg.angle_increment = 0.0 if count < 2 else (h.max_angle - h.min_angle) / (count - 1)
    msg.time_increment = 0.0
    msg.scan_time = 0.0
    msg.range_min = spec.range_min
    msg.range_max = spec.range_max
    msg.ranges = np.asarray(ranges, dtype=np.float32)
    msg.intensities = np.zeros(len(ranges), dtype=np.float32)
    return msg


def image(array: np.ndarray, encoding: str, frame: str, seconds: float) -> Any:
    """``sensor_msgs/Image`` of an (H, W[, C]) array (uint8 or float32), little endian."""
    from workbench.msgs.sensor_msgs import Image

    data = np.ascontiguousarray(array)
    height, width = data.shape[:2]
    msg = Image()
    msg.header.stamp = stamp(seconds)
    msg.header.frame_id = frame
    msg.height = height
    msg.width = width
    msg.encoding = encoding
    msg.is_bigendian = 0
    msg.step = int(data.strides[0])
    msg.data = np.frombuffer(
        data.astype(data.dtype.newbyteorder("<"), copy=False).tobytes(), np.uint8
    )
    return msg


def camera_info(
    spec: CameraSpec, frame: str, seconds: float, parameters: dict[str, float] | None = None
) -> Any:
    """``sensor_msgs/CameraInfo`` as gazebo_ros_camera_utils fills it.

    Like Gazebo: ``cx = (W + 1) / 2``, ``cy = (H + 1) / 2`` unless ``<Cx>``/``<Cy>``
    are given (the rendered image's centre is at ``(W - 1) / 2`` in ROS's pixel
    convention: Gazebo's value is one pixel off, kept for compatibility; see
    :attr:`workbench.sim.sensors.Camera.K` for the exact one); ``fx = fy =
    W / (2 tan(hfov / 2))`` unless ``<focalLength>``; plumb_bob distortion from
    ``<distortionK1>``... (0 by default); ``P[3] = -f * <hackBaseline>``.
    """
    from workbench.msgs.sensor_msgs import CameraInfo

    values = dict(parameters or {})
    f = values.get("focalLength") or spec.focal_length
    cx = values.get("Cx") or (spec.width + 1.0) / 2.0
    cy = values.get("Cy") or (spec.height + 1.0) / 2.0
    baseline = values.get("hackBaseline", 0.0)
    msg = CameraInfo()
    msg.header.stamp = stamp(seconds)
    msg.header.frame_id = frame
    msg.height = spec.height
    msg.width = spec.width
    msg.distortion_model = "plumb_bob"
    msg.D = [
        values.get("distortionK1", 0.0),
        values.get("distortionK2", 0.0),
        values.get("distortionT1", 0.0),
        values.get("distortionT2", 0.0),
        values.get("distortionK3", 0.0),
    ]
    msg.K = [f, 0.0, cx, 0.0, f, cy, 0.0, 0.0, 1.0]
    msg.R = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    msg.P = [f, 0.0, cx, -f * baseline, 0.0, f, cy, 0.0, 0.0, 0.0, 1.0, 0.0]
    return msg


#: PointCloud2 layout of ``setPointCloud2FieldsByString(2, "xyz", "rgb")``: x, y, z
#: float32 at 0, 4, 8, rgb float32 at 16, 32 bytes a point.
POINT_STEP = 32


def point_cloud(points: np.ndarray, color: np.ndarray | None, frame: str, seconds: float) -> Any:
    """``sensor_msgs/PointCloud2`` (organised, H x W) of optical-frame points and their colours.

    As gazebo_ros_openni_kinect: x, y, z float32 (NaN where unseen; then
    ``is_dense`` is false), and the image's three bytes for each pixel copied in
    image order into the first three bytes of the ``rgb`` field (for an rgb8
    image RViz, which reads the field as packed BGR, shows red and blue
    swapped, as with Gazebo: gazebo_ros_pkgs issue 484).
    """
    from workbench.msgs.sensor_msgs import PointCloud2, PointField

    height, width = points.shape[:2]
    buffer = np.zeros((height * width, POINT_STEP), dtype=np.uint8)
    xyz = np.ascontiguousarray(points.reshape(-1, 3), dtype="<f4")
    buffer[:, 0:12] = xyz.view(np.uint8).reshape(-1, 12)
    if color is not None:
        pixels = color.reshape(height * width, -1)
        if pixels.shape[1] == 1:
            pixels = np.repeat(pixels, 3, axis=1)
        buffer[:, 16:19] = pixels[:, :3]
    msg = PointCloud2()
    msg.header.stamp = stamp(seconds)
    msg.header.frame_id = frame
    msg.height = height
    msg.width = width
    msg.fields = [
        PointField(name="x", offset=0, datatype=PointField.FLOAT32, count=1),
        PointField(name="y", offset=4, datatype=PointField.FLOAT32, count=1),
        PointField(name="z", offset=8, datatype=PointField.FLOAT32, count=1),
        PointField(name="rgb", offset=16, datatype=PointField.FLOAT32, count=1),
    ]
    msg.is_bigendian = False
    msg.point_step = POINT_STEP
    msg.row_step = POINT_STEP * width
    msg.data = buffer.reshape(-1)
    msg.is_dense = bool(np.all(np.isfinite(xyz)))
    return msg


def imu_message(
    orientation: np.ndarray,
    angular_velocity: np.ndarray,
    linear_acceleration: np.ndarray,
    gaussian_noise: float,
    frame: str,
    seconds: float,
) -> Any:
    """``sensor_msgs/Imu`` with the covariance diagonals ``gaussianNoise^2`` (gazebo_ros_imu_sensor)."""
    from workbench.msgs.sensor_msgs import Imu

    msg = Imu()
    msg.header.stamp = stamp(seconds)
    msg.header.frame_id = frame
    x, y, z, w = (float(v) for v in orientation)
    msg.orientation.x, msg.orientation.y, msg.orientation.z, msg.orientation.w = x, y, z, w
    for target, vector in (
        (msg.angular_velocity, angular_velocity),
        (msg.linear_acceleration, linear_acceleration),
    ):
        target.x, target.y, target.z = (float(v) for v in vector)
    covariance = np.zeros(9)
    covariance[[0, 4, 8]] = gaussian_noise**2
    msg.orientation_covariance = covariance
    msg.angular_velocity_covariance = covariance
    msg.linear_acceleration_covariance = covariance
    return msg
