"""Where ``model://`` URIs lead: Gazebo's model folders.

A model folder holds ``model.config`` (whose ``<sdf>`` elements name the model
file, one per SDFormat version) and that file, as in Gazebo's model database.
Folders are searched in ``GAZEBO_MODEL_PATH`` (``:``-separated, first wins),
then in workbench's own ``urdf/models``. As a convenience ``urdf/NAME.sdf`` and
``urdf/NAME.urdf`` answer ``model://NAME`` too.

``model://NAME`` in an ``<include>`` names a model folder, which may sit inside
another folder (``model://turtlebot3_autorace/traffic_stop``); in a ``<mesh>``
it names a file (``model://NAME/meshes/base.dae``), found under the first
search folder that has it, whether or not its folder holds a ``model.config``
(Gazebo looks files up the same way). Paths may not climb out with ``..``.

Model files are read only from the model folders (``GAZEBO_MODEL_PATH``), the
shipped models (``urdf/``) and the folder of the world or model file that
includes them (:func:`allowed_model_file`); a ``model.config`` names a file
inside its own folder.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any

from lxml import etree

from workbench.errors import ModelError

#: Models every world has without a file: Gazebo's stock ground and light.
BUILT_IN_MODELS = ("ground_plane", "sun")
#: The scheme of Gazebo's model URIs.
MODEL_SCHEME = "model://"


class ModelUriError(ModelError):
    """A ``model://`` URI that names nothing in the model folders."""


def model_search_path() -> list[Path]:
    """The folders searched for ``model://NAME``, in order."""
    from workbench.paths import urdf_dir

    folders = [Path(p) for p in os.environ.get("GAZEBO_MODEL_PATH", "").split(os.pathsep) if p]
    return [*folders, urdf_dir() / "models"]


def uri_path(uri: str) -> str | None:
    """The relative path a ``model://`` URI names (``model:///a/b`` too), None when it climbs
    out with ``..`` or names nothing."""
    rest = uri[len(MODEL_SCHEME) :] if uri.startswith(MODEL_SCHEME) else uri
    parts = [part for part in rest.strip().split("/") if part not in ("", ".")]
    if not parts or ".." in parts:
        return None
    return "/".join(parts)


def find_model_dir(name: str) -> Path | None:
    """The folder of model ``name`` (``NAME`` or ``FOLDER/NAME``, holding ``model.config``), or None."""
    relative = uri_path(name)
    if relative is None:
        return None
    for folder in model_search_path():
        candidate = folder / relative
        if (candidate / "model.config").is_file():
            return candidate
    return None


def find_model_file(name: str) -> Path | None:
    """The SDF/URDF file of model ``name``: its folder's ``model.config`` entry, else ``urdf/NAME.*``.

    Raises:
        ModelError: A ``model.config`` that is not XML or names a missing file.
    """
    from workbench.paths import urdf_dir

    folder = find_model_dir(name)
    if folder is not None:
        return config_file(folder)
    if uri_path(name) == name and "/" not in name:
        for suffix in (".sdf", ".urdf"):
            candidate = urdf_dir() / f"{name}{suffix}"
            if candidate.is_file():
                return candidate
    return None


def resolve_model_uri(uri: str) -> Path:
    """The file a ``model://NAME/PATH`` URI names (a mesh, a texture).

    Raises:
        ModelUriError: No search folder has the file, or the URI climbs out with ``..``.
    """
    relative = uri_path(uri)
    if relative is None:
        raise ModelUriError(
            f"cannot resolve {uri}: not a path inside a model folder",
            hint="write model://MODEL/path/to/file without '..'",
        )
    folders = model_search_path()
    for folder in folders:
        candidate = folder / relative
        if candidate.is_file():
            return candidate
    model = relative.split("/")[0]
    known = any((folder / model).is_dir() for folder in folders)
    what = (
        f"model folder '{model}' has no {relative.partition('/')[2]}"
        if known
        else (f"no model folder '{model}'")
    )
    raise ModelUriError(
        f"cannot resolve {uri}: {what}",
        hint="looked in "
        + ", ".join(str(f) for f in folders)
        + "; add folders to GAZEBO_MODEL_PATH",
    )


