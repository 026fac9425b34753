"""Look inside a Meshcat StaticHtml snapshot: which scene paths it draws."""

from __future__ import annotations

import base64
import re
from pathlib import Path

_DATA = re.compile(r'data:application/octet-binary;base64,([A-Za-z0-9+/=]+)"')
_PATH_KEY = b"\xa4path"


def _read_str(data: bytes, at: int) -> str | None:
    head = data[at]
    if 0xA0 <= head <= 0xBF:
        length, start = head & 0x1F, at + 1
    elif head == 0xD9:
        length, start = data[at + 1], at + 2
    elif head == 0xDA:
        length, start = int.from_bytes(data[at + 1 : at + 3], "big"), at + 3
    else:
        return None
    return data[start : start + length].decode("utf-8", "replace")


def command_paths(html: str) -> list[str]:
    """Scene-tree paths of every command (set_object, set_transform ...) in a snapshot.

    The snapshot stores its commands as base64 msgpack maps; only their
    ``path`` strings are read here.
    """
    paths: list[str] = []
    for match in _DATA.finditer(html):
        data = base64.b64decode(match.group(1))
        index = data.find(_PATH_KEY)
        while index >= 0:
            value = _read_str(data, index + len(_PATH_KEY))
            if value is not None:
                paths.append(value)
            index = data.find(_PATH_KEY, index + 1)
    return paths


def snapshot_paths(path: str | Path) -> list[str]:
    """:func:`command_paths` of a snapshot file."""
    return command_paths(Path(path).read_text(encoding="utf-8"))
