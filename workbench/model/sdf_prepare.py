"""An SDF model file made ready for Drake's parser, as the simulator reads it.

Drake is given the model as text: its includes expanded and nested models
merged (:mod:`workbench.model.sdf_nesting`), its ``model://`` and relative mesh
URIs resolved and converted (:mod:`workbench.model.sdf_uris`), and its names
written as Drake takes them (:mod:`workbench.model.sdf_names`). Blank lines
stand in for the prolog, so Drake's line numbers are the file's wherever
nothing was merged. ``workbench check`` and ``load_robot`` read SDF models
this way, resolving ``model://`` exactly as ``workbench sim`` does.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree


@dataclass
class PreparedSdf:
    """The text Drake parses and what was changed on the way.

    Attributes:
        text: The SDF document with one flattened ``<model>``.
        warnings: One line per name changed so Drake accepts it.
    """

    text: str
    warnings: list[str] = field(default_factory=list)


def prepare_sdf(text: str, path: Path) -> PreparedSdf | None:
    """The prepared text of the SDF file ``path`` (holding ``text``), or None when it holds no
    ``<model>`` at its top (a world, a light: Drake reads those itself).

    Raises:
        ModelError: Not XML; an include, a mesh or a ``model://`` URI that cannot be resolved.
    """
    from workbench.model.sdf_nesting import drake_names, flatten_model
    from workbench.model.sdf_uris import drop_material_scripts, resolve_mesh_uris
    from workbench.model.sdf_xml import parse_sdf_text

    root = parse_sdf_text(text, path)
    model = root.find("model") if root.tag == "sdf" else None
    if model is None:
        return None
    nesting = flatten_model(model, path=path, version=root.get("version"))
    resolve_mesh_uris(model, path.parent, path)
    drop_material_scripts(model)
    drake_names(model)
    root.set("version", nesting.version)
    padding = "\n" * ((root.sourceline or 1) - 1)
    return PreparedSdf(padding + etree.tostring(root, encoding="unicode"), nesting.warnings)
