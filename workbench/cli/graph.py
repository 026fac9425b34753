"""``workbench graph FILE``: urdf_to_graphviz (NAME.gv and NAME.pdf in the current directory)."""

from __future__ import annotations

import argparse


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="a .urdf or .xacro file, or a name from urdf/")
    parser.add_argument(
        "--format",
        choices=("pdf", "svg", "png"),
        help="rendering format (default: pdf, or the suffix of -o)",
    )
    parser.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="write the rendering to OUT (and the graph to OUT with .gv); OUT.gv writes only the graph",
    )


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from workbench.model.graph import write_graph
    from workbench.model.loader import load_document

    document = load_document(args.file)
    if args.output:
        out = Path(args.output)
        if out.suffix == ".gv":
            gv, rendered = out, None
        else:
            gv, rendered = out.with_suffix(".gv"), out
    else:
        fmt = args.format or "pdf"
        gv, rendered = Path(f"{document.name}.gv"), Path(f"{document.name}.{fmt}")
    # The .gv is announced before rendering, so it is reported even when dot is missing.
    written = write_graph(document, gv, None)
    print(f"Created file {written[0]}")
    if rendered is not None:
        written = write_graph(document, gv, rendered, args.format)
        print(f"Created file {written[1]}")
    return 0
