"""map_server maps: saving as map_saver and loading as map_server.

Matched against ros-planning/navigation, map_server (noetic branch):

* ``src/map_saver.cpp`` (MapGenerator::mapCallback): writes ``P5`` with the
  comment ``# CREATOR: ...``, ``width height``, ``255``; rows from the top
  (``i = x + (height - y - 1) * width``); a cell ``0 <= v <= threshold_free``
  (default 25) is 254, ``v >= threshold_occupied`` (default 65) is 0, all
  else 205; the YAML is ``image/resolution/origin [x, y, yaw]/negate: 0/
  occupied_thresh: 0.65/free_thresh: 0.196``.
* ``src/image_loader.cpp`` (loadMapFromFile): ``occ = (255 - mean) / 255``
  (mean inverted first when ``negate``); ``occ > occupied_thresh`` -> 100,
  ``occ < free_thresh`` -> 0, else -1 (trinary) or ``1 + 98 * ratio`` (scale,
  unless alpha < 1), raw copies the value; image row j is map row h-1-j.
* ``src/main.cpp``: every key but ``mode`` is required; a relative ``image``
  is resolved against the YAML's directory.
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import GridMap, MapFileError, load_map, read_map_metadata, save_map
from workbench.mapping.mapfile import map_to_pixels
from workbench.mapping.pgm import write_pgm


def _write_yaml(path, image="m.pgm", **overrides):
    keys = {
        "image": image,
        "resolution": 0.05,
        "origin": "[-1.0, -2.0, 0.0]",
        "negate": 0,
        "occupied_thresh": 0.65,
        "free_thresh": 0.196,
    }
    keys.update(overrides)
    text = "".join(f"{k}: {v}\n" for k, v in keys.items() if v is not None)
    path.write_text(text)
    return path


def test_save_then_load_reproduces_map_saver_thresholds_at_their_edges(tmp_path):
    values = np.array([[-1, 0, 1, 24, 25, 26], [50, 64, 65, 66, 99, 100]], dtype=np.int8)
    grid = GridMap(values, 0.05, (-3.5, 2.25, 0.0))
    pgm, yaml_path = save_map(grid, tmp_path / "mymap")
    loaded = load_map(yaml_path)
    # map_saver: [0, 25] free, [65, 100] occupied, everything else unknown.
    expected = np.array([[-1, 0, 0, 0, 0, -1], [-1, -1, 100, 100, 100, 100]], dtype=np.int8)
    np.testing.assert_array_equal(loaded.data, expected)
    np.testing.assert_array_equal(loaded.data, grid.trinary().data)
    assert loaded.resolution == pytest.approx(0.05)
    np.testing.assert_allclose(loaded.origin, [-3.5, 2.25, 0.0])
    # A saved-and-reloaded trinary map survives a second round trip unchanged.
    _, again = save_map(loaded, tmp_path / "again")
    np.testing.assert_array_equal(load_map(again).data, loaded.data)


def test_saved_files_are_byte_for_byte_what_map_saver_writes(tmp_path):
    grid = GridMap(np.array([[0, 100], [-1, 30]], dtype=np.int8), 0.1, (1.0, 2.0, 0.5))
    pgm, yaml_path = save_map(grid, tmp_path / "mymap")
    raw = pgm.read_bytes()
    assert raw.startswith(b"P5\n# CREATOR: ")
    header, pixels = raw.rsplit(b"\n255\n", 1)
    assert header.endswith(b"\n2 2")
    # Rows top-down: the last map row ([-1, 30]) comes first; both are unknown (205).
    assert list(pixels) == [205, 205, 254, 0]
    assert yaml_path.read_text() == (
        "image: mymap.pgm\nresolution: 0.100000\norigin: [1.000000, 2.000000, 0.500000]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
    )


@pytest.mark.parametrize(
    ("pixel", "expected"),
    [
        (0, 100),
        (89, 100),  # occ = 166/255 = 0.651 > 0.65
        (90, -1),  # occ = 165/255 = 0.647
        (205, -1),  # occ = 50/255 = 0.19608, not < 0.196
        (206, 0),  # occ = 49/255 = 0.192
        (254, 0),
        (255, 0),
    ],
)
def test_trinary_loading_at_the_pixel_thresholds(tmp_path, pixel, expected):
    write_pgm(tmp_path / "m.pgm", np.full((1, 1), pixel, dtype=np.uint8))
    loaded = load_map(_write_yaml(tmp_path / "m.yaml"))
    assert int(loaded.data[0, 0]) == expected


def test_negate_scale_and_raw_modes(tmp_path):
    pixels = np.array([[0, 90, 150, 255]], dtype=np.uint8)
    write_pgm(tmp_path / "m.pgm", pixels)
    negated = load_map(_write_yaml(tmp_path / "n.yaml", negate=1))
    assert negated.data.tolist() == [[0, -1, -1, 100]]
    scaled = load_map(_write_yaml(tmp_path / "s.yaml", mode="scale"))
    # 90: occ = 0.6471 -> 1 + 98 * (0.6471 - 0.196) / (0.65 - 0.196) = 98.36 -> 98 (truncated);
    # 150: occ = 0.4118 -> 47.58 -> 47 (map_server 1.17.1's 1 + 98 * ratio)
    assert scaled.data.tolist() == [[100, 98, 47, 0]]
    raw = load_map(_write_yaml(tmp_path / "r.yaml", mode="raw"))
    # The cell is a signed char holding the pixel value (255 wraps to -1 as in the message).
    assert raw.data.tolist() == [[0, 90, np.int8(np.uint8(150).view(np.int8)), -1]]


def test_image_rows_are_flipped_so_cell_zero_is_bottom_left(tmp_path):
    pixels = np.array([[0, 254], [254, 254]], dtype=np.uint8)  # top-left pixel occupied
    write_pgm(tmp_path / "m.pgm", pixels)
    loaded = load_map(_write_yaml(tmp_path / "m.yaml"))
    assert loaded.data[1, 0] == 100  # top row of the image = last map row
    assert loaded.data[0, 0] == 0
    np.testing.assert_array_equal(map_to_pixels(loaded), pixels)


def test_png_images_load_as_map_server_does(tmp_path):
    from PIL import Image

    Image.fromarray(np.array([[0, 254]], dtype=np.uint8)).save(tmp_path / "m.png")
    loaded = load_map(_write_yaml(tmp_path / "m.yaml", image="m.png"))
    assert loaded.data.tolist() == [[100, 0]]


@pytest.mark.parametrize(
    "key", ["image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh"]
)
def test_missing_yaml_key_is_a_one_line_error_naming_it(tmp_path, key):
    write_pgm(tmp_path / "m.pgm", np.zeros((1, 1), dtype=np.uint8))
    path = _write_yaml(tmp_path / "m.yaml", **{key: None})
    with pytest.raises(MapFileError) as info:
        load_map(path)
    text = info.value.one_line()
    assert f"'{key}'" in text and str(path) in text and "\n" not in text


def test_bad_yaml_values_and_syntax(tmp_path):
    write_pgm(tmp_path / "m.pgm", np.zeros((1, 1), dtype=np.uint8))
    with pytest.raises(MapFileError, match="origin"):
        load_map(_write_yaml(tmp_path / "a.yaml", origin="[1, 2]"))
    with pytest.raises(MapFileError, match="mode"):
        load_map(_write_yaml(tmp_path / "b.yaml", mode="fancy"))
    with pytest.raises(MapFileError, match="resolution"):
        load_map(_write_yaml(tmp_path / "c.yaml", resolution="abc"))
    (tmp_path / "d.yaml").write_text("image: m.pgm\nresolution: [0.05\n")
    with pytest.raises(MapFileError, match="not valid YAML") as info:
        load_map(tmp_path / "d.yaml")
    assert info.value.line is not None


def test_missing_image_and_non_image_are_clear_errors(tmp_path):
    with pytest.raises(MapFileError, match="map image not found") as info:
        load_map(_write_yaml(tmp_path / "m.yaml", image="nothere.pgm"))
    assert "nothere.pgm" in info.value.one_line()
    (tmp_path / "text.pgm").write_text("this is not an image\n")
    with pytest.raises(MapFileError, match="not an image"):
        load_map(_write_yaml(tmp_path / "t.yaml", image="text.pgm"))
    (tmp_path / "short.pgm").write_bytes(b"P5\n4 4\n255\n\x00\x00")
    with pytest.raises(MapFileError, match="truncated"):
        load_map(_write_yaml(tmp_path / "s.yaml", image="short.pgm"))
    with pytest.raises(MapFileError, match="not found"):
        read_map_metadata(tmp_path / "absent.yaml")


def test_absolute_image_path_is_used_as_is(tmp_path):
    write_pgm(tmp_path / "abs.pgm", np.full((2, 3), 254, dtype=np.uint8))
    sub = tmp_path / "sub"
    sub.mkdir()
    meta = read_map_metadata(_write_yaml(sub / "m.yaml", image=str(tmp_path / "abs.pgm")))
    assert meta.image == tmp_path / "abs.pgm"
    assert load_map(sub / "m.yaml").data.shape == (2, 3)


def test_writing_to_an_unwritable_place_is_a_one_line_error(tmp_path):
    grid = GridMap(np.zeros((2, 2), dtype=np.int8), 0.05)
    with pytest.raises(MapFileError, match="does not exist"):
        save_map(grid, tmp_path / "no" / "such" / "dir" / "map")
    # A directory where the image should go cannot be opened for writing, even by root.
    (tmp_path / "blocked.pgm").mkdir()
    with pytest.raises(MapFileError, match="cannot write map image") as info:
        save_map(grid, tmp_path / "blocked")
    assert "blocked.pgm" in info.value.one_line()


def test_example_maps_in_the_mapping_folder_reload_unchanged(tmp_path):
    from workbench.paths import mapping_dir

    for name in ("demo_rooms", "intel_lab"):
        grid = load_map(mapping_dir() / f"{name}.yaml")
        assert set(np.unique(grid.data)) <= {-1, 0, 100}
        assert (grid.data == 100).sum() > 500 and (grid.data == 0).sum() > 5000
        _, again = save_map(grid, tmp_path / name)
        np.testing.assert_array_equal(load_map(again).data, grid.data)
