"""The map_server node on an in-process bus, matched to ROS Noetic's map_server 1.17.

Read from ros-planning/navigation, branch noetic-devel (map_server 1.17.3):

* ``src/main.cpp`` ``MapServer::MapServer``: ``~frame_id`` defaults to ``map``;
  services ``static_map`` (nav_msgs/GetMap) and ``change_map`` (nav_msgs/LoadMap);
  latched publishers ``map_metadata`` and ``map`` with queue 1.
  ``loadMapFromValues``: logs ``Loading map from image "%s"`` and ``Read a %d X %d
  map @ %.3lf m/cell``; ``header.frame_id = frame_id_``, ``header.stamp`` and
  ``info.map_load_time`` now. ``mapCallback`` logs ``Sending map``;
  ``changeMapCallback`` answers ``RESULT_SUCCESS`` or ``RESULT_UNDEFINED_FAILURE``.
  ``loadMapFromParams`` (deprecated ``map_server IMAGE RES``): ``~negate`` 0,
  ``~occupied_thresh`` 0.65, ``~free_thresh`` 0.196, origin 0, trinary.
* ``src/image_loader.cpp`` ``loadMapFromFile``: ``setEulerZYX(origin[2], 0, 0)``
  for the orientation; occ > occ_th is 100, occ < free_th is 0, else -1 (trinary)
  or ``1 + 98 * ratio`` (scale); raw copies the mean.
* ``test/utest.cpp`` ``testMapMode``: a 256-pixel grey spectrum gives 90 cells of
  100, 26 of 0 and 140 of -1 (trinary, free_th 0.1); 140 scaled cells in 1..99;
  every raw value once. ``test/rtest.cpp``: the map by service and by topic, frame
  ``map``, and ``change_map`` answering 0.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from workbench.bus import Bus, Node
from workbench.mapping import load_map
from workbench.mapping.map_server_node import MapServer, load_image
from workbench.mapping.mapfile import MapMetadata
from workbench.mapping.pgm import write_pgm
from workbench.msgs.nav_msgs import GetMap, LoadMap, MapMetaData, OccupancyGrid

#: A 2 x 3 image, rows top-down: occupied, free, unknown / unknown (100: occ 0.608),
#: free (250), free (210: occ 0.176 < 0.196).
PIXELS = np.array([[0, 254, 205], [100, 250, 210]], dtype=np.uint8)
#: The cells map_server makes of it: row 0 is the image's bottom row.
CELLS = [-1, 0, 0, 100, 0, -1]


def write_map(folder: Path, name: str = "m", pixels=PIXELS, **keys) -> Path:
    write_pgm(folder / f"{name}.pgm", pixels)
    values = {
        "image": f"{name}.pgm",
        "resolution": "0.05",
        "origin": "[-1.5, 2.25, 0.3]",
        "negate": "0",
        "occupied_thresh": "0.65",
        "free_thresh": "0.196",
    }
    values.update({key: str(value) for key, value in keys.items()})
    path = folder / f"{name}.yaml"
    path.write_text("".join(f"{key}: {value}\n" for key, value in values.items()))
    return path


@pytest.fixture
def bus():
    bus = Bus(threaded=False)
    yield bus
    bus.shutdown()


def _drain(bus: Bus) -> None:
    while bus.spin_once(0.0):
        pass


def test_publishes_latched_map_and_metadata_with_the_originals_names(bus, tmp_path, capsys):
    server_node = Node("map_server", bus=bus, disable_rosout=True)
    MapServer(server_node, str(write_map(tmp_path)))
    out = capsys.readouterr().out
    assert f'Loading map from image "{tmp_path / "m.pgm"}"' in out
    assert "Read a 3 X 2 map @ 0.050 m/cell" in out

    # Subscribers that come later still get both (latched).
    user = Node("user", bus=bus, disable_rosout=True)
    maps, metas = [], []
    user.create_subscription("/map", OccupancyGrid, maps.append)
    user.create_subscription("/map_metadata", MapMetaData, metas.append)
    _drain(bus)
    assert len(maps) == 1 and len(metas) == 1
    grid = maps[0]
    assert grid.header.frame_id == "map"
    assert (grid.info.width, grid.info.height) == (3, 2)
    assert grid.info.resolution == pytest.approx(0.05)
    assert grid.data.tolist() == CELLS
    assert (grid.info.origin.position.x, grid.info.origin.position.y) == (-1.5, 2.25)
    q = grid.info.origin.orientation
    assert (q.x, q.y, q.z, q.w) == pytest.approx((0, 0, math.sin(0.15), math.cos(0.15)))
    assert grid.header.stamp == grid.info.map_load_time
    assert metas[0] == grid.info

    graph = bus.graph()
    assert graph.topics["/map"].type == "nav_msgs/OccupancyGrid"
    assert graph.topics["/map_metadata"].type == "nav_msgs/MapMetaData"
    assert graph.services["/static_map"].type == "nav_msgs/GetMap"
    assert graph.services["/change_map"].type == "nav_msgs/LoadMap"


def test_static_map_returns_the_map_in_the_private_frame_id(bus, tmp_path, capsys):
    node = Node("map_server", bus=bus, disable_rosout=True, argv=["_frame_id:=world"])
    MapServer(node, str(write_map(tmp_path)))
    user = Node("user", bus=bus, disable_rosout=True)
    response = user.create_client("/static_map", GetMap).call(GetMap.Request())
    assert response.map.header.frame_id == "world"
    assert response.map.data.tolist() == CELLS
    assert "Sending map" in capsys.readouterr().out


def test_change_map_publishes_the_new_map_and_keeps_the_old_one_on_failure(bus, tmp_path):
    node = Node("map_server", bus=bus, disable_rosout=True)
    MapServer(node, str(write_map(tmp_path)))
    other = write_map(tmp_path, "other", np.zeros((4, 5), dtype=np.uint8), resolution="0.1")
    user = Node("user", bus=bus, disable_rosout=True)
    maps: list = []
    user.create_subscription("/map", OccupancyGrid, maps.append)
    change = user.create_client("/change_map", LoadMap)

    answer = change.call(LoadMap.Request(map_url=str(other)))
    assert answer.result == LoadMap.Response.RESULT_SUCCESS == 0
    _drain(bus)
    assert (maps[-1].info.width, maps[-1].info.height) == (5, 4)
    assert set(maps[-1].data.tolist()) == {100}

    answer = change.call(LoadMap.Request(map_url=str(tmp_path / "missing.yaml")))
    assert answer.result == LoadMap.Response.RESULT_UNDEFINED_FAILURE == 255
    served = user.create_client("/static_map", GetMap).call(GetMap.Request()).map
    assert (served.info.width, served.info.height) == (5, 4)


def test_deprecated_image_and_resolution_form_reads_private_parameters(bus, tmp_path):
    write_pgm(tmp_path / "m.pgm", PIXELS)
    node = Node("map_server", bus=bus, disable_rosout=True, argv=["_negate:=1"])
    server = MapServer(node, str(tmp_path / "m.pgm"), 0.25)
    grid = server.map
    assert grid.info.resolution == 0.25
    assert grid.info.origin.position.x == 0.0 and grid.info.origin.orientation.w == 1.0
    # negate: occ = c / 255, so 205 (0.80) is occupied, 0 free, 100 (0.39) unknown.
    assert grid.data.tolist() == [-1, 100, 100, 0, 100, 100]


def spectrum_meta(tmp_path: Path, mode: str) -> MapMetadata:
    """utest.cpp's spectrum: every grey level once (16 x 16), free_th 0.1."""
    write_pgm(tmp_path / "spectrum.pgm", np.arange(256, dtype=np.uint8).reshape(16, 16))
    return MapMetadata(
        tmp_path / "s.yaml", tmp_path / "spectrum.pgm", 0.1, (0, 0, 0), False, 0.65, 0.1, mode
    )


