"""``libgazebo_ros_camera.so``, ``libgazebo_ros_openni_kinect.so`` and ``libgazebo_ros_depth_camera.so``.

Parameters, as gazebo_plugins (noetic-devel) reads them in
gazebo_ros_camera_utils.cpp, gazebo_ros_openni_kinect.cpp and
gazebo_ros_depth_camera.cpp:

* ``<cameraName>`` (default empty): topics are relative to
  ``<robotNamespace>/<cameraName>``; absolute topic names stay;
* ``<imageTopicName>`` (``image_raw``; ``ir/image_raw`` for the depth plugins),
  ``<cameraInfoTopicName>`` (``camera_info``; ``ir/camera_info``);
* ``<frameName>``: ``header.frame_id`` of everything, as given (no leading
  slash). Gazebo publishes the images in that frame unrotated, while the
  pixels are in the optical convention (x right, y down, z forward): name a
  ``*_optical_frame`` there, rotated ``rpy(-pi/2, 0, -pi/2)`` from the link;
* ``<updateRate>`` (0: the sensor's ``<update_rate>``) throttles further;
* ``<Cx>``, ``<Cy>``, ``<focalLength>``, ``<hackBaseline>``, ``<distortionK1..3>``,
  ``<distortionT1..2>``: only copied into CameraInfo, as in Gazebo.

The depth plugins add ``<depthImageTopicName>`` (``depth/image_raw``, 32FC1 m),
``<depthImageCameraInfoTopicName>`` (``depth/camera_info``),
``<pointCloudTopicName>`` (``points``, PointCloud2 x, y, z, rgb in the optical
frame), ``<pointCloudCutoff>`` (0.4 m) and, for OpenNI, ``<pointCloudCutoffMax>``
(5 m): depths outside ``(cutoff, cutoffMax)`` become NaN in both the depth image
and the cloud.

As in Gazebo, a camera renders only while one of its topics has a subscriber
(or the sensor is ``<always_on>``); :meth:`CameraPluginBase.capture` renders
on demand for Python code, and ``latest`` keeps the last frame.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from workbench.sim.plugins import SdfElement, UpdateInfo
from workbench.sim.sensors.base import RosSensorPlugin, parameter, robot_namespace
from workbench.sim.sensors.camera import Camera, CameraFrame
from workbench.sim.sensors.messages import (
    camera_info,
    image,
    point_cloud,
    resolve_topic,
    tf_frame,
)
from workbench.sim.sensors.spec import CameraSpec

_INFO_KEYS = (
    "Cx",
    "Cy",
    "focalLength",
    "hackBaseline",
    "distortionK1",
    "distortionK2",
    "distortionK3",
    "distortionT1",
    "distortionT2",
)


class CameraPluginBase(RosSensorPlugin):
    """What the three camera plugins share: the camera, the image and its CameraInfo."""

    sensor_types: tuple[str, ...] = ("camera", "depth")
    label = "camera"
    image_topic_default = "image_raw"
    info_topic_default = "camera_info"
    wants_depth = False

    def setup(self, sdf: SdfElement) -> None:
        assert isinstance(self.spec, CameraSpec)
        self.camera = Camera(self.spec, seed=self.seed)
        self.namespace = "/".join(
            p for p in (robot_namespace(sdf), parameter(sdf, "cameraName", "")) if p
        )
        self.frame = tf_frame(parameter(sdf, "frameName", ""))
        self.info_parameters = {k: float(sdf.get(k, 0.0)) for k in _INFO_KEYS if sdf.has(k)}
        throttle = float(sdf.get("updateRate", 0.0))
        if throttle > 0 and (self.update_rate <= 0 or throttle < self.update_rate):
            self.update_rate = throttle
        #: The last frame rendered, or None.
        self.latest: CameraFrame | None = None
        self.publishers: dict[str, Any] = {}
        if self.node is not None:
            from workbench.msgs.sensor_msgs import CameraInfo, Image

            self._advertise("image", "imageTopicName", self.image_topic_default, Image)
            self._advertise("info", "cameraInfoTopicName", self.info_topic_default, CameraInfo)
            self.advertise_more(sdf)

    def advertise_more(self, sdf: SdfElement) -> None:
        """The depth plugins' extra topics."""

    def _advertise(self, key: str, parameter_name: str, default: str, kind: Any) -> None:
        topic = resolve_topic(self.namespace, parameter(self.sdf, parameter_name, default))
        self.publishers[key] = self.node.create_publisher(topic, kind, queue_size=2)

    def capture(self) -> CameraFrame:
        """Render now (on the server's loop thread) and keep the frame as ``latest``."""

        def work() -> CameraFrame:
            X_WS, _ = self.sensor_pose()
            self.latest = self.camera.capture(self.world, X_WS, depth=self.wants_depth)
            return self.latest

        result: CameraFrame = self.model.server.call(work)
        return result

    def update(self, info: UpdateInfo) -> None:
        wanted = {key for key, pub in self.publishers.items() if self.listeners(pub) > 0}
        if not wanted and not self.spec.always_on:
            return
        X_WS, _ = self.sensor_pose()
        need_depth = self.wants_depth and bool(
            wanted & {"depth", "points", "depth_info"} or self.spec.always_on
        )
        need_color = bool(wanted & {"image", "info", "points"}) or self.spec.always_on
        frame = self.camera.capture(self.world, X_WS, color=need_color, depth=need_depth)
        self.latest = frame
        self.publish(frame, wanted, info.sim_time)

    def publish(self, frame: CameraFrame, wanted: set[str], seconds: float) -> None:
        assert isinstance(self.spec, CameraSpec)
        if frame.color is not None and "image" in wanted:
            self.publishers["image"].publish(
                image(frame.color, self.spec.encoding, self.frame, seconds)
            )
        if "info" in wanted:
            self.publishers["info"].publish(
                camera_info(self.spec, self.frame, seconds, self.info_parameters)
            )

    def close(self) -> None:
        publishers: dict[str, Any] = getattr(self, "publishers", {})
        for publisher in publishers.values():
            publisher.unregister()
        publishers.clear()


