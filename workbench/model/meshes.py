"""Make mesh files readable by Drake: OBJ/glTF pass through, STL/DAE/PLY become OBJ.

A COLLADA file's ``<unit meter="...">`` scales its vertices into metres, as
Gazebo and RViz read it (a mesh drawn in inches has ``meter="0.0254"``); its
``<up_axis>`` is ignored, as Gazebo ignores it. Converted meshes go to a cache directory (``$WORKBENCH_CACHE_DIR``, else
``$XDG_CACHE_HOME/workbench/meshes``, else ``~/.cache/workbench/meshes``),
keyed by the source path, size and modification time, so a mesh is converted
once.
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import logging
import math
import os
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from workbench.errors import ModelError
from workbench.model.limits import MAX_MESH_BYTES, check_input_file
from workbench.paths import exists

#: Formats Drake's parser and Meshcat read directly.
NATIVE_FORMATS = (".obj", ".gltf", ".glb", ".vtk")
#: Formats converted to OBJ with trimesh first.
CONVERTED_FORMATS = (".stl", ".dae", ".ply", ".off")


class MeshError(ModelError):
    """A mesh file is missing, in a format nobody here reads, or fails to convert."""


def cache_dir() -> Path:
    """The directory converted meshes are written to (created on demand)."""
    from workbench.paths import cache_root

    return cache_root() / "meshes"


def check_mesh(path: Path, *, where: Path | None = None, line: int | None = None) -> None:
    """Raise :class:`MeshError` if ``path`` is missing, in an unsupported format, not a
    regular file, or bigger than :data:`~workbench.model.limits.MAX_MESH_BYTES`."""
    suffix = path.suffix.lower()
    if suffix not in NATIVE_FORMATS + CONVERTED_FORMATS:
        raise MeshError(
            f"unsupported mesh format '{suffix or path.name}' ({path})",
            path=where,
            line=line,
            hint="use .obj, .gltf, .stl, .dae or .ply",
        )
    if not exists(path):
        raise MeshError(
            f"mesh file not found: {path}",
            path=where,
            line=line,
            hint="check the filename and the package:// path",
        )
    try:
        check_input_file(path, "mesh", MAX_MESH_BYTES, where=where, line=line)
    except ModelError as error:
        message = error.message if where is not None else f"mesh {path}: {error.message}"
        raise MeshError(message, path=where, line=line, hint=error.hint) from None


#: Loggers of the converters: they log tracebacks for textures they cannot find.
_CONVERTER_LOGGERS = ("trimesh", "collada")
#: Longest converter message kept in an error, characters.
_LONGEST_REASON = 300


@contextlib.contextmanager
def _quiet_converters() -> Iterator[None]:
    """Keep trimesh's and pycollada's log records and warnings off the terminal.

    A mesh that converts needs no word from them (a missing texture is not drawn
    anyway); one that does not gets workbench's own one-line error.
    """
    loggers = [logging.getLogger(name) for name in _CONVERTER_LOGGERS]
    levels = [logger.level for logger in loggers]
    for logger in loggers:
        logger.setLevel(logging.CRITICAL + 1)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            yield
    finally:
        for logger, level in zip(loggers, levels, strict=True):
            logger.setLevel(level)


def _reason(error: Exception, suffix: str) -> str:
    """Why a conversion failed, on one line."""
    if isinstance(error, ImportError):
        # trimesh reaches for optional modules when a file is not what its suffix says
        return f"the file is damaged or not a {suffix} mesh"
    text = " ".join(str(error).split()) or type(error).__name__
    return text if len(text) <= _LONGEST_REASON else text[: _LONGEST_REASON - 3] + "..."


def unit_scale(mesh: Any) -> float:
    """Metres per unit of a mesh trimesh read (COLLADA's ``<unit meter>``; 1 when unknown)."""
    units = str(getattr(mesh, "units", None) or mesh.metadata.get("units", "") or "")
    factor, _, unit = units.partition("*")
    if unit.strip() != "meters":
        return 1.0
    try:
        value = float(factor)
    except ValueError:
        return 1.0
    return value if math.isfinite(value) and value > 0 else 1.0


def prepare_mesh(path: Path, *, where: Path | None = None, line: int | None = None) -> Path:
    """Return a path Drake can read for the mesh at ``path``, converting if needed.

    Raises:
        MeshError: Missing file, unsupported format, or a failed conversion.
    """
    check_mesh(path, where=where, line=line)
    suffix = path.suffix.lower()
    if suffix in NATIVE_FORMATS:
        return path.resolve()
    stat = path.stat()
    # "units": meshes converted before COLLADA units were applied are not reused
    key = f"{path.resolve()}|{stat.st_size}|{stat.st_mtime_ns}|units"
    key = hashlib.sha1(key.encode()).hexdigest()
    target = cache_dir() / f"{path.stem}-{key[:16]}.obj"
    if target.is_file():
        return target
    try:
        import trimesh

        with _quiet_converters():
            mesh: Any = trimesh.load(str(path), force="mesh")  # a Trimesh with force="mesh"
            if len(mesh.faces) == 0 and suffix == ".dae":
                mesh = _collada_geometry(path, trimesh)
            if len(mesh.faces) == 0:
                raise ValueError("the mesh has no triangles")
            scale = unit_scale(mesh)
            if scale != 1.0:
                mesh.apply_scale(scale)
            target.parent.mkdir(parents=True, exist_ok=True)
            partial = target.with_suffix(f".{os.getpid()}.tmp")
            mesh.export(str(partial), file_type="obj")
        partial.replace(target)
    except Exception as error:  # trimesh raises many kinds; all mean "cannot convert"
        hint = "convert it to .obj yourself"
        if suffix == ".dae" and importlib.util.find_spec("collada") is None:
            hint = "reading .dae needs 'pip install pycollada', or convert it to .obj"
        raise MeshError(
            f"cannot convert mesh {path} to OBJ: {_reason(error, suffix)}",
            path=where,
            line=line,
            hint=hint,
        ) from None
    return target


def _collada_geometry(path: Path, trimesh: Any) -> Any:
    """A COLLADA file's triangles read without its images, materials and effects.

    pycollada refuses a whole file over an image without a file path (3ds Max's
    exporter writes them) and trimesh then reads no triangles; Gazebo draws the
    geometry anyway.
    """
    import io

    from lxml import etree

    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
    root = etree.parse(str(path), parser).getroot()
    for element in list(root.iter()):
        name = etree.QName(element).localname if isinstance(element.tag, str) else ""
        if name in ("library_images", "library_materials", "library_effects", "bind_material"):
            element.getparent().remove(element)
    data = io.BytesIO(etree.tostring(root))
    return trimesh.load(data, file_type="dae", force="mesh")
