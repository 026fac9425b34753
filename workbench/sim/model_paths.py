"""Where ``model://NAME`` is found: Gazebo's model folders.

A model folder holds ``model.config`` (whose ``<sdf>`` element names the model
file) and that file, as in Gazebo's model database. Folders are searched in
``GAZEBO_MODEL_PATH`` (``:``-separated, first wins), then in workbench's own
``urdf/models``. As a convenience ``urdf/NAME.sdf`` and ``urdf/NAME.urdf``
answer ``model://NAME`` too.
"""

from __future__ import annotations

import os
from pathlib import Path

from lxml import etree

from workbench.errors import SimulationError

#: Models every world has without a file: Gazebo's stock ground and light.
BUILT_IN_MODELS = ("ground_plane", "sun")


def model_search_path() -> list[Path]:
    """The folders searched for ``model://NAME``, in order."""
    from workbench.paths import urdf_dir

    folders = [Path(p) for p in os.environ.get("GAZEBO_MODEL_PATH", "").split(os.pathsep) if p]
    return [*folders, urdf_dir() / "models"]


def find_model_dir(name: str) -> Path | None:
    """The folder of model ``name`` (one holding ``model.config``), or None."""
    if not name or "/" in name or name in (".", ".."):
        return None
    for folder in model_search_path():
        candidate = folder / name
        if (candidate / "model.config").is_file():
            return candidate
    return None


def find_model_file(name: str) -> Path | None:
    """The SDF/URDF file of model ``name``: its folder's ``model.config`` entry, else ``urdf/NAME.*``.

    Raises:
        SimulationError: A ``model.config`` that is not XML or names a missing file.
    """
    from workbench.paths import urdf_dir

    folder = find_model_dir(name)
    if folder is not None:
        return _config_file(folder)
    for suffix in (".sdf", ".urdf"):
        candidate = urdf_dir() / f"{name}{suffix}"
        if candidate.is_file():
            return candidate
    return None


def _config_file(folder: Path) -> Path:
    config = folder / "model.config"
    try:
        root = etree.parse(str(config)).getroot()
    except (OSError, etree.XMLSyntaxError) as error:
        raise SimulationError(f"{config}: cannot read model.config: {error}") from None
    entries = root.findall("sdf")
    if not entries:
        raise SimulationError(f"{config}: no <sdf> element names the model file")

    def version(element: object) -> tuple[int, ...]:
        text = getattr(element, "get", lambda *_: "0")("version", "0") or "0"
        return tuple(int(p) for p in text.split(".") if p.isdigit())

    best = max(entries, key=version)
    path = folder / (best.text or "").strip()
    if not path.is_file():
        raise SimulationError(
            f"{config}:{best.sourceline}: the model file '{(best.text or '').strip()}' is missing"
        )
    return path
