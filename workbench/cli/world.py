"""``workbench world build PLAN -o WORLD``: Gazebo's building editor; ``workbench world list``."""

from __future__ import annotations

import argparse
from pathlib import Path

#: Files read as plan descriptions; anything else is an image (a map YAML is told by its keys).
PLAN_SUFFIXES = (".yaml", ".yml", ".json")


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the ``build`` and ``list`` verbs."""
    parser.description = (
        "Make worlds: build a Gazebo-style building from a floor plan (the building editor), "
        "list the shipped worlds."
    )
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    build_parser = verbs.add_parser(
        "build",
        help="turn a floor plan (YAML/JSON, a map YAML or an image) into an SDF building",
        description="Turn a floor plan into an SDF world (or model) of static boxes: walls split "
        "around doors and windows, floor slabs, stairs, furniture. PLAN is a plan file "
        "(.yaml/.json; see workbench.sim.building.plan_file), a map_server map YAML, or an "
        "image (PGM/PNG) whose dark pixels are walls.",
    )
    build_parser.add_argument("plan", help="the floor plan: plan YAML/JSON, map YAML or image")
    build_parser.add_argument(
        "-o", "--output", required=True, help="the .world/.sdf file (or model folder) to write"
    )
    build_parser.add_argument(
        "--model",
        action="store_true",
        help="write a model, not a world (a folder path gets model.config + model.sdf)",
    )
    build_parser.add_argument("--name", help="the building's name (default: the plan's)")
    image = build_parser.add_argument_group("images")
    image.add_argument(
        "--resolution", type=float, metavar="M", help="metres per pixel (a map YAML has its own)"
    )
    image.add_argument("--height", type=float, metavar="M", help="wall height (default 2.5)")
    image.add_argument(
        "--threshold",
        type=float,
        metavar="OCC",
        help="a pixel darker than this occupancy, (255 - grey) / 255, is a wall (default 0.65)",
    )
    image.add_argument("--negate", action="store_true", help="light walls on a dark background")
    image.add_argument(
        "--origin",
        type=float,
        nargs=2,
        metavar=("X", "Y"),
        help="where the image's lower-left corner goes, m (a map YAML has its own)",
    )
    image.add_argument(
        "--min-pixels", type=int, default=1, metavar="N", help="drop specks under N pixels"
    )
    verbs.add_parser("list", help="list the shipped worlds (workbench sim NAME)")


def run(args: argparse.Namespace) -> int:
    """Run the chosen verb; returns the exit status."""
    if args.verb == "list":
        return list_worlds()
    return build(
        args.plan,
        args.output,
        model=args.model,
        name=args.name,
        resolution=args.resolution,
        height=args.height,
        threshold=args.threshold,
        negate=True if args.negate else None,
        origin=tuple(args.origin) if args.origin else None,
        min_pixels=args.min_pixels,
    )


def build(
    plan: str,
    output: str,
    *,
    model: bool = False,
    name: str | None = None,
    resolution: float | None = None,
    height: float | None = None,
    threshold: float | None = None,
    negate: bool | None = None,
    origin: tuple[float, ...] | None = None,
    min_pixels: int = 1,
) -> int:
    """Read ``plan`` (a plan file, a map YAML or an image) and write its building to ``output``.

    Raises:
        PlanError: The plan cannot be read or is wrong, or the output cannot be written.
    """
    from workbench.limits import check_regular_file
    from workbench.sim.building import PlanError, load_plan, plan_from_image
    from workbench.sim.building.sdf import check_building_output

    source = Path(plan)
    check_regular_file(source, "plan file", PlanError)
    check_building_output(output, "model" if model else "world")
    if source.suffix.lower() in PLAN_SUFFIXES and not _is_map_yaml(source):
        building = load_plan(source)
        if name:
            building.name = name
        options = (resolution, height, threshold, negate, origin)
        if any(v is not None for v in options) or min_pixels != 1:
            raise PlanError(
                "--resolution, --height, --threshold, --negate, --origin and --min-pixels are "
                "for images; a plan file gives its own sizes",
                path=source,
            )
    else:
        if min_pixels < 1:
            raise PlanError(f"--min-pixels must be 1 or more, got {min_pixels}", path=source)
        building = plan_from_image(
            source,
            resolution,
            height=2.5 if height is None else height,
            threshold=threshold,
            negate=negate,
            origin=(origin[0], origin[1]) if origin else None,
            min_pixels=min_pixels,
            name=name,
        )
    files = building.save(output, "model" if model else "world")
    print(f"{building.summary()}, {len(building.pieces())} boxes and cylinders")
    for note in building.notes():
        print(f"note: {note}")
    for file in files:
        print(f"wrote {file}")
    if not model:
        print(f"run it: workbench sim {files[0]}")
    return 0


def list_worlds() -> int:
    """Print the shipped worlds (``workbench sim NAME``) with their first comment line."""
    from workbench.sim.world_file import shipped_worlds

    for world_name, path in shipped_worlds().items():
        print(f"{world_name:<16} {_first_comment(path)}")
    return 0


def _is_map_yaml(path: Path) -> bool:
    """A map_server map YAML (``image:`` and ``resolution:``), not a plan."""
    if path.suffix.lower() not in (".yaml", ".yml"):
        return False
    from workbench.errors import WorkbenchError
    from workbench.limits import load_yaml_file

    try:
        doc = load_yaml_file(path, "plan file")
    except WorkbenchError:
        return False  # load_plan says what is wrong
    return isinstance(doc, dict) and "image" in doc and "resolution" in doc


def _first_comment(path: Path) -> str:
    try:
        text = path.read_text()
    except OSError:
        return ""
    start = text.find("<!--")
    if start < 0:
        return ""
    comment = text[start + 4 : text.find("-->", start)].strip()
    return comment.splitlines()[0].strip() if comment else ""
