"""The map_saver node on an in-process bus, matched byte for byte to ROS Noetic's map_saver.

Expected files are built here from the rules of ros-planning/navigation,
noetic-devel, ``map_server/src/map_saver.cpp`` (map_server 1.17.3):

* ``MapGenerator::MapGenerator``: logs ``Waiting for the map``, subscribes to
  ``map`` with queue 1.
* ``MapGenerator::mapCallback``: logs ``Received a %d X %d map @ %.3f m/pix``;
  writes ``mapname + ".pgm"`` (logged ``Writing map occupancy data to %s``) as
  ``"P5\\n# CREATOR: map_saver.cpp %.3f m/pix\\n%d %d\\n255\\n"`` then one byte a
  cell, ``i = x + (height - y - 1) * width``: ``0 <= v <= threshold_free`` is 254,
  else ``v >= threshold_occupied`` is 0, else 205; then ``mapname + ".yaml"``
  (logged with the same words) as ``"image: %s\\nresolution: %f\\norigin: [%f, %f,
  %f]\\nnegate: 0\\noccupied_thresh: 0.65\\nfree_thresh: 0.196\\n\\n"`` with the
  yaw from ``tf2::Matrix3x3(q).getEulerYPR``; logs ``Done\\n``.
* ``main``: ``-f`` (default ``map``), ``--occ`` (default 65, atoi, 1..100),
  ``--free`` (default 25, atoi, 0..100), ``threshold_free must be smaller than
  threshold_occupied``; ``-h`` prints the usage; spins until a map was saved.

The round trip saves a map as ROS's map_saver writes it, serves it with
map_server and saves it again: the files are identical, and
``workbench.mapping.load_map`` reads both as the served map.
"""

from __future__ import annotations

import math
import os

import numpy as np
import pytest

from workbench.bus import Bus, Node, set_default_bus
from workbench.cli import main as cli_main
from workbench.errors import MappingError
from workbench.mapping import load_map
from workbench.mapping.map_saver_node import (
    USAGE,
    MapSaver,
    c_atoi,
    parse_arguments,
    save_map_files,
    yaml_text,
    yaw_from_quaternion,
)
from workbench.mapping.map_server_node import MapServer
from workbench.msgs.nav_msgs import OccupancyGrid

#: A 4 x 3 grid, row 0 at the origin, with values at every threshold's edge.
CELLS = [
    [0, 25, 26, -1],
    [64, 65, 100, 101],
    [127, -2, -128, 50],
]
#: map_saver's bytes for it, top row first, default thresholds (free 0..25, occupied >= 65).
PIXELS_DEFAULT = [0, 205, 205, 205, 205, 0, 0, 0, 254, 254, 205, 205]
#: With --occ 50 --free 0.
PIXELS_OCC50_FREE0 = [0, 205, 205, 0, 0, 0, 0, 0, 254, 205, 205, 205]
HEADER = b"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n4 3\n255\n"
YAML = (
    "image: {image}\nresolution: 0.050000\norigin: [1.000000, -2.500000, 0.500000]\n"
    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
)


def make_grid(cells=CELLS, resolution=0.05, x=1.0, y=-2.5, yaw=0.5) -> OccupancyGrid:
    grid = OccupancyGrid()
    grid.header.frame_id = "map"
    grid.info.width, grid.info.height = len(cells[0]), len(cells)
    grid.info.resolution = resolution
    grid.info.origin.position.x, grid.info.origin.position.y = x, y
    q = grid.info.origin.orientation
    q.z, q.w = math.sin(yaw / 2), math.cos(yaw / 2)
    grid.data = np.array(cells, dtype=np.int8).reshape(-1)
    return grid


@pytest.fixture
def bus():
    bus = Bus(threaded=False)
    yield bus
    bus.shutdown()


def _publish(bus: Bus, grid: OccupancyGrid, topic: str = "/map") -> None:
    node = Node("mapper", bus=bus, disable_rosout=True)
    node.create_publisher(topic, OccupancyGrid, 1, latch=True).publish(grid)


