"""``workbench graph FILE``: urdf_to_graphviz (NAME.gv and NAME.pdf in the current directory)."""

from __future__ import annotations

import argparse

FORMATS = ("pdf", "svg", "png")


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="a .urdf or .xacro file, or a name from urdf/")
    parser.add_argument(
        "--format",
        choices=FORMATS,
        help="rendering format (default: pdf, or the suffix of -o)",
    )
    parser.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="write the rendering to OUT (and the graph to OUT with .gv); OUT.gv writes only the graph",
    )


def run(args: argparse.Namespace) -> int:
    return graph(args.file, fmt=args.format, output=args.output)


def graph(file: str, *, fmt: str | None = None, output: str | None = None) -> int:
    """urdf_to_graphviz: write NAME.gv and its rendering (NAME.pdf) into the current folder.

    Args:
        file: A ``.urdf`` or ``.xacro`` path, or a name from ``urdf/``.
        fmt: ``pdf``, ``svg`` or ``png`` (default: pdf, or the suffix of ``output``).
        output: Write the rendering here (and the graph beside it as ``.gv``); a ``.gv``
            path writes only the graph.

    Raises:
        ModelError: An unknown format, an unreadable description, or dot is missing.
    """
    from pathlib import Path

    from workbench.errors import ModelError
    from workbench.model.graph import read_graph_document, write_graph
    from workbench.model.limits import file_stem_problem, shown_name
    from workbench.output_files import check_output

    if fmt is not None and fmt not in FORMATS:
        raise ModelError(f"unknown format '{fmt}'", hint=f"use one of {', '.join(FORMATS)}")
    document = read_graph_document(file)
    if output:
        out = Path(output)
        if out.suffix == ".gv":
            gv, rendered = out, None
        else:
            gv, rendered = out.with_suffix(".gv"), out
    else:
        problem = file_stem_problem(document.name)
        if problem is not None:
            raise ModelError(
                f"the robot name '{shown_name(document.name)}' cannot name the output file: "
                f"it {problem}",
                path=document.path,
                hint="give the output file with -o OUT",
            )
        gv, rendered = Path(f"{document.name}.gv"), Path(f"{document.name}.{fmt or 'pdf'}")
    check_output(gv, "graphviz", error=ModelError)
    if rendered is not None:
        kind = fmt or rendered.suffix.lstrip(".").lower() or "pdf"
        if kind not in FORMATS:
            raise ModelError(
                f"cannot tell the format of {rendered}", hint=f"use --format {'|'.join(FORMATS)}"
            )
        check_output(rendered, kind, error=ModelError)
    # The .gv is announced before rendering, so it is reported even when dot is missing.
    written = write_graph(document, gv, None)
    print(f"Created file {written[0]}")
    if rendered is not None:
        written = write_graph(document, gv, rendered, fmt)
        print(f"Created file {written[1]}")
    return 0
