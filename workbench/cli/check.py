"""``workbench check FILE``: check_urdf's tree report plus workbench's own findings."""

from __future__ import annotations

import argparse
import json
import os
import sys


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="a .urdf, .sdf or .xacro file, or a name from urdf/")
    parser.add_argument("--json", action="store_true", help="print the report as JSON")
    parser.add_argument(
        "--no-load", action="store_true", help="do not load the model into Drake (faster)"
    )
    parser.epilog = (
        "Exit status: 0 when there is no error (warnings allowed), 1 when there is an error "
        "or the file cannot be read."
    )


def _display_path(argument: str, resolved) -> str:
    if os.path.exists(argument):
        return argument
    try:
        return os.path.relpath(resolved)
    except ValueError:
        return str(resolved)


def run(args: argparse.Namespace) -> int:
    from workbench.errors import ModelError
    from workbench.model.check import check_robot

    try:
        report = check_robot(args.file, load=not args.no_load)
    except ModelError as error:
        if not args.json:
            raise
        finding = {
            "severity": "error",
            "code": "unreadable",
            "element": "file",
            "message": error.message,
            "hint": error.hint or "",
            "line": error.line,
        }
        document = {
            "path": error.path or args.file,
            "ok": False,
            "errors": 1,
            "warnings": 0,
            "loaded": False,
            "robot": None,
            "root": None,
            "tree": [],
            "findings": [finding],
        }
        print(json.dumps(document, indent=2))
        return 1
    if args.json:
        print(json.dumps(report.to_dict(), indent=2))
    else:
        sys.stdout.write(report.format(_display_path(args.file, report.path)))
    return 0 if report.ok else 1
