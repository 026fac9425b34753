"""RViz's other default displays: Grid, Axes, TF, LaserScan, PointCloud2, Map, Path, poses, Odometry, RobotModel."""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np

from workbench.errors import ViewerError
from workbench.rviz.display import Context, Display

#: Most cells a side of the Grid display (2,002 lines; RViz's default is 10).
MAX_GRID_CELLS = 1000


def _stamped_transform(context: Context, header: Any) -> Any:
    return context.transform(header.frame_id, header.stamp)


def _pose_transform(pose: Any) -> Any:
    from workbench.spatial import rigid_transform

    q = pose.orientation
    quaternion = (q.x, q.y, q.z, q.w)
    if all(v == 0.0 for v in quaternion):
        quaternion = (0.0, 0.0, 0.0, 1.0)
    return rigid_transform(
        [pose.position.x, pose.position.y, pose.position.z], quaternion=quaternion
    )


def _rgba(rgb: tuple[float, ...], alpha: float = 1.0) -> Any:
    from pydrake.geometry import Rgba

    return Rgba(rgb[0], rgb[1], rgb[2], alpha)


class GridDisplay(Display):
    """A grid in the fixed frame's xy plane (RViz: 10 cells of 1 m, grey).

    Raises:
        ViewerError: ``cells`` not a whole number from 1 to :data:`MAX_GRID_CELLS`, or
            ``cell_size`` not a finite number above 0.
    """

    class_name = "Grid"

    def __init__(self, cells: int = 10, cell_size: float = 1.0, name: str = "Grid") -> None:
        whole = isinstance(cells, numbers.Integral) and not isinstance(cells, bool)
        if not whole or not 1 <= cells <= MAX_GRID_CELLS:
            raise ViewerError(
                f"Grid '{name:.60}': cells must be a whole number from 1 to {MAX_GRID_CELLS:,}, "
                f"not {cells!r:.40}"
            )
        if not isinstance(cell_size, numbers.Real) or not (
            math.isfinite(cell_size) and cell_size > 0
        ):
            raise ViewerError(
                f"Grid '{name:.60}': cell_size must be a finite number above 0, not {cell_size!r:.40}"
            )
        super().__init__(topic="", name=name)
        self.cells: int = int(cells)
        self.cell_size: float = float(cell_size)
        self._drawn: bool = False

    def update(self, context: Context) -> None:
        if self._drawn:
            return
        half = self.cells * self.cell_size / 2
        ticks = np.linspace(-half, half, self.cells + 1)
        starts = np.concatenate(
            [
                np.stack([ticks, -half * np.ones_like(ticks), 0 * ticks]),
                np.stack([-half * np.ones_like(ticks), ticks, 0 * ticks]),
            ],
            axis=1,
        )
        ends = np.concatenate(
            [
                np.stack([ticks, half * np.ones_like(ticks), 0 * ticks]),
                np.stack([half * np.ones_like(ticks), ticks, 0 * ticks]),
            ],
            axis=1,
        )
        context.meshcat.SetLineSegments(
            f"{context.prefix}/{self.path}", np.asfortranarray(starts), np.asfortranarray(ends),
            1.0, _rgba((0.63, 0.63, 0.64), 0.5),
        )  # fmt: skip
        self._drawn = True
        self.drawn += 1


class AxesDisplay(Display):
    """A triad at ``frame`` (default: the fixed frame)."""

    class_name = "Axes"

    def __init__(self, frame: str = "", length: float = 1.0, name: str = "Axes") -> None:
        super().__init__(topic="", name=name)
        self.frame = frame
        self.length = length
        self._drawn = False

    def update(self, context: Context) -> None:
        from workbench.tf.exceptions import TransformException
        from workbench.viz.frames import add_triad

        path = f"{context.prefix}/{self.path}"
        if not self._drawn:
            add_triad(context.meshcat, path, self.length, self.length * 0.05)
            self._drawn = True
        try:
            context.meshcat.SetTransform(path, context.transform(self.frame or context.fixed_frame))
            self.status.pop("Transform", None)
        except TransformException as error:
            self.status["Transform"] = f"No transform from [{self.frame}] to fixed frame: {error}"