def test_map_modes_count_as_map_servers_own_unit_test(tmp_path):
    counts = np.bincount(
        load_image(spectrum_meta(tmp_path, "trinary")).cells.view(np.uint8).ravel(),
        minlength=256,
    )
    assert (counts[100], counts[0], counts[255]) == (90, 26, 140)
    scale = np.bincount(
        load_image(spectrum_meta(tmp_path, "scale")).cells.view(np.uint8).ravel(),
        minlength=256,
    )
    assert (scale[100], scale[0], scale[1:100].sum()) == (90, 26, 140)
    # 1 + 98 * ratio: the darkest unknown grey (89.25 < 90) is 98, the lightest (229) 1.
    cells = load_image(spectrum_meta(tmp_path, "scale")).cells[::-1].ravel()
    assert (cells[90], cells[229]) == (98, 1)
    raw = np.bincount(
        load_image(spectrum_meta(tmp_path, "raw")).cells.view(np.uint8).ravel(), minlength=256
    )
    assert raw.tolist() == [1] * 256


@pytest.mark.parametrize(
    "keys",
    [
        {},
        {"negate": 1},
        {"mode": "scale"},
        {"mode": "raw", "negate": 1},
        {"occupied_thresh": 0.5, "free_thresh": 0.3},
    ],
)
def test_served_map_agrees_with_load_map(bus, tmp_path, keys):
    pixels = np.arange(0, 256, 8, dtype=np.uint8).reshape(4, 8)
    path = write_map(tmp_path, pixels=pixels, **keys)
    server = MapServer(Node("map_server", bus=bus, disable_rosout=True), str(path))
    expected = load_map(path)
    assert server.map.data.tolist() == expected.flat().tolist()
    assert (server.map.info.width, server.map.info.height) == (expected.width, expected.height)


def test_rgba_image_in_scale_mode_keeps_transparent_pixels_unknown(bus, tmp_path):
    from PIL import Image

    rgba = np.array([[[150, 150, 150, 255], [150, 150, 150, 0]]], dtype=np.uint8)
    Image.fromarray(rgba, "RGBA").save(tmp_path / "m.png")
    path = write_map(tmp_path, mode="scale", image="m.png")
    server = MapServer(Node("map_server", bus=bus, disable_rosout=True), str(path))
    # 150: occ = 0.4118, 1 + 98 * (0.4118 - 0.196) / 0.454 = 47.6 -> 47; alpha 0 stays -1.
    assert server.map.data.tolist() == [47, -1]
    assert load_map(path).flat().tolist() == [47, -1]
