"""Laser logs: CARMEN (plain and gzip) and ROS 1 bags with LaserScan and odometry."""

from __future__ import annotations

import gzip

import numpy as np
import pytest

from workbench.mapping import LogError, read_bag, read_carmen, read_log
from workbench.mapping.carmen import write_carmen
from workbench.mapping.simulate import demo_world, loop_trajectory, simulate_scans

RANGES = " ".join(["2.5"] * 180)


def _flaser(x=1.0, y=2.0, theta=0.5, t=10.0, ranges=RANGES):
    return f"FLASER 180 {ranges} {x} {y} {theta} {x} {y} {theta} {t} host {t}\n"


def test_flaser_fields_and_beam_layout(tmp_path):
    path = tmp_path / "a.log"
    path.write_text("# comment\nPARAM robot_frontlaser_offset 0.0 nohost 0\n" + _flaser())
    log = read_carmen(path)
    assert len(log.scans) == 1 and log.warnings == []
    scan = log.scans[0]
    assert scan.stamp == 10.0
    np.testing.assert_allclose(scan.odom, [1.0, 2.0, 0.5])
    np.testing.assert_allclose(scan.reference, [1.0, 2.0, 0.5])
    # 180 beams over 180 degrees, one degree apart, starting at -90 degrees.
    assert np.degrees(scan.angles[0]) == pytest.approx(-90.0)
    assert np.degrees(scan.angles[1] - scan.angles[0]) == pytest.approx(1.0)
    assert scan.source.endswith("a.log:3")


def test_bad_lines_are_reported_with_their_line_number_and_skipped(tmp_path):
    path = tmp_path / "bad.log"
    path.write_text(
        _flaser(t=1.0)
        + "FLASER 180 1 2 3\n"  # too short
        + _flaser(t=2.0).replace(" 1.0 2.0", " 1.0 abc", 1)  # not a number
        + "FLASER many 1 2\n"  # bad count
        + "ODOM 0 0 0 0 0 0 3.0 host 3.0\n"
        + "NEFF 12\n"
        + _flaser(t=4.0)
    )
    log = read_carmen(path)
    assert [s.stamp for s in log.scans] == [1.0, 4.0]
    assert len(log.warnings) == 3
    assert log.warnings[0].startswith(f"{path}:2: ")
    assert log.warnings[1].startswith(f"{path}:3: ")
    assert log.warnings[2].startswith(f"{path}:4: ")


def test_rlaser_looks_backwards_and_robotlaser1_uses_its_own_layout(tmp_path):
    ranges = " ".join(["1.0"] * 5)
    robot = (
        f"ROBOTLASER1 0 -1.0 2.0 0.5 30.0 0.01 0 5 {ranges} 0 "
        "3.0 4.0 0.1 2.9 4.0 0.1 0 0 0 0 0 7.5 host 7.5\n"
    )
    path = tmp_path / "mixed.log"
    path.write_text(_flaser(t=1.0).replace("FLASER", "RLASER") + robot)
    rear, robotlaser = read_carmen(path).scans
    assert np.degrees(rear.angles[0]) == pytest.approx(90.0)
    np.testing.assert_allclose(robotlaser.angles, [-1.0, -0.5, 0.0, 0.5, 1.0])
    np.testing.assert_allclose(robotlaser.odom, [3.0, 4.0, 0.1])
    assert robotlaser.max_range == 30.0 and robotlaser.stamp == 7.5


def test_gzip_is_detected_from_the_content_and_round_trips(tmp_path):
    scans = simulate_scans(demo_world(), loop_trajectory()[:5], beams=181, seed=3)
    path = write_carmen(tmp_path / "sim.log.gz", scans)
    assert path.read_bytes()[:2] == b"\x1f\x8b"
    renamed = path.rename(tmp_path / "sim.txt")  # the name does not matter
    log = read_log(renamed)
    assert len(log.scans) == 5
    np.testing.assert_allclose(log.scans[2].ranges, scans[2].ranges, atol=1e-4)
    np.testing.assert_allclose(log.scans[2].angles, scans[2].angles, atol=1e-9)
    np.testing.assert_allclose(log.scans[4].odom, scans[4].odom, atol=1e-6)


