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
"""

from __future__ import annotations

import os
from pathlib import Path

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
        ModelError: ``model.config`` is not XML, names no file or a missing one.
    """
    config = folder / "model.config"
    try:
        root = etree.parse(str(config)).getroot()
    except (OSError, etree.XMLSyntaxError) as error:
        from workbench.model.limits import xml_error_text

        raise ModelError(
            f"{config}: cannot read model.config: {xml_error_text(str(error))}"
        ) from None
    entries = root.findall("sdf")
    if not entries:
        raise ModelError(f"{config}: no <sdf> element names the model file")

    def version(element: object) -> tuple[int, ...]:
        text = getattr(element, "get", lambda *_: "0")("version", "0") or "0"
        return tuple(int(p) for p in text.split(".") if p.isdigit())

    best = max(entries, key=version)
    from workbench.model.limits import shown_name, uri_problem

    problem = uri_problem((best.text or "").strip())
    if problem is not None:
        raise ModelError(
            f"{config}:{best.sourceline}: <sdf> '{shown_name((best.text or '').strip())}' {problem}"
        )
    path = folder / (best.text or "").strip()
    if not path.is_file():
        raise ModelError(
            f"{config}:{best.sourceline}: the model file '{(best.text or '').strip()}' is missing"
        )
    return path
