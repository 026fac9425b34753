"""Bags: writing, reading back (also with rosbags alone), info layout, recovery, errors.

``bag info``'s layout is rosbag's ``Bag.__str__`` (ROS Noetic rosbag/bag.py):
left column padded to the longest key + 1, ``duration`` as ``%.1fs`` under a
minute, ``start``/``end`` as ``%b %d %Y %H:%M:%S.ff (epoch.ff)``, sizes in KB/MB
with one decimal, ``compression: none [n/n chunks]``, types with md5 in brackets
and topic lines ``topic   N msgs    : type``.

Regenerate the golden file with ``WORKBENCH_REGEN_GOLDEN=1 pytest tests/bag``.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest
from rosbags.rosbag1 import Reader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from workbench.bag import (
    BagDamagedError,
    BagFormatError,
    BagNotFoundError,
    BagWriteError,
    BagWriter,
    default_bag_name,
    format_info,
    read_messages,
    summarize,
)
from workbench.msgs.geometry_msgs import Twist, Vector3
from workbench.msgs.turtlesim import Pose

T0 = 1638598185.48  # the manual's bag starts here
# md5sums as ROS Noetic publishes them (rosmsg md5)
TWIST_MD5 = "9f195f881246fdfa2798d1d3eebca84a"
POSE_MD5 = "863b248d5016ca62ea2e895ae5265cf9"


@pytest.fixture
def utc(monkeypatch):
    monkeypatch.setenv("TZ", "UTC")
    time.tzset()
    yield
    monkeypatch.undo()
    time.tzset()


def _write_sample(path: Path, n: int = 50, **kwargs) -> Path:
    with BagWriter(path, **kwargs) as bag:
        for i in range(n):
            bag.write(
                "/turtle1/cmd_vel",
                Twist(linear=Vector3(x=2.0), angular=Vector3(z=0.1 * i)),
                T0 + i * 0.2,
            )
            bag.write(
                "/turtle1/pose", Pose(x=5.5 + 0.1 * i, y=5.5, theta=0.01 * i), T0 + i * 0.2 + 0.016
            )
    return bag.path


def test_writer_uses_active_name_then_renames(tmp_path):
    bag = BagWriter(tmp_path / "run").open()
    bag.write("/turtle1/pose", Pose(x=1.0), T0)
    assert (tmp_path / "run.bag.active").exists()
    assert not (tmp_path / "run.bag").exists()
    assert bag.close() == tmp_path / "run.bag"
    assert (tmp_path / "run.bag").exists()
    assert not (tmp_path / "run.bag.active").exists()


def test_default_name_is_the_date_like_rosbag():
    import datetime

    when = datetime.datetime(2021, 12, 4, 11, 39, 45)
    assert default_bag_name(when=when) == "2021-12-04-11-39-45.bag"
    assert default_bag_name("turtle", when=when) == "turtle_2021-12-04-11-39-45.bag"


def test_round_trip_with_workbench_reader(tmp_path):
    path = _write_sample(tmp_path / "a.bag")
    messages = list(read_messages(path))
    assert len(messages) == 100
    topic, stamp, msg, typename, stamp_ns = messages[1]
    assert (topic, typename) == ("/turtle1/pose", "turtlesim/Pose")
    assert stamp == pytest.approx(T0 + 0.016)
    assert msg.x == pytest.approx(5.5)
    poses = list(read_messages(path, topics=["/turtle1/pose"]))
    assert [m.msg.theta for m in poses] == pytest.approx([0.01 * i for i in range(50)], abs=1e-6)


def test_rosbags_alone_reads_our_bag_with_the_right_md5sums(tmp_path):
    path = _write_sample(tmp_path / "a.bag")
    with Reader(path) as reader:
        digests = {c.topic: (c.msgtype, c.digest) for c in reader.connections}
        assert digests == {
            "/turtle1/cmd_vel": ("geometry_msgs/msg/Twist", TWIST_MD5),
            "/turtle1/pose": ("turtlesim/msg/Pose", POSE_MD5),
        }
        store = get_typestore(Stores.ROS1_NOETIC)
        for conn in reader.connections:
            store.register(get_types_from_msg(conn.msgdef.data, conn.msgtype))
        decoded = [
            store.deserialize_ros1(data, conn.msgtype)
            for conn, _, data in reader.messages()
            if conn.topic == "/turtle1/pose"
        ]
    assert len(decoded) == 50
    assert decoded[10].x == pytest.approx(6.5)


def test_info_is_golden(tmp_path, data_dir, utc):
    path = _write_sample(tmp_path / "2021-12-04-11-39-45.bag")
    text = format_info(summarize(path), name=path.name)
    golden = data_dir / "lab2" / "bag_info.txt"
    if os.environ.get("WORKBENCH_REGEN_GOLDEN"):
        golden.write_text(text + "\n")
    assert text + "\n" == golden.read_text()


def test_info_compressed_counts_chunks(tmp_path, utc):
    path = _write_sample(tmp_path / "c.bag", n=400, compression="bz2", chunk_size=4096)
    text = format_info(summarize(path))
    line = next(x for x in text.splitlines() if x.startswith("compression:"))
    summary = summarize(path)
    assert len(summary.chunks) > 1
    assert line.startswith(
        f"compression: bz2 [{len(summary.chunks)}/{len(summary.chunks)} chunks; "
    )
    assert summary.message_count == 800


def test_interrupted_recording_is_readable(tmp_path):
    bag = BagWriter(tmp_path / "live", chunk_size=1024).open()
    for i in range(200):
        bag.write("/turtle1/pose", Pose(x=float(i)), T0 + i * 0.016)
    # the process dies here: no index, the file keeps its .active name
    active = tmp_path / "live.bag.active"
    copy = tmp_path / "copy.bag.active"
    copy.write_bytes(active.read_bytes())
    bag.close()
    with pytest.raises(BagNotFoundError, match="copy.bag.active"):
        summarize(tmp_path / "copy.bag")
    summary = summarize(copy)
    assert not summary.indexed
    xs = [m.msg.x for m in read_messages(copy)]
    assert 0 < len(xs) < 200  # the chunks flushed before the crash
    assert xs == [float(i) for i in range(len(xs))]
    assert summary.message_count == len(xs)


def test_truncated_bag_recovers_what_is_readable(tmp_path):
    path = _write_sample(tmp_path / "a.bag", n=100)
    data = path.read_bytes()
    cut = tmp_path / "cut.bag"
    cut.write_bytes(data[: len(data) // 2])
    summary = summarize(cut)
    assert summary.damage and "cut short" in summary.damage
    messages = list(read_messages(cut))
    assert 50 < len(messages) < 200
    assert "recovered what was readable" in format_info(summary)


def test_corrupt_index_falls_back_to_scan(tmp_path):
    path = _write_sample(tmp_path / "a.bag", n=20)
    data = bytearray(path.read_bytes())
    data[-40:] = b"\xff" * 40  # smash the end of the index
    path.write_bytes(bytes(data))
    assert len(list(read_messages(path))) == 40


def test_bad_files_give_one_line_errors(tmp_path):
    with pytest.raises(BagNotFoundError, match="does not exist"):
        summarize(tmp_path / "nope.bag")
    empty = tmp_path / "empty.bag"
    empty.write_bytes(b"")
    with pytest.raises(BagDamagedError, match="empty"):
        summarize(empty)
    text = tmp_path / "notes.bag"
    text.write_text("hello\n")
    with pytest.raises(BagFormatError, match="not a ROS bag"):
        summarize(text)
    old = tmp_path / "old.bag"
    old.write_bytes(b"#ROSBAG V1.2\n" + b"\0" * 20)
    with pytest.raises(BagFormatError, match="1.2 is not supported"):
        summarize(old)
    garbage = tmp_path / "garbage.bag"
    garbage.write_bytes(b"#ROSBAG V2.0\n" + b"\x05\x00\x00\x00abc")
    with pytest.raises(BagDamagedError, match="header is unreadable"):
        summarize(garbage)


def test_unwritable_paths(tmp_path):
    with pytest.raises(BagWriteError, match="directory does not exist") as info:
        BagWriter(tmp_path / "missing" / "x.bag").open()
    assert "create" in info.value.one_line()
    afile = tmp_path / "afile"
    afile.write_text("")
    with pytest.raises(BagWriteError):
        BagWriter(afile / "x.bag").open()
    with pytest.raises(BagWriteError, match="unknown compression"):
        BagWriter(tmp_path / "x.bag", compression="zip")


def _index_pos(data: bytes) -> int:
    at = data.index(b"index_pos=") + len(b"index_pos=")
    return int.from_bytes(data[at : at + 8], "little")


def test_recording_killed_while_writing_a_chunk_out_is_read_up_to_it(tmp_path):
    """A chunk goes where the index was; killed meanwhile, the file is scanned to the damage."""
    bag = BagWriter(tmp_path / "live", chunk_seconds=60.0).open()
    for i in range(10):
        bag.write("/turtle1/pose", Pose(x=float(i)), T0 + i)
    bag.flush()
    before = bag.active_path.read_bytes()  # indexed: chunk 1, then the index
    for i in range(10, 20):
        bag.write("/turtle1/pose", Pose(x=float(i)), T0 + i)
    bag.flush()
    after = bag.active_path.read_bytes()  # chunk 1, chunk 2, then the new index
    bag.close()
    end = _index_pos(before)
    assert summarize(tmp_path / "live.bag").message_count == 20
    at = before.index(b"index_pos=") + len(b"index_pos=")
    unindexed = before[:at] + bytes(8) + before[at + 8 : end]  # index_pos=0, as while writing
    chunk_end = _index_pos(after)
    for written, expected in ((40, 10), (chunk_end - end, 20)):
        killed = tmp_path / f"killed{written}.bag.active"
        # part of chunk 2 written over the old index, the rest of which is still there
        killed.write_bytes(unindexed + after[end : end + written] + before[end + written :])
        summary = summarize(killed)
        assert not summary.indexed
        assert [m.msg.x for m in read_messages(killed)] == [float(i) for i in range(expected)]


def test_a_closed_writer_refuses_more_messages(tmp_path):
    bag = BagWriter(tmp_path / "done")
    bag.write("/turtle1/pose", Pose(x=1.0), T0)  # opens on first use
    bag.close()
    with pytest.raises(BagWriteError, match="closed"):
        bag.write("/turtle1/pose", Pose(x=2.0), T0 + 1)
    assert summarize(tmp_path / "done.bag").message_count == 1
