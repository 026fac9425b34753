"""The mesh files of an SDF model, as files Drake can read.

A ``<mesh><uri>`` is ``model://MODEL/PATH`` (looked up as
:mod:`workbench.model.gazebo_models` says), ``file:///ABSOLUTE``, or a path
relative to the SDF file; ``package://`` URIs are left to Drake's package map.
Each mesh becomes a ``file://`` URI of a file Drake reads: OBJ as is, DAE, STL
and PLY converted to OBJ (:func:`workbench.model.meshes.prepare_mesh`).
A mesh with several ``<uri>`` keeps the first, as libsdformat reads it. Other URIs
(material scripts, textures) are not read by Drake; material scripts are dropped
(:func:`drop_material_scripts`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from workbench.errors import ModelError
from workbench.model.meshes import prepare_mesh


def mesh_file(uri: str, base_dir: Path | None, *, path: Path | None, line: int | None) -> Path:
    """The file a ``<mesh><uri>`` names.

    Args:
        uri: The URI as written.
        base_dir: Folder a relative path starts from (default: the working directory).
        path: The SDF file, for messages.
        line: The URI's line in it.

    Raises:
        ModelError: A ``model://`` URI that names no file.
    """
    from workbench.model.gazebo_models import resolve_model_uri

    if uri.startswith("model://"):
        try:
            return resolve_model_uri(uri)
        except ModelError as error:
            raise ModelError(error.message, path=path, line=line, hint=error.hint) from None
    text = uri.removeprefix("file://")
    file = Path(text)
    return file if file.is_absolute() else (base_dir or Path.cwd()) / file


def drop_material_scripts(model: Any) -> None:
    """Remove ``<material><script>`` elements (Gazebo's OGRE material scripts), which Drake does
    not draw and refuses without a ``<uri>`` (Gazebo 11 loads a script given by name alone)."""
    for script in list(model.iter("script")):
        parent = script.getparent()
        if parent is not None and parent.tag == "material":
            parent.remove(script)


def resolve_mesh_uris(model: Any, base_dir: Path | None, path: Path | None) -> None:
    """Turn every ``<mesh><uri>`` of ``model`` (an lxml element) into a ``file://`` URI Drake reads.

    Raises:
        ModelError: A URI that names no file; a missing, oversized or unconvertible mesh.
    """
    for mesh in model.iter("mesh"):
        uris = mesh.findall("uri")
        if not uris:
            continue
        uri = uris[0]
        for extra in uris[1:]:  # libsdformat reads the first (exporters add "__default__")
            mesh.remove(extra)
        value = (uri.text or "").strip()
        if not value or value.startswith("package://"):
            continue
        file = mesh_file(value, base_dir, path=path, line=uri.sourceline)
        uri.text = prepare_mesh(file, where=path, line=uri.sourceline).as_uri()
