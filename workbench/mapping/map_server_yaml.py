"""Reading a map YAML the way ``map_server`` (ROS Noetic, map_server 1.17) reads it.

``MapServer::loadMapFromYaml`` (``map_server/src/main.cpp``) converts the keys
with yaml-cpp, in this order, and stops at the first one that is missing or
does not convert, with its own error text:

* ``resolution`` (double), ``negate`` (int), ``occupied_thresh`` and
  ``free_thresh`` (double): "The map does not contain a resolution tag or it is
  invalid." and so on;
* ``mode`` (string): missing or not a scalar means ``trinary``; another word
  than ``trinary``/``scale``/``raw`` is "Invalid mode tag \"...\".";
* ``origin``: its first three items as doubles (more are ignored);
* ``image`` (string): empty is "The image tag cannot be an empty string.";
  a path not starting with ``/`` is joined to the YAML's directory.

Scalars convert as yaml-cpp converts them: a number must be the whole scalar
(``0.05``, ``5e-2``, ``.inf``; not ``true`` or ``0.05 m``), an int takes a
``0x`` (hex) or leading ``0`` (octal) prefix as C++ streams do, and a null
(``~``, ``null``, empty) is no value. The YAML is read as text nodes (no
YAML 1.1 guessing), so ``mode: yes`` is the word ``yes`` as in yaml-cpp.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

import yaml

from workbench.limits import MAX_TEXT_FILE_BYTES, check_regular_file, check_yaml
from workbench.mapping.errors import MapFileError
from workbench.mapping.mapfile import MODES, MapMetadata

_DOUBLE = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_INFINITY = {".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF"}
_NEGATIVE_INFINITY = {"-.inf", "-.Inf", "-.INF"}
_NAN = {".nan", ".NaN", ".NAN"}
_INT = re.compile(r"([+-]?)(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9]\d*)")
_INT_MIN, _INT_MAX = -(2**31), 2**31 - 1


def _missing(key: str) -> str:
    article = "an" if key[0] in "aeiou" else "a"
    return f"The map does not contain {article} {key} tag or it is invalid."


def _scalar(node: yaml.Node | None) -> str | None:
    """The text of a non-null scalar node, else None (yaml-cpp's ``IsScalar``)."""
    if not isinstance(node, yaml.ScalarNode) or node.tag.endswith(":null"):
        return None
    return str(node.value)


def yaml_double(node: yaml.Node | None) -> float | None:
    """The node as yaml-cpp's ``as<double>()`` reads it; None when that throws."""
    text = _scalar(node)
    if text is None:
        return None
    if _DOUBLE.fullmatch(text):
        value = float(text)
        return value if math.isfinite(value) else None  # out of range fails the stream
    if text in _INFINITY:
        return math.inf
    if text in _NEGATIVE_INFINITY:
        return -math.inf
    if text in _NAN:
        return math.nan
    return None


def yaml_int(node: yaml.Node | None) -> int | None:
    """The node as yaml-cpp's ``as<int>()`` reads it (base from the prefix); None if it throws."""
    text = _scalar(node)
    match = _INT.fullmatch(text) if text is not None else None
    if match is None:
        return None
    sign, digits = match.groups()
    if digits[:2] in ("0x", "0X"):
        value = int(digits[2:], 16)
    elif digits.startswith("0"):
        value = int(digits, 8)
    else:
        value = int(digits)
    value = -value if sign == "-" else value
    return value if _INT_MIN <= value <= _INT_MAX else None


def _lookup(mapping: yaml.Node | None, key: str) -> yaml.Node | None:
    if not isinstance(mapping, yaml.MappingNode):
        return None
    for key_node, value_node in mapping.value:
        if isinstance(key_node, yaml.ScalarNode) and key_node.value == key:
            return value_node
    return None


def _item(sequence: yaml.Node | None, index: int) -> yaml.Node | None:
    if isinstance(sequence, yaml.SequenceNode) and index < len(sequence.value):
        return sequence.value[index]
    return None


def _compose(path: Path) -> yaml.Node | None:
    try:
        if path.exists() and not path.is_dir():  # a FIFO would block, /dev/zero not end
            check_regular_file(path, "map YAML", MapFileError)
            if path.stat().st_size > MAX_TEXT_FILE_BYTES:
                raise MapFileError("the map YAML is larger than 16 MiB", path=path)
        text = path.read_text()
    except FileNotFoundError:
        raise MapFileError(f"Map_server could not open {path}.", hint="no such file") from None
    except IsADirectoryError:
        raise MapFileError(f"Map_server could not open {path}.", hint="it is a directory") from None
    except OSError as exc:
        raise MapFileError(f"Map_server could not open {path}.", hint=exc.strerror) from None
    except UnicodeDecodeError:
        raise MapFileError("the map YAML is not text", path=path) from None
    try:
        check_yaml(text, "the map YAML", error=MapFileError, path=path)  # depth, aliases
    except MapFileError as error:
        if "is not valid YAML" not in error.message:
            raise  # past a bound; plain syntax errors get map_server's wording below
    try:
        return yaml.compose(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = mark.line + 1 if mark is not None else None
        problem = getattr(exc, "problem", None) or "invalid YAML"
        raise MapFileError(f"invalid YAML: {problem}", path=path, line=line) from None


def _number(doc: yaml.Node | None, key: str, path: Path) -> float:
    value = yaml_double(_lookup(doc, key))
    if value is None:
        raise MapFileError(_missing(key), path=path)
    if not math.isfinite(value):
        raise MapFileError(f"the {key} {value} is not finite", path=path)
    return value


def _mode(doc: yaml.Node | None, path: Path) -> str:
    text = _scalar(_lookup(doc, "mode"))
    if text is None:
        return "trinary"  # ROS_DEBUG: "... assuming Trinary"
    if text not in MODES:
        raise MapFileError(
            f'Invalid mode tag "{text}".', path=path, hint="use trinary, scale or raw"
        )
    return text


def read_map_yaml(path: str | os.PathLike[str]) -> MapMetadata:
    """Read a map YAML as ``map_server MAP.yaml`` does.

    The image path is joined to the YAML's directory as map_server joins it
    (``dirname(yaml) / image``, unchanged when the YAML has no directory part).

    Raises:
        MapFileError: The file cannot be opened, is not YAML, or a key is missing or
            invalid; the message is map_server's for that key.
    """
    path = Path(path)
    doc = _compose(path)
    resolution = _number(doc, "resolution", path)
    negate = yaml_int(_lookup(doc, "negate"))
    if negate is None:
        raise MapFileError(_missing("negate"), path=path)
    occupied = _number(doc, "occupied_thresh", path)
    free = _number(doc, "free_thresh", path)
    mode = _mode(doc, path)
    origin_node = _lookup(doc, "origin")
    origin = tuple(yaml_double(_item(origin_node, index)) for index in range(3))
    if any(value is None for value in origin):
        raise MapFileError(_missing("origin"), path=path, hint="write it as [x, y, yaw]")
    if not all(math.isfinite(value) for value in origin if value is not None):
        # map_server takes nan/inf and publishes a map no one can place: refuse it here
        raise MapFileError(
            f"the origin {list(origin)} is not finite", path=path, hint="write it as [x, y, yaw]"
        )
    image = _scalar(_lookup(doc, "image"))
    if image is None:
        raise MapFileError(_missing("image"), path=path)
    if not image:
        raise MapFileError("The image tag cannot be an empty string.", path=path)
    if not image.startswith("/"):
        directory = os.path.dirname(os.fspath(path))
        image = os.path.join(directory, image) if directory else image
    x, y, yaw = (float(value) for value in origin if value is not None)
    return MapMetadata(
        path, Path(image), resolution, (x, y, yaw), negate != 0, occupied, free, mode
    )


__all__ = ["read_map_yaml", "yaml_double", "yaml_int"]