def test_missing_empty_and_corrupt_logs_are_one_line_errors(tmp_path):
    with pytest.raises(LogError, match="not found"):
        read_log(tmp_path / "absent.log")
    (tmp_path / "odom.log").write_text("ODOM 0 0 0 0 0 0 1.0 host 1.0\n")
    with pytest.raises(LogError, match="no laser lines") as info:
        read_log(tmp_path / "odom.log")
    assert "odom.log" in info.value.one_line()
    (tmp_path / "corrupt.gz").write_bytes(b"\x1f\x8b\x08\x00garbage-not-deflate" * 4)
    with pytest.raises(LogError, match="corrupt"):
        read_log(tmp_path / "corrupt.gz")
    with pytest.raises(LogError, match="directory"):
        read_log(tmp_path)


def test_truncated_gzip_keeps_the_scans_before_the_damage(tmp_path):
    text = "".join(_flaser(t=float(k)) for k in range(200)).encode()
    data = gzip.compress(text)
    (tmp_path / "cut.gz").write_bytes(data[: len(data) // 2])
    log = read_log(tmp_path / "cut.gz")
    assert 0 < len(log.scans) < 200
    assert any("truncated" in w for w in log.warnings)


def test_intel_log_has_910_scans_of_180_beams(intel_log):
    log = read_log(intel_log)
    assert len(log.scans) == 910
    assert all(len(s.ranges) == 180 for s in log.scans)
    assert log.warnings == []
    assert 2600 < log.duration < 2700
    refs = log.references()
    assert refs is not None and refs.shape == (910, 3)


# --- ROS 1 bags -------------------------------------------------------------------------


def _write_bag(path, scans, *, odom="odometry", frame_prefix=""):
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    ts = get_typestore(Stores.ROS1_NOETIC)
    # The noetic store lacks tf2_msgs; its one message is a list of transforms.
    ts.register(
        get_types_from_msg("geometry_msgs/TransformStamped[] transforms", "tf2_msgs/msg/TFMessage")
    )
    T = ts.types
    Time = T["builtin_interfaces/msg/Time"]
    Header = T["std_msgs/msg/Header"]

    def header(t, frame):
        return Header(
            seq=0, stamp=Time(sec=int(t), nanosec=int(round((t % 1) * 1e9))), frame_id=frame
        )

    def quat(yaw):
        return T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=np.sin(yaw / 2), w=np.cos(yaw / 2))

    Vector3 = T["geometry_msgs/msg/Vector3"]
    with Writer(path) as writer:
        c_scan = writer.add_connection("/scan", "sensor_msgs/msg/LaserScan", typestore=ts)
        c_odom = writer.add_connection("/odom", "nav_msgs/msg/Odometry", typestore=ts)
        c_tf = writer.add_connection("/tf", "tf2_msgs/msg/TFMessage", typestore=ts)
        c_static = writer.add_connection("/tf_static", "tf2_msgs/msg/TFMessage", typestore=ts)
        mount = T["geometry_msgs/msg/TransformStamped"](
            header=header(0.0, "base_link"),
            child_frame_id="laser",
            transform=T["geometry_msgs/msg/Transform"](
                translation=Vector3(x=0.2, y=0.0, z=0.1), rotation=quat(0.0)
            ),
        )
        writer.write(
            c_static,
            1,
            ts.serialize_ros1(
                T["tf2_msgs/msg/TFMessage"](transforms=[mount]), "tf2_msgs/msg/TFMessage"
            ),
        )
        for scan in scans:
            t = 100.0 + scan.stamp
            ns = int(t * 1e9)
            # The scan's odometry is the laser pose; the base is 0.2 m behind it.
            base = scan.odom - np.array(
                [0.2 * np.cos(scan.odom[2]), 0.2 * np.sin(scan.odom[2]), 0.0]
            )
            pose = T["geometry_msgs/msg/Pose"](
                position=T["geometry_msgs/msg/Point"](x=base[0], y=base[1], z=0.0),
                orientation=quat(base[2]),
            )
            if odom == "odometry":
                cov = np.zeros(36)
                msg = T["nav_msgs/msg/Odometry"](
                    header=header(t - 0.05, "odom"),
                    child_frame_id="base_link",
                    pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose, covariance=cov),
                    twist=T["geometry_msgs/msg/TwistWithCovariance"](
                        twist=T["geometry_msgs/msg/Twist"](
                            linear=Vector3(x=0.0, y=0.0, z=0.0),
                            angular=Vector3(x=0.0, y=0.0, z=0.0),
                        ),
                        covariance=cov,
                    ),
                )
                writer.write(c_odom, ns, ts.serialize_ros1(msg, "nav_msgs/msg/Odometry"))
                msg2 = T["nav_msgs/msg/Odometry"](
                    header=header(t + 0.05, "odom"),
                    child_frame_id="base_link",
                    pose=msg.pose,
                    twist=msg.twist,
                )
                writer.write(c_odom, ns + 1, ts.serialize_ros1(msg2, "nav_msgs/msg/Odometry"))
            else:
                tf = T["geometry_msgs/msg/TransformStamped"](
                    header=header(t, frame_prefix + "odom"),
                    child_frame_id=frame_prefix + "base_link",
                    transform=T["geometry_msgs/msg/Transform"](
                        translation=Vector3(x=base[0], y=base[1], z=0.0), rotation=quat(base[2])
                    ),
                )
                writer.write(
                    c_tf,
                    ns,
                    ts.serialize_ros1(
                        T["tf2_msgs/msg/TFMessage"](transforms=[tf]), "tf2_msgs/msg/TFMessage"
                    ),
                )
            ranges = scan.ranges.astype(np.float32)
            ranges[3] = np.nan
            ranges[4] = np.inf
            msg = T["sensor_msgs/msg/LaserScan"](
                header=header(t, "laser"),
                angle_min=float(scan.angles[0]),
                angle_max=float(scan.angles[-1]),
                angle_increment=float(scan.angles[1] - scan.angles[0]),
                time_increment=0.0,
                scan_time=0.1,
                range_min=0.05,
                range_max=float(scan.max_range),
                ranges=ranges,
                intensities=np.zeros(0, dtype=np.float32),
            )
            writer.write(c_scan, ns + 2, ts.serialize_ros1(msg, "sensor_msgs/msg/LaserScan"))
    return path


