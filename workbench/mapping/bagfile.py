"""Laser scans with odometry from ROS 1 bags (``sensor_msgs/LaserScan`` + ``nav_msgs/Odometry`` or ``/tf``).

Reads with rosbags' :class:`~rosbags.highlevel.AnyReader` and its noetic
typestore. Odometry is the pose of ``base_frame`` in ``odom_frame``, from a
``nav_msgs/Odometry`` topic or else from ``/tf``; it is interpolated at each
scan's header stamp. The laser's mounting comes from ``/tf_static`` (or
``/tf``) when a ``base_frame -> laser frame`` transform exists, else the
laser is taken to sit at the base.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workbench.limits import check_regular_file
from workbench.mapping.errors import LogError
from workbench.mapping.geometry import compose, wrap_angle
from workbench.mapping.scan import LaserLog, Scan, scan_problem
from workbench.spatial import yaw_from_quaternion

SCAN_TYPE = "sensor_msgs/msg/LaserScan"
ODOM_TYPE = "nav_msgs/msg/Odometry"
TF_TYPE = "tf2_msgs/msg/TFMessage"
#: Scans up to this far (s) outside the odometry's time span use the nearest odometry.
EXTRAPOLATION_LIMIT = 0.2


def _stamp(header) -> float:
    return header.stamp.sec + 1e-9 * header.stamp.nanosec


def _yaw(q) -> float:
    return yaw_from_quaternion((q.x, q.y, q.z, q.w))


def _frame(name: str) -> str:
    return name.lstrip("/")


def _interpolate(times: np.ndarray, poses: np.ndarray, t: float) -> np.ndarray | None:
    if t < times[0] - EXTRAPOLATION_LIMIT or t > times[-1] + EXTRAPOLATION_LIMIT:
        return None
    k = int(np.searchsorted(times, t))
    if k <= 0:
        return poses[0].copy()
    if k >= len(times):
        return poses[-1].copy()
    t0, t1 = times[k - 1], times[k]
    w = 0.0 if t1 <= t0 else (t - t0) / (t1 - t0)
    a, b = poses[k - 1], poses[k]
    xy = a[:2] + w * (b[:2] - a[:2])
    theta = wrap_angle(a[2] + w * wrap_angle(b[2] - a[2]))
    return np.array([xy[0], xy[1], float(theta)])


def read_bag(
    path: str | Path,
    *,
    scan_topic: str | None = None,
    odom_topic: str | None = None,
    odom_frame: str = "odom",
    base_frame: str | None = None,
) -> LaserLog:
    """Read scans and odometry from a ROS 1 bag.

    Args:
        path: The ``.bag`` file.
        scan_topic: The LaserScan topic; None picks the only one (or ``/scan``).
        odom_topic: The Odometry topic; None picks the only one, else uses ``/tf``.
        odom_frame: Parent frame of the odometry transforms on ``/tf``.
        base_frame: The robot frame; None takes the Odometry's ``child_frame_id``
            or the only child of ``odom_frame`` on ``/tf``.

    Raises:
        LogError: missing or corrupt bag, no (or ambiguous) scan topic, no scans.
    """
    from rosbags.highlevel import AnyReader
    from rosbags.typesys import Stores, get_typestore

    path = Path(path)
    if not path.is_file():
        raise LogError("bag file not found", path=path)
    warnings: list[str] = []
    typestore = get_typestore(Stores.ROS1_NOETIC)
    try:
        reader = AnyReader([path], default_typestore=typestore)
        reader.open()
    except Exception as exc:  # rosbags raises several unrelated types for bad files
        raise LogError(f"cannot read bag: {exc}", path=path, hint="is it a ROS 1 bag?") from None
    try:
        by_type: dict[str, list[str]] = {}
        for c in reader.connections:
            by_type.setdefault(c.msgtype, [])
            if c.topic not in by_type[c.msgtype]:
                by_type[c.msgtype].append(c.topic)
        scan_topics = by_type.get(SCAN_TYPE, [])
        if scan_topic is None:
            if len(scan_topics) == 1:
                scan_topic = scan_topics[0]
            elif "/scan" in scan_topics:
                scan_topic = "/scan"
            elif not scan_topics:
                raise LogError("the bag has no sensor_msgs/LaserScan topic", path=path)
            else:
                raise LogError(
                    f"the bag has several LaserScan topics: {', '.join(sorted(scan_topics))}",
                    path=path,
                    hint="choose one with scan_topic",
                )
        elif scan_topic not in scan_topics:
            raise LogError(
                f"no LaserScan topic {scan_topic!r} in the bag "
                f"(LaserScan topics: {', '.join(scan_topics) or 'none'})",
                path=path,
            )
        odom_topics = by_type.get(ODOM_TYPE, [])
        if odom_topic is None and len(odom_topics) == 1:
            odom_topic = odom_topics[0]
        odom_times: list[float] = []
        odom_poses: list[list[float]] = []
        mounts: dict[tuple[str, str], np.ndarray] = {}
        raw_scans = []
        bad_odometry = 0
        tf_edges: dict[str, list[tuple[float, list[float]]]] = {}
        wanted = [
            c
            for c in reader.connections
            if c.topic in (scan_topic, odom_topic, "/tf", "/tf_static")
        ]
        for connection, _time, data in reader.messages(connections=wanted):
            try:
                msg = reader.deserialize(data, connection.msgtype)
            except Exception as exc:
                warnings.append(f"{path}:{connection.topic}: skipped a bad message ({exc})")
                continue
            if connection.topic == scan_topic:
                raw_scans.append(msg)
            elif connection.topic == odom_topic:
                p = msg.pose.pose
                sample = [_stamp(msg.header), p.position.x, p.position.y, _yaw(p.orientation)]
                if not np.all(np.isfinite(sample)):
                    bad_odometry += 1
                    continue
                odom_times.append(sample[0])
                odom_poses.append(sample[1:])
                if base_frame is None:
                    base_frame = _frame(msg.child_frame_id)
            elif connection.msgtype == TF_TYPE:
                for tf in msg.transforms:
                    parent, child = _frame(tf.header.frame_id), _frame(tf.child_frame_id)
                    tr = tf.transform
                    pose = [tr.translation.x, tr.translation.y, _yaw(tr.rotation)]
                    if not np.all(np.isfinite([*pose, _stamp(tf.header)])):
                        bad_odometry += 1
                        continue
                    mounts[(parent, child)] = np.array(pose)
                    if parent == _frame(odom_frame):
                        tf_edges.setdefault(child, []).append((_stamp(tf.header), pose))
    except LogError:
        raise
    except Exception as exc:
        raise LogError(f"cannot read bag: {exc}", path=path) from None
    finally:
        reader.close()
    if not odom_times and tf_edges:
        if base_frame is None:
            if len(tf_edges) > 1:
                raise LogError(
                    f"several frames hang off {odom_frame!r} on /tf: {', '.join(sorted(tf_edges))}",
                    path=path,
                    hint="choose one with base_frame",
                )
            base_frame = next(iter(tf_edges))
        for stamp, pose in sorted(tf_edges.get(base_frame, [])):
            odom_times.append(stamp)
            odom_poses.append(pose)
    if bad_odometry:
        warnings.append(
            f"{path}: skipped {bad_odometry} odometry or /tf pose(s) that are not finite (NaN or inf)"
        )
    if not raw_scans:
        raise LogError(f"no messages on {scan_topic}", path=path)
    if not odom_times:
        warnings.append(
            f"{path}: no odometry (nav_msgs/Odometry or /tf {odom_frame} -> base); "
            "scans are matched without a motion prior"
        )
    times = np.array(odom_times)
    poses = np.array(odom_poses).reshape(-1, 3)
    order = np.argsort(times, kind="stable")
    times, poses = times[order], poses[order]
    scans: list[Scan] = []
    for index, msg in enumerate(raw_scans):
        stamp = _stamp(msg.header)
        mount = mounts.get((base_frame or "", _frame(msg.header.frame_id)), np.zeros(3))
        if len(times):
            base = _interpolate(times, poses, stamp)
            if base is None:
                warnings.append(
                    f"{path}:{scan_topic}[{index}]: skipped scan at t={stamp:.3f}, "
                    "outside the odometry's time span"
                )
                continue
        else:
            base = np.zeros(3)
        n = len(msg.ranges)
        with np.errstate(all="ignore"):
            angles = msg.angle_min + msg.angle_increment * np.arange(n)
        scan = Scan(
            stamp=stamp,
            ranges=np.asarray(msg.ranges, dtype=float),
            angles=angles,
            odom=compose(base, mount),
            max_range=float(msg.range_max) if msg.range_max > 0 else np.inf,
            min_range=float(max(msg.range_min, 0.0)),
            source=f"{path}:{scan_topic}[{index}]",
        )
        problem = scan_problem(scan)
        if problem is not None:
            warnings.append(f"{path}:{scan_topic}[{index}]: skipped scan: {problem}")
            continue
        scans.append(scan)
    if not scans:
        skipped = [w for w in warnings if ": skipped scan: " in w]
        if skipped:
            raise LogError(
                f"no usable scan on {scan_topic}; the first: "
                + skipped[0].rsplit(": skipped scan: ", 1)[1],
                path=path,
            )
        raise LogError(f"no scan on {scan_topic} falls inside the odometry's time span", path=path)
    return LaserLog(path, scans, warnings)


#: Name endings tried when a log is given by the name of a shipped one (``intel-corrected``).
_LOG_SUFFIXES = ("", ".log.gz", ".log", ".gz", ".bag")


def shipped_logs() -> list[Path]:
    """The laser logs that ship with workbench (``mapping/logs/``)."""
    from workbench.paths import mapping_dir

    folder = mapping_dir() / "logs"
    return sorted(p for p in folder.iterdir() if p.is_file() and p.suffix != ".md")


def resolve_log(path: str | Path) -> Path:
    """``path`` itself if it exists or names a folder; else the shipped log of that name."""
    candidate = Path(path)
    if candidate.exists() or len(candidate.parts) != 1:
        return candidate
    from workbench.paths import mapping_dir

    folder = mapping_dir() / "logs"
    for suffix in _LOG_SUFFIXES:
        shipped = folder / f"{candidate.name}{suffix}"
        if shipped.is_file():
            return shipped
    return candidate


def _shipped_name(path: Path) -> str:
    name = path.name
    for suffix in sorted(_LOG_SUFFIXES, key=len, reverse=True):
        if suffix and name.endswith(suffix):
            return name[: -len(suffix)]
    return name


def read_log(path: str | Path, **bag_options: object) -> LaserLog:
    """Read a CARMEN log (plain or gzip) or a ROS 1 bag, told apart by their content.

    ``path`` may also be the name of a log shipped in ``mapping/logs/`` (e.g.
    ``intel-corrected``), found from any folder.
    """
    from workbench.mapping.carmen import read_carmen

    path = resolve_log(path)
    try:
        if path.exists() and not path.is_dir():
            check_regular_file(path, "log", LogError)  # a FIFO would block, /dev/zero not end
        with open(path, "rb") as stream:
            head = stream.read(13)
    except FileNotFoundError:
        names = ", ".join(_shipped_name(p) for p in shipped_logs())
        raise LogError(
            "log file not found",
            path=path,
            hint=f"give the path of a CARMEN log or a bag, or a shipped log's name ({names})",
        ) from None
    except IsADirectoryError:
        raise LogError("is a directory, not a log file", path=path) from None
    except OSError as exc:
        raise LogError(f"cannot read log: {exc.strerror}", path=path) from None
    if head.startswith(b"#ROSBAG V2.0"):
        return read_bag(path, **bag_options)  # type: ignore[arg-type]
    return read_carmen(path)