class TFDisplay(Display):
    """Every tf frame as a triad in the fixed frame, and a line from each frame to its parent.

    RViz also writes the frame names; Meshcat draws no text, so names are left out.
    """

    class_name = "TF"

    def __init__(self, scale: float = 0.3, name: str = "TF") -> None:
        super().__init__(topic="", name=name)
        self.scale = scale
        self._shown: set[str] = set()

    def update(self, context: Context) -> None:
        from workbench.tf.exceptions import TransformException
        from workbench.viz.frames import add_triad

        with context.buffer._lock:
            frames = context.buffer.get_frame_strings()
            parents = {
                child: entry["parent"] for child, entry in context.buffer.frames_info().items()
            }
        problems = {}
        origins: dict[str, np.ndarray] = {}
        for frame in frames:
            path = f"{context.prefix}/{self.path}/frames/{frame}"
            try:
                X = context.transform(frame)
            except TransformException as error:
                problems[frame] = f"No transform from [{frame}] to [{context.fixed_frame}]: {error}"
                continue
            if frame not in self._shown:
                add_triad(context.meshcat, path, self.scale, self.scale * 0.03)
                self._shown.add(frame)
            context.meshcat.SetTransform(path, X)
            origins[frame] = X.translation()
        pairs = [(c, p) for c, p in parents.items() if c in origins and p in origins]
        if pairs:
            starts = np.array([origins[c] for c, _ in pairs]).T
            ends = np.array([origins[p] for _, p in pairs]).T
            context.meshcat.SetLineSegments(
                f"{context.prefix}/{self.path}/arrows",
                np.asfortranarray(starts),
                np.asfortranarray(ends),
                2.0,
                _rgba((1.0, 0.9, 0.2)),
            )
        self.status = problems
        self.drawn += 1


class _PointsDisplay(Display):
    """A sensor stream drawn as points of ``size`` (m) and ``color`` (r, g, b), every message."""

    draw_every = True
    default_size = 0.01
    default_color: tuple[float, float, float] = (1.0, 1.0, 1.0)

    def __init__(
        self,
        topic: str | None = None,
        size: float | None = None,
        color: tuple[float, float, float] | None = None,
        name: str | None = None,
    ) -> None:
        super().__init__(topic, name)
        self.size = size if size is not None else self.default_size
        self.color = color if color is not None else self.default_color


class LaserScanDisplay(_PointsDisplay):
    """``sensor_msgs/LaserScan`` as points in the fixed frame (default topic ``scan``)."""

    class_name = "LaserScan"
    message_type = "sensor_msgs/LaserScan"
    default_topic = "scan"
    default_size = 0.03
    default_color = (1.0, 0.0, 0.0)

    def draw(self, context: Context, message: Any) -> None:
        ranges = np.asarray(message.ranges, dtype=float)
        angles = message.angle_min + message.angle_increment * np.arange(len(ranges))
        valid = np.isfinite(ranges) & (ranges >= message.range_min) & (ranges <= message.range_max)
        r, a = ranges[valid], angles[valid]
        xyz = np.stack([r * np.cos(a), r * np.sin(a), np.zeros_like(r)])
        X = _stamped_transform(context, message.header)
        _cloud(context, f"{context.prefix}/{self.path}", xyz, self.size, self.color, X)


class PointCloud2Display(_PointsDisplay):
    """``sensor_msgs/PointCloud2`` with x, y, z (and rgb) fields."""

    class_name = "PointCloud2"
    message_type = "sensor_msgs/PointCloud2"
    default_topic = "points"

    def draw(self, context: Context, message: Any) -> None:
        xyz, rgb = cloud_arrays(message)
        X = _stamped_transform(context, message.header)
        _cloud(context, f"{context.prefix}/{self.path}", xyz, self.size, self.color, X, rgb)