class GazeboRosCamera(CameraPluginBase):
    """``libgazebo_ros_camera.so``: Image and CameraInfo of a ``camera`` sensor."""

    sensor_types = ("camera",)


class GazeboRosOpenniKinect(CameraPluginBase):
    """``libgazebo_ros_openni_kinect.so``: image, depth image, point cloud and their CameraInfos."""

    sensor_types = ("depth",)
    label = "openni kinect"
    image_topic_default = "ir/image_raw"
    info_topic_default = "ir/camera_info"
    wants_depth = True
    cutoff_max_default = 5.0

    def advertise_more(self, sdf: SdfElement) -> None:
        from workbench.msgs.sensor_msgs import CameraInfo, Image, PointCloud2

        self._advertise("points", "pointCloudTopicName", "points", PointCloud2)
        self._advertise("depth", "depthImageTopicName", "depth/image_raw", Image)
        self._advertise(
            "depth_info", "depthImageCameraInfoTopicName", "depth/camera_info", CameraInfo
        )
        self.cutoff = float(sdf.get("pointCloudCutoff", 0.4))
        self.cutoff_max = float(sdf.get("pointCloudCutoffMax", self.cutoff_max_default))

    def publish(self, frame: CameraFrame, wanted: set[str], seconds: float) -> None:
        super().publish(frame, wanted, seconds)
        if frame.depth is None:
            return
        assert isinstance(self.spec, CameraSpec)
        depth = np.where(
            (frame.depth > self.cutoff) & (frame.depth < self.cutoff_max), frame.depth, np.nan
        ).astype(np.float32)
        if "depth" in wanted:
            self.publishers["depth"].publish(image(depth, "32FC1", self.frame, seconds))
        if "depth_info" in wanted:
            self.publishers["depth_info"].publish(
                camera_info(self.spec, self.frame, seconds, self.info_parameters)
            )
        if "points" in wanted:
            points = self.camera.points(depth)
            self.publishers["points"].publish(point_cloud(points, frame.color, self.frame, seconds))


class GazeboRosDepthCamera(GazeboRosOpenniKinect):
    """``libgazebo_ros_depth_camera.so``: as OpenNI, with no far cutoff."""

    label = "depth camera"
    cutoff_max_default = math.inf