def test_writes_map_savers_bytes_and_log_lines(bus, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    saver = MapSaver(Node("map_saver", bus=bus, disable_rosout=True), "mymap")
    assert not saver.saved.is_set()
    _publish(bus, make_grid())
    assert saver.wait(timeout=10)
    assert saver.error is None
    assert (tmp_path / "mymap.pgm").read_bytes() == HEADER + bytes(PIXELS_DEFAULT)
    assert (tmp_path / "mymap.yaml").read_text() == YAML.format(image="mymap.pgm")
    lines = [line.split("]: ", 1)[-1] for line in capsys.readouterr().out.splitlines()]
    assert lines == [
        "Waiting for the map",
        "Received a 4 X 3 map @ 0.050 m/pix",
        "Writing map occupancy data to mymap.pgm",
        "Writing map occupancy data to mymap.yaml",
        "Done",
        "",
    ]


def test_thresholds_and_the_name_as_given(tmp_path):
    base = str(tmp_path / "sub" / "thr")
    os.mkdir(tmp_path / "sub")
    pgm, yaml_path = save_map_files(make_grid(), base, threshold_occupied=50, threshold_free=0)
    assert pgm.read_bytes() == HEADER + bytes(PIXELS_OCC50_FREE0)
    # The YAML's image is the -f name plus .pgm, exactly as given (here absolute).
    assert yaml_path.read_text() == YAML.format(image=base + ".pgm")


def test_remapped_topic_and_only_the_first_map_is_saved(bus, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    node = Node("map_saver", bus=bus, disable_rosout=True, argv=["map:=/slam/map"])
    saver = MapSaver(node, "first")
    _publish(bus, make_grid(), "/slam/map")
    assert saver.wait(timeout=10)
    publisher = Node("late", bus=bus, disable_rosout=True)
    publisher.create_publisher("/slam/map", OccupancyGrid, 1).publish(make_grid(resolution=1.0))
    while bus.spin_once(0.0):
        pass
    assert (tmp_path / "first.pgm").read_bytes().startswith(HEADER)


def test_waits_without_a_map_and_writes_nothing(bus, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    saver = MapSaver(Node("map_saver", bus=bus, disable_rosout=True), "never")
    assert saver.wait(timeout=0.3) is False
    assert list(tmp_path.iterdir()) == []


def test_unwritable_path_is_one_error_naming_the_file(bus, tmp_path):
    target = str(tmp_path / "missing-dir" / "m")
    saver = MapSaver(Node("map_saver", bus=bus, disable_rosout=True), target)
    _publish(bus, make_grid())
    assert saver.wait(timeout=10)
    assert saver.error is not None
    assert saver.error.one_line() == (
        f"Couldn't save map file to {target}.pgm (No such file or directory)"
    )


def test_round_trip_through_map_server_is_byte_identical(bus, tmp_path, monkeypatch):
    """A map as ROS's map_saver writes it, served by map_server, saved again: same bytes."""
    ros_dir, our_dir = tmp_path / "ros", tmp_path / "ours"
    ros_dir.mkdir()
    our_dir.mkdir()
    rng = np.random.default_rng(3)
    pixels = rng.choice(np.array([0, 205, 254], dtype=np.uint8), size=(7, 9))
    pgm = b"P5\n# CREATOR: map_saver.cpp 0.025 m/pix\n9 7\n255\n" + pixels.tobytes()
    yaml_bytes = (
        b"image: map.pgm\nresolution: 0.025000\norigin: [-12.200000, -3.175000, -1.234567]\n"
        b"negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
    )
    (ros_dir / "map.pgm").write_bytes(pgm)
    (ros_dir / "map.yaml").write_bytes(yaml_bytes)

    server = MapServer(Node("map_server", bus=bus, disable_rosout=True), str(ros_dir / "map.yaml"))
    monkeypatch.chdir(our_dir)
    saver = MapSaver(Node("map_saver", bus=bus, disable_rosout=True), "map")
    assert saver.wait(timeout=10) and saver.error is None
    assert (our_dir / "map.pgm").read_bytes() == pgm
    assert (our_dir / "map.yaml").read_bytes() == yaml_bytes
    ours, theirs = load_map(our_dir / "map.yaml"), load_map(ros_dir / "map.yaml")
    assert ours.flat().tolist() == theirs.flat().tolist() == server.map.data.tolist()
    np.testing.assert_allclose(ours.origin, [-12.2, -3.175, -1.234567])


def test_yaw_as_tf2_get_euler_ypr():
    assert yaw_from_quaternion(0, 0, math.sin(0.25), math.cos(0.25)) == pytest.approx(0.5)
    # Angles beyond pi come back wrapped, as ROS writes them.
    assert yaw_from_quaternion(0, 0, math.sin(2.0), math.cos(2.0)) == pytest.approx(4 - 2 * math.pi)
    # An unnormalised quaternion is normalised by setRotation (2 / |q|^2).
    assert yaw_from_quaternion(0, 0, 2 * math.sin(0.25), 2 * math.cos(0.25)) == pytest.approx(0.5)
    # Pitch 90 degrees: the singular case sets the yaw to 0.
    assert yaw_from_quaternion(0, math.sin(math.pi / 4), 0, math.cos(math.pi / 4)) == 0.0


def test_zero_quaternion_writes_nan_yaw_as_glibc_prints_it():
    grid = make_grid()
    grid.info.origin.orientation.z = grid.info.origin.orientation.w = 0.0
    assert "origin: [1.000000, -2.500000, -nan]\n" in yaml_text("m.pgm", grid)


def test_data_of_the_wrong_size_is_an_error(tmp_path):
    grid = make_grid()
    grid.info.width = 5
    with pytest.raises(MappingError, match="holds 12 cells, not width x height = 5 x 3"):
        save_map_files(grid, str(tmp_path / "bad"))


def test_arguments_as_map_saver_reads_them():
    assert parse_arguments([]).mapname == "map"
    options = parse_arguments(["--occ", "70", "-f", "room", "--free", "10"])
    assert (options.mapname, options.threshold_occupied, options.threshold_free) == (
        "room",
        70,
        10,
    )
    assert parse_arguments(["-h", "--bogus"]).show_help
    # atoi: leading digits count, anything else is 0.
    assert (c_atoi("70abc"), c_atoi(" -3"), c_atoi("abc")) == (70, -3, 0)
    assert parse_arguments(["--free", "abc"]).threshold_free == 0
    for args, text in [
        (["--occ", "0"], "threshold_occupied must be between 1 and 100"),
        (["--occ", "abc"], "threshold_occupied must be between 1 and 100"),
        (["--free", "101"], "threshold_free must be between 0 and 100"),
        (["--occ", "30", "--free", "30"], "threshold_free must be smaller than threshold_occupied"),
        (["-f"], "-f needs a value"),
        (["extra"], "unknown argument 'extra'"),
    ]:
        with pytest.raises(MappingError, match=text):
            parse_arguments(args)


@pytest.fixture
def threaded_default_bus():
    bus = Bus(threaded=True)
    set_default_bus(bus)
    yield bus
    set_default_bus(None)
    bus.shutdown()


def test_workbench_run_finds_both_nodes_and_saves(threaded_default_bus, tmp_path, capsys):
    ros_map = tmp_path / "in"
    ros_map.mkdir()
    (ros_map / "m.pgm").write_bytes(HEADER + bytes(PIXELS_DEFAULT))
    (ros_map / "m.yaml").write_text(YAML.format(image="m.pgm"))
    MapServer(Node("map_server", bus=threaded_default_bus), str(ros_map / "m.yaml"))
    out = tmp_path / "out"
    assert cli_main(["run", "map_server", "map_saver", "-f", str(out)]) == 0
    assert out.with_suffix(".pgm").read_bytes() == HEADER + bytes(PIXELS_DEFAULT)
    capsys.readouterr()

    assert cli_main(["run", "map_server", "map_saver", "-f", str(tmp_path / "no" / "m")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [
        f"workbench run: error: Couldn't save map file to {tmp_path / 'no' / 'm'}.pgm "
        "(No such file or directory)"
    ]
    assert cli_main(["run", "map_server", "map_saver", "-h"]) == 0
    assert capsys.readouterr().out == USAGE + "\n"