def cloud_arrays(message: Any) -> tuple[np.ndarray, np.ndarray | None]:
    """``(xyz (3, N), rgb (3, N) uint8 or None)`` of a PointCloud2, NaN points dropped.

    Raises:
        ValueError: No float32 x, y, z fields.
    """
    fields = {f.name: f for f in message.fields}
    if not all(name in fields and fields[name].datatype == 7 for name in "xyz"):
        raise ValueError("PointCloud2 needs FLOAT32 x, y and z fields")
    n = message.width * message.height
    raw = np.frombuffer(bytes(message.data), dtype=np.uint8)[: n * message.point_step]
    rows = raw.reshape(n, message.point_step)
    order = ">" if message.is_bigendian else "<"
    xyz = np.stack(
        [
            rows[:, fields[c].offset : fields[c].offset + 4].copy().view(f"{order}f4")[:, 0]
            for c in "xyz"
        ]
    ).astype(float)
    rgb = None
    if "rgb" in fields or "rgba" in fields:
        field = fields.get("rgb") or fields["rgba"]
        packed = rows[:, field.offset : field.offset + 4].copy().view(f"{order}u4")[:, 0]
        rgb = np.stack([(packed >> 16) & 255, (packed >> 8) & 255, packed & 255]).astype(np.uint8)
    keep = np.all(np.isfinite(xyz), axis=0)
    return xyz[:, keep], (rgb[:, keep] if rgb is not None else None)


def _cloud(
    context: Context,
    path: str,
    xyz: np.ndarray,
    size: float,
    color: Any,
    X: Any,
    rgb: np.ndarray | None = None,
) -> None:
    from pydrake.perception import BaseField, Fields, PointCloud

    fields = BaseField.kXYZs | (BaseField.kRGBs if rgb is not None else 0)
    cloud = PointCloud(xyz.shape[1], Fields(fields))  # type: ignore[arg-type]
    cloud.mutable_xyzs()[:] = xyz.astype(np.float32)
    if rgb is not None:
        cloud.mutable_rgbs()[:] = rgb
    context.meshcat.SetObject(path, cloud, size, _rgba(color))
    context.meshcat.SetTransform(path, X)


class MapDisplay(Display):
    """``nav_msgs/OccupancyGrid`` in one of RViz's colour schemes (``map``, ``costmap``, ``raw``).

    Args:
        topic: The grid's topic (default ``map``).
        color_scheme: RViz's ``Color Scheme`` (see :mod:`workbench.rviz.map_palette`).
        alpha: RViz's ``Alpha`` (0.7 as RViz's default).
        name: The display's name.
    """

    class_name = "Map"

    message_type = "nav_msgs/OccupancyGrid"
    default_topic = "map"

    def __init__(
        self,
        topic: str | None = None,
        color_scheme: str = "map",
        alpha: float = 0.7,
        name: str | None = None,
    ) -> None:
        from workbench.errors import ViewerError
        from workbench.rviz.map_palette import SCHEMES

        super().__init__(topic, name)
        if color_scheme not in SCHEMES:
            raise ViewerError(
                f"Map display '{self.name:.60}': unknown Color Scheme '{color_scheme:.60}'",
                hint="one of: " + ", ".join(SCHEMES),
            )
        self.color_scheme = color_scheme
        self.alpha = float(alpha)
        #: Drawn this many 2 mm steps above z = 0, so that maps drawn over each other
        #: (a costmap over the map) do not flicker; RViz.add_display sets it.
        self.layer = 0
        #: ``(x_min, x_max, y_min, y_max)`` of the last map drawn, in the fixed frame (m).
        self.extent: tuple[float, float, float, float] | None = None

    def draw(self, context: Context, message: Any) -> None:
        from workbench.rviz.map_palette import colour_cells, is_opaque, shrink

        info = message.info
        width, height, resolution = info.width, info.height, info.resolution
        if width * height == 0 or not resolution > 0:
            self.status["Map"] = (
                f"Map is zero-sized ({width}x{height})"
                if width * height == 0
                else "Resolution is not positive"
            )
            return
        data = message.data
        raw = (
            np.frombuffer(bytes(data), dtype=np.int8)
            if isinstance(data, (bytes, bytearray))
            else np.asarray(data, dtype=np.int64).astype(np.int8)
        )
        if raw.size != width * height:
            self.status["Map"] = (
                f"Data size doesn't match width*height: width = {width}, height = {height}, "
                f"data size = {raw.size}"
            )
            return
        cells = raw.reshape(height, width).view(np.uint8)
        factor = int(np.ceil(max(width, height) / MAP_TEXTURE_LIMIT))
        if factor > 1:
            cells = shrink(cells, factor, self.color_scheme)
            self.status["Resolution"] = (
                f"{width}x{height} cells drawn as {cells.shape[1]}x{cells.shape[0]} "
                "(the most occupied cell of each block, so walls stay)"
            )
        else:
            self.status.pop("Resolution", None)
        from pydrake.geometry import Mesh

        from workbench.paths import cache_root
        from workbench.rviz.texture import write_quad

        rgba = colour_cells(cells, self.color_scheme, self.alpha)
        opaque = is_opaque(self.color_scheme, self.alpha)
        path = f"{context.prefix}/{self.path}"
        size_x, size_y = width * resolution, height * resolution
        quad = write_quad(cache_root() / "rviz", rgba, size_x, size_y, blend=not opaque)
        context.meshcat.SetObject(path + "/image", Mesh(str(quad)))  # type: ignore[call-overload]
        from workbench.spatial import rigid_transform

        X_FM = _stamped_transform(context, message.header).multiply(_pose_transform(info.origin))
        context.meshcat.SetTransform(path, X_FM)
        context.meshcat.SetTransform(path + "/image", rigid_transform([0, 0, 0.002 * self.layer]))
        corners = np.array([[0, 0, 0], [size_x, 0, 0], [0, size_y, 0], [size_x, size_y, 0]]).T
        xy = (X_FM.rotation().matrix() @ corners + X_FM.translation()[:, None])[:2]
        self.extent = (xy[0].min(), xy[0].max(), xy[1].min(), xy[1].max())
        self.status.pop("Map", None)


