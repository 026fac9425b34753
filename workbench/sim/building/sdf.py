"""Write a building as Gazebo's building editor saves one: a static model of boxes, in a world or alone.

The building is one static model named after the plan, one link per wall,
floor slab and flight of stairs, each box a collision and a coloured visual.
In a world, every piece of furniture is a static model of its own (so it can be
looked up and moved like a Gazebo model); in a model it is one more link.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import Literal
from xml.sax.saxutils import escape, quoteattr

from workbench.sim.building.plan import BuildingPlan, Colour, Piece, PlanError


def plan_to_sdf(plan: BuildingPlan, kind: Literal["world", "model"] = "world") -> str:
    """The SDF text of ``plan``: a world (ground, sun, building, furniture) or one model.

    Raises:
        PlanError: The plan is not valid.
    """
    if kind not in ("world", "model"):
        raise PlanError(f"kind must be 'world' or 'model', got {kind!r}")
    plan.validate()
    pieces = plan.pieces()
    source = f" from {Path(plan.source).name}" if plan.source else ""
    comment = [plan.description] if plan.description else []
    comment += [f"{plan.summary()}.", f"Written by 'workbench world build'{source}."]
    text = "\n     ".join(_comment(line) for line in comment)
    head = ['<?xml version="1.0"?>', f"<!-- {text} -->", '<sdf version="1.6">']
    if kind == "model":
        body = _model(plan.name, pieces, indent=1)
        return "\n".join([*head, *body, "</sdf>", ""])
    building = [p for p in pieces if not p.furniture]
    furniture = [p for p in pieces if p.furniture]
    lines = [
        *head,
        f"  <world name={quoteattr(plan.name)}>",
        "    <include><uri>model://ground_plane</uri></include>",
        "    <include><uri>model://sun</uri></include>",
        *_model(plan.name, building, indent=2),
    ]
    for group in _groups(furniture):
        lines += _model(group[0].group, group, indent=2)
    lines += [
        '    <physics type="ode">',
        f"      <max_step_size>{plan.max_step_size:g}</max_step_size>",
        "      <real_time_factor>1</real_time_factor>",
        "    </physics>",
        "  </world>",
        "</sdf>",
        "",
    ]
    return "\n".join(lines)


def save_building(
    plan: BuildingPlan,
    path: str | os.PathLike[str],
    kind: Literal["world", "model"] | None = None,
) -> list[Path]:
    """Write ``plan`` and return the files written.

    ``kind`` None: a world; a world written to an existing folder is
    ``NAME.world`` there. A model written to a folder (an existing one, or a
    path without a suffix) becomes a Gazebo model folder, ``model.config`` and
    ``model.sdf``, for ``GAZEBO_MODEL_PATH`` and ``model://``; otherwise one file.
    Outputs follow :mod:`workbench.output_files`: no folder is created but a new
    model folder itself (in a folder that exists), and an existing file is replaced
    only when ``workbench world build`` wrote it.

    Raises:
        PlanError: The plan is not valid or the file cannot be written.
    """
    from workbench.output_files import write_output

    kind = kind or "world"
    files = check_building_output(path, kind, plan.name)
    text = plan_to_sdf(plan, kind)
    target = Path(path)
    if not files:  # a new model folder, in a folder that exists
        try:
            target.mkdir()
        except OSError as error:
            raise PlanError(
                f"cannot create the model folder: {error.strerror}",
                path=target,
                hint="choose another -o",
            ) from None
        files = check_building_output(path, kind, plan.name)
    contents = [_model_config(plan), text] if len(files) == 2 else [text]
    for file, content in zip(files, contents, strict=True):
        write_output(file, content, error=PlanError)
    return files


def check_building_output(
    path: str | os.PathLike[str], kind: Literal["world", "model"], name: str | None = None
) -> list[Path]:
    """Check, before any work, that a building of ``kind`` may be written to ``path``.

    Args:
        path: Where the user asked for it (a file, or a folder).
        kind: ``world`` or ``model``.
        name: The building's name, which names the file written into an existing
            folder; None to check only what does not depend on it.

    Returns:
        The files that will be written (none yet for a model folder still to be made).

    Raises:
        PlanError: The folder is missing, the target is a pipe or device, or an
            existing file was not written by ``workbench world build``.
    """
    from workbench.output_files import check_output

    if not os.fspath(path).strip():
        raise PlanError("no output given: -o needs a .world/.sdf file or a folder")
    target = Path(path)
    folder = _is_dir(target)
    if kind == "model" and (folder or not target.suffix):
        if not folder:
            parent = target.parent if str(target.parent) else Path(".")
            if target.exists() or target.is_symlink():
                raise PlanError(
                    "cannot write the model folder: this is not a folder",
                    path=target,
                    hint="give a folder for model.config and model.sdf, or a .sdf file",
                )
            if not _is_dir(parent):
                raise PlanError(
                    f"cannot write the model folder: the folder {parent} does not exist",
                    path=target,
                    hint="create it first; workbench creates only the model folder itself",
                )
            return []
        pairs = [
            (target / "model.config", "building-model-config"),
            (target / "model.sdf", "building-sdf"),
        ]
    elif folder:
        if name is None:
            return []
        pairs = [(target / f"{name}.{'world' if kind == 'world' else 'sdf'}", "building-sdf")]
    else:
        pairs = [(target, "building-sdf")]
    return [check_output(file, what, error=PlanError) for file, what in pairs]


def _model_config(plan: BuildingPlan) -> str:
    return (
        '<?xml version="1.0"?>\n'
        f"<!-- Written by 'workbench world build'. -->\n<model>\n"
        f"  <name>{escape(plan.name)}</name>\n"
        '  <version>1.0</version>\n  <sdf version="1.6">model.sdf</sdf>\n'
        f"  <description>{escape(plan.summary())}</description>\n</model>\n"
    )


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except (OSError, ValueError):  # a name too long to look up
        return False


def _model(name: str, pieces: list[Piece], indent: int) -> list[str]:
    pad = "  " * indent
    lines = [f"{pad}<model name={quoteattr(name)}>", f"{pad}  <static>true</static>"]
    for group in _groups(pieces):
        lines.append(f"{pad}  <link name={quoteattr(group[0].group)}>")
        for piece in group:
            lines += _shape(piece, f"{pad}    ")
        lines.append(f"{pad}  </link>")
    lines.append(f"{pad}</model>")
    return lines


def _shape(piece: Piece, pad: str) -> list[str]:
    x, y, z, yaw = piece.pose
    pose = f"{pad}  <pose>{_n(x)} {_n(y)} {_n(z)} 0 0 {_n(yaw)}</pose>"
    if piece.shape == "cylinder":
        geometry = (
            f"<cylinder><radius>{_n(piece.radius)}</radius>"
            f"<length>{_n(piece.size[2])}</length></cylinder>"
        )
    else:
        geometry = f"<box><size>{' '.join(_n(v) for v in piece.size)}</size></box>"
    name = quoteattr(piece.name)
    visual = quoteattr(f"{piece.name}_visual")
    return [
        f"{pad}<collision name={name}>",
        pose,
        f"{pad}  <geometry>{geometry}</geometry>",
        f"{pad}</collision>",
        f"{pad}<visual name={visual}>",
        pose,
        f"{pad}  <geometry>{geometry}</geometry>",
        f"{pad}  {_material(piece.colour)}",
        f"{pad}</visual>",
    ]


def _material(colour: Colour) -> str:
    rgba = " ".join(_n(v) for v in colour)
    return f"<material><ambient>{rgba}</ambient><diffuse>{rgba}</diffuse></material>"


def _groups(pieces: Iterable[Piece]) -> list[list[Piece]]:
    groups: dict[str, list[Piece]] = {}
    for piece in pieces:
        groups.setdefault(piece.group, []).append(piece)
    return list(groups.values())


def _n(value: float) -> str:
    text = f"{round(value, 6):.10g}"
    return "0" if text == "-0" else text


def _comment(text: str) -> str:
    return escape(text).replace("--", "- -")
