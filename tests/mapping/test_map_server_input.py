"""map_server's bad input: one error line naming the file and the key, exit status 1.

The texts are map_server's own, from ros-planning/navigation, noetic-devel,
``map_server/src/main.cpp`` ``MapServer::loadMapFromYaml``: "Map_server could not
open %s.", "The map does not contain a resolution tag or it is invalid." (and
negate, occupied_thresh, free_thresh, origin, image alike), "Invalid mode tag
\\"%s\\".", "The image tag cannot be an empty string."; ``image_loader.cpp``
``loadMapFromFile``: "failed to open image file \\"%s\\": ..."; ``main``: the usage
for anything but 1 or 2 arguments. Keys are converted as yaml-cpp converts them
(``node.as<double>()``, ``as<int>()``, ``as<std::string>()``): a missing mode is
trinary, a number must be the whole scalar. (On Noetic, yaml-cpp 0.6 throws
``InvalidNode``/``BadConversion`` where main.cpp catches ``InvalidScalar``, so the
real node aborts with a C++ exception instead of printing these lines; the lines
printed here are the ones main.cpp means to print.)
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.cli import main as cli_main
from workbench.mapping.map_server_yaml import read_map_yaml, yaml_double, yaml_int
from workbench.mapping.pgm import write_pgm

GOOD = {
    "image": "m.pgm",
    "resolution": "0.05",
    "origin": "[0.0, 0.0, 0.0]",
    "negate": "0",
    "occupied_thresh": "0.65",
    "free_thresh": "0.196",
}


def _yaml(tmp_path, **changes):
    keys = dict(GOOD)
    for key, value in changes.items():
        if value is None:
            keys.pop(key)
        else:
            keys[key] = value
    write_pgm(tmp_path / "m.pgm", np.full((2, 2), 254, dtype=np.uint8))
    path = tmp_path / "m.yaml"
    path.write_text("".join(f"{key}: {value}\n" for key, value in keys.items()))
    return path


def _run(capsys, *args) -> tuple[int, list[str]]:
    status = cli_main(["run", "map_server", "map_server", *map(str, args)])
    captured = capsys.readouterr()
    assert "Traceback" not in captured.err
    return status, captured.err.strip().splitlines()


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"resolution": None}, "The map does not contain a resolution tag or it is invalid."),
        ({"resolution": "abc"}, "The map does not contain a resolution tag or it is invalid."),
        ({"resolution": "~"}, "The map does not contain a resolution tag or it is invalid."),
        ({"resolution": "0.05 m"}, "The map does not contain a resolution tag or it is invalid."),
        ({"negate": "0.5"}, "The map does not contain a negate tag or it is invalid."),
        ({"negate": "true"}, "The map does not contain a negate tag or it is invalid."),
        ({"occupied_thresh": None}, "The map does not contain an occupied_thresh tag or it"),
        ({"free_thresh": "[0.1]"}, "The map does not contain a free_thresh tag or it is invalid."),
        ({"mode": "fancy"}, 'Invalid mode tag "fancy".'),
        ({"mode": "yes"}, 'Invalid mode tag "yes".'),
        ({"origin": "[1.0, 2.0]"}, "The map does not contain an origin tag or it is invalid."),
        ({"origin": "5"}, "The map does not contain an origin tag or it is invalid."),
        ({"origin": "[0, zero, 0]"}, "The map does not contain an origin tag or it is invalid."),
        ({"image": None}, "The map does not contain an image tag or it is invalid."),
        ({"image": '""'}, "The image tag cannot be an empty string."),
    ],
)
def test_bad_key_is_one_line_naming_file_and_key(tmp_path, capsys, changes, message):
    path = _yaml(tmp_path, **changes)
    status, lines = _run(capsys, path)
    assert status == 1
    assert len(lines) == 1
    assert lines[0].startswith(f"workbench run: error: {path}: {message}")


def test_missing_yaml_and_bad_yaml(tmp_path, capsys):
    status, lines = _run(capsys, tmp_path / "nope.yaml")
    assert status == 1
    assert lines == [
        f"workbench run: error: Map_server could not open {tmp_path / 'nope.yaml'}. (no such file)"
    ]
    broken = tmp_path / "broken.yaml"
    broken.write_text("resolution: [0.05\nnegate: 0\n")
    status, lines = _run(capsys, broken)
    assert status == 1 and len(lines) == 1
    assert lines[0].startswith(f"workbench run: error: {broken}:") and "invalid YAML" in lines[0]
    empty = tmp_path / "empty.yaml"
    empty.write_text("")
    assert _run(capsys, empty) == (
        1,
        [
            f"workbench run: error: {empty}: "
            "The map does not contain a resolution tag or it is invalid."
        ],
    )


def test_missing_or_unreadable_image(tmp_path, capsys):
    path = _yaml(tmp_path, image="gone.pgm")
    status, lines = _run(capsys, path)
    assert status == 1
    assert lines == [
        f'workbench run: error: failed to open image file "{tmp_path / "gone.pgm"}": '
        "map image not found"
    ]
    (tmp_path / "text.png").write_text("not an image")
    status, lines = _run(capsys, _yaml(tmp_path, image="text.png"))
    assert status == 1 and len(lines) == 1
    assert f'failed to open image file "{tmp_path / "text.png"}": not an image' in lines[0]


def test_wrong_number_of_arguments_is_the_usage(capsys):
    for args in ([], ["a", "b", "c"]):
        status, lines = _run(capsys, *args)
        assert status == 1 and len(lines) == 1
        assert "map_server takes 1 or 2 arguments" in lines[0]
        assert "USAGE: map_server <map.yaml>" in lines[0]


def test_keys_convert_as_yaml_cpp_converts_them(tmp_path):
    meta = read_map_yaml(
        _yaml(
            tmp_path,
            resolution="5e-2",  # a string to YAML 1.1, a double to yaml-cpp
            negate="0x1",  # C++ streams read the base from the prefix
            origin="[1, -2.5, .5, 99]",  # extra items are ignored
            mode="[scale]",  # not a scalar: trinary
        )
    )
    assert meta.resolution == 0.05 and meta.negate is True and meta.mode == "trinary"
    assert meta.origin == (1.0, -2.5, 0.5)
    assert meta.image == tmp_path / "m.pgm"
    assert yaml_double(None) is None
    assert math.isinf(_double(".inf")) and math.isnan(_double(".NaN"))
    assert _double("inf") is None and _double("true") is None and _double("1e") is None
    assert (_int("010"), _int("-7"), _int("08"), _int("1.0")) == (8, -7, None, None)
    assert _int("2147483648") is None


def test_relative_image_is_joined_to_the_yamls_directory(tmp_path, monkeypatch):
    _yaml(tmp_path)
    monkeypatch.chdir(tmp_path)
    assert str(read_map_yaml("m.yaml").image) == "m.pgm"
    assert read_map_yaml(tmp_path / "m.yaml").image == tmp_path / "m.pgm"
    absolute = _yaml(tmp_path, image=str(tmp_path / "m.pgm"))
    assert read_map_yaml(absolute).image == tmp_path / "m.pgm"


def _double(text: str) -> float | None:
    import yaml

    return yaml_double(yaml.compose(f"v: {text}").value[0][1])


def _int(text: str) -> int | None:
    import yaml

    return yaml_int(yaml.compose(f"v: {text}").value[0][1])