#: Largest map texture side drawn at full resolution (browsers allow 4096 and up).
MAP_TEXTURE_LIMIT = 2048


class _ColouredDisplay(Display):
    """A topic display drawn in one colour (RViz's ``Color`` and ``Alpha`` properties)."""

    default_color: tuple[float, float, float] = (25 / 255, 1.0, 0.0)

    def __init__(
        self,
        topic: str | None = None,
        color: tuple[float, float, float] | None = None,
        alpha: float = 1.0,
        name: str | None = None,
    ) -> None:
        super().__init__(topic, name)
        self.color = tuple(color) if color is not None else self.default_color
        self.alpha = float(alpha)


class PathDisplay(_ColouredDisplay):
    """``nav_msgs/Path`` as a line strip through its poses, in the path's header frame
    (RViz's default ``Lines`` style, colour 25; 255; 0)."""

    class_name = "Path"

    message_type = "nav_msgs/Path"
    default_topic = "path"

    def draw(self, context: Context, message: Any) -> None:
        path = f"{context.prefix}/{self.path}"
        if len(message.poses) < 2:  # nothing to join: an empty plan clears the line
            context.meshcat.Delete(path)
            return
        X = _stamped_transform(context, message.header)
        pts = np.array(
            [[p.pose.position.x, p.pose.position.y, p.pose.position.z] for p in message.poses]
        ).T
        colour = _rgba(self.color, self.alpha)
        context.meshcat.SetLine(path, np.asfortranarray(pts), 2.0, colour)
        context.meshcat.SetTransform(path, X)


class PoseDisplay(Display):
    """``geometry_msgs/PoseStamped`` as an arrow along the pose's x (RViz's default shape)."""

    class_name = "Pose"

    message_type = "geometry_msgs/PoseStamped"
    default_topic = "pose"

    def draw(self, context: Context, message: Any) -> None:
        X = _stamped_transform(context, message.header).multiply(_pose_transform(message.pose))
        _arrow(context, f"{context.prefix}/{self.path}", X)


class PoseArrayDisplay(_ColouredDisplay):
    """``geometry_msgs/PoseArray`` (AMCL's particle cloud) as RViz's "Arrow (Flat)" shape:
    per pose a line of ``arrow_length`` along its x and two head strokes to
    ``(0.75, +-0.2) * arrow_length``, colour 255; 25; 0, all in one line set."""

    class_name = "PoseArray"

    message_type = "geometry_msgs/PoseArray"
    default_topic = "particlecloud"
    default_color = (1.0, 25 / 255, 0.0)

    def __init__(
        self,
        topic: str | None = None,
        color: tuple[float, float, float] | None = None,
        alpha: float = 1.0,
        arrow_length: float = 0.3,
        name: str | None = None,
    ) -> None:
        super().__init__(topic, color, alpha, name)
        self.arrow_length = float(arrow_length)

    def draw(self, context: Context, message: Any) -> None:
        path = f"{context.prefix}/{self.path}"
        if not message.poses:
            context.meshcat.Delete(path)
            return
        starts, ends = flat_arrows(message.poses, self.arrow_length)
        X_FH = _stamped_transform(context, message.header)
        context.meshcat.SetLineSegments(
            path, np.asfortranarray(starts), np.asfortranarray(ends), 1.0,
            _rgba(self.color, self.alpha),
        )  # fmt: skip
        context.meshcat.SetTransform(path, X_FH)