@pytest.mark.parametrize("odom", ["odometry", "tf"])
def test_bag_scans_get_interpolated_odometry_and_the_laser_mount(tmp_path, odom):
    scans = simulate_scans(demo_world(), loop_trajectory()[:6], beams=181, seed=2)
    path = _write_bag(
        tmp_path / "run.bag", scans, odom=odom, frame_prefix="/" if odom == "tf" else ""
    )
    log = read_log(path)
    assert len(log.scans) == 6
    for got, want in zip(log.scans, scans, strict=True):
        np.testing.assert_allclose(got.odom, want.odom, atol=1e-5)
        np.testing.assert_allclose(got.angles, want.angles, atol=1e-6)
        assert got.stamp == pytest.approx(100.0 + want.stamp)
    # NaN and inf readings stay in the scan but are not valid returns.
    assert not log.scans[0].valid()[3] and not log.scans[0].valid()[4]
    assert log.scans[0].min_range == pytest.approx(0.05)


def test_bag_errors_name_the_problem(tmp_path):
    scans = simulate_scans(demo_world(), loop_trajectory()[:2], beams=181, seed=2)
    path = _write_bag(tmp_path / "run.bag", scans)
    with pytest.raises(LogError, match="no LaserScan topic '/front'"):
        read_bag(path, scan_topic="/front")
    broken = tmp_path / "broken.bag"
    broken.write_bytes(b"#ROSBAG V2.0\n" + b"\x00" * 50)
    with pytest.raises(LogError, match="cannot read bag"):
        read_log(broken)
    with pytest.raises(LogError, match="not found"):
        read_bag(tmp_path / "absent.bag")