def config_file(folder: Path) -> Path:
    """The model file a model folder's ``model.config`` names (its newest SDFormat version).

    Raises:
        ModelError: ``model.config`` is not XML, names no file, a missing one or one outside
            the folder, or gives a version that is not ``MAJOR.MINOR``.
    """
    from workbench.model.limits import (
        MAX_MODEL_BYTES,
        check_input_file,
        shown_name,
        uri_problem,
    )

    config = folder / "model.config"
    check_input_file(config, "model.config", MAX_MODEL_BYTES)
    try:
        root = etree.parse(str(config), etree.XMLParser(resolve_entities=False)).getroot()
    except (OSError, etree.XMLSyntaxError) as error:
        from workbench.model.limits import xml_error_text

        raise ModelError(
            f"{config}: cannot read model.config: {xml_error_text(str(error))}"
        ) from None
    entries = root.findall("sdf")
    if not entries:
        raise ModelError(f"{config}: no <sdf> element names the model file")
    versions = [(_version(config, entry), entry) for entry in entries]
    best = max(versions, key=lambda pair: pair[0])[1]
    text = (best.text or "").strip()
    where = f"{config}:{best.sourceline}"
    problem = uri_problem(text)
    if problem is not None:
        raise ModelError(f"{where}: <sdf> '{shown_name(text)}' {problem}")
    shown = text if len(text) <= 80 else text[:77] + "..."
    relative = Path(text)
    if not text or relative.is_absolute() or ".." in relative.parts:
        raise ModelError(
            f"{where}: the model file '{shown}' is not inside the model folder",
            hint="name a file of the model's own folder, e.g. <sdf version='1.6'>model.sdf</sdf>",
        )
    path = folder / relative
    if not path.is_file():
        raise ModelError(f"{where}: the model file '{shown}' is missing")
    return path


def _version(config: Path, entry: Any) -> tuple[int, ...]:
    """An ``<sdf version>`` as numbers (none given: the oldest).

    Raises:
        ModelError: A version that is not dot-separated ASCII digits (``1.²``, ``one``).
    """
    text = (entry.get("version") or "").strip()
    if not text:
        return (0,)
    if not re.fullmatch(r"[0-9]{1,6}(\.[0-9]{1,6}){0,3}", text, re.ASCII):
        shown = text if len(text) <= 40 else text[:37] + "..."
        raise ModelError(
            f"{config}:{entry.sourceline}: <sdf version='{shown}'> is not an SDFormat version",
            hint="write it as MAJOR.MINOR, e.g. version='1.6'",
        )
    return tuple(int(part) for part in text.split("."))


def allowed_model_file(
    file: Path, including: Path | None, *, uri: str, line: int | None, top: Path | None = None
) -> Path:
    """``file`` when a model file may be read from there, for an include in ``including``.

    Model files are read only under ``GAZEBO_MODEL_PATH``, the shipped models (``urdf/``),
    and the folders of the file that includes them and of the file the chain of includes
    started from (``top``: the world). A model given as text (a spawn request) has no folder.

    Raises:
        ModelError: ``file`` lies elsewhere (an absolute path, or ``..`` climbing out).
    """
    from workbench.paths import urdf_dir

    roots = [*model_search_path(), urdf_dir()]
    roots += [p.parent for p in (including, top) if p is not None]
    if any(_under(file, root) for root in roots):
        return file
    shown = uri if len(uri) <= 80 else uri[:77] + "..."
    raise ModelError(
        f"<include> of '{shown}': model files are read only from GAZEBO_MODEL_PATH, the "
        "shipped models and the including file's folder",
        path=including,
        line=line,
        hint="add the model's folder to GAZEBO_MODEL_PATH and include it as model://NAME",
    )


def _under(file: Path, root: Path) -> bool:
    """Whether ``file`` lies in ``root``, by the names as written or as the links lead."""
    try:
        if Path(os.path.normpath(file)).is_relative_to(os.path.normpath(root)):
            return True
        return file.resolve().is_relative_to(root.resolve())
    except (OSError, ValueError, RuntimeError):
        return False