def flat_arrows(poses: Any, length: float) -> tuple[np.ndarray, np.ndarray]:
    """Segment starts and ends (3, 3N) of RViz's flat arrows for ``poses`` (m).

    Quaternions are normalised; an all-zero one counts as the identity.
    """
    from scipy.spatial.transform import Rotation

    p = np.array([[q.position.x, q.position.y, q.position.z] for q in poses], dtype=float)
    q = np.array(
        [[o.orientation.x, o.orientation.y, o.orientation.z, o.orientation.w] for o in poses],
        dtype=float,
    )
    q[~np.any(q != 0.0, axis=1)] = (0.0, 0.0, 0.0, 1.0)
    R = Rotation.from_quat(q)
    tip = p + R.apply(np.array([length, 0.0, 0.0]))
    left = p + R.apply(np.array([0.75 * length, 0.2 * length, 0.0]))
    right = p + R.apply(np.array([0.75 * length, -0.2 * length, 0.0]))
    starts = np.stack([p, tip, tip], axis=1).reshape(-1, 3).T
    ends = np.stack([tip, left, right], axis=1).reshape(-1, 3).T
    return starts, ends


class OdometryDisplay(Display):
    """``nav_msgs/Odometry``: an arrow at the pose (RViz keeps the last 100; here the newest)."""

    class_name = "Odometry"

    message_type = "nav_msgs/Odometry"
    default_topic = "odom"

    def draw(self, context: Context, message: Any) -> None:
        X = _stamped_transform(context, message.header).multiply(_pose_transform(message.pose.pose))
        _arrow(context, f"{context.prefix}/{self.path}", X, colour=(1.0, 0.1, 0.0))


def _arrow(
    context: Context, path: str, X: Any, length: float = 1.0, colour=(1.0, 0.1, 0.0)
) -> None:
    from workbench.msgs.visualization_msgs import Marker
    from workbench.rviz.marker_draw import draw_marker

    marker = Marker(type=0)
    marker.scale.x, marker.scale.y, marker.scale.z = length, 0.05 * length, 0.1 * length
    marker.color.r, marker.color.g, marker.color.b = (float(c) for c in colour)
    marker.color.a = 1.0
    draw_marker(context.meshcat, path, marker)
    context.meshcat.SetTransform(path, X)


class RobotModelDisplay(Display):
    """The robot in ``robot_description`` (a parameter), each link posed by tf."""

    class_name = "RobotModel"

    def __init__(self, param: str = "robot_description", name: str = "RobotModel") -> None:
        super().__init__(topic="", name=name)
        self.param = param
        self._display: Any = None

    def update(self, context: Context) -> None:
        if self._display is None and not self._load(context):
            return
        self._display.fixed_frame = context.fixed_frame
        problems = self._display.update()
        self.status = {link: text for link, text in problems.items()}
        self.drawn += 1

    def _load(self, context: Context) -> bool:
        from workbench.errors import WorkbenchError
        from workbench.model import RobotDescription, load_robot
        from workbench.robot_state.display import RobotModelDisplay as LinkPoser

        node = context.node
        if not node.has_param(self.param):
            self.status["URDF"] = (
                f"Parameter [{self.param}] does not exist, and was not found by searchParam()"
            )
            return False
        try:
            robot = load_robot(RobotDescription.from_text(str(node.get_param(self.param))))
        except WorkbenchError as error:
            self.status["URDF"] = f"URDF failed to load: {error}"
            return False

        class _Viewer:
            meshcat = context.meshcat

            @staticmethod
            def show_robot(robot: Any, q: Any = None, prefix: str | None = None) -> str:
                from workbench.viz import Viewer

                return Viewer(context.meshcat).show_robot(robot, q, f"{context.prefix}/{self.path}")

        self._display = LinkPoser(robot, context.buffer, _Viewer(), context.fixed_frame)
        self.status.pop("URDF", None)
        return True
