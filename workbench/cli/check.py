"""``workbench check FILE``: check_urdf's report plus workbench's own findings.

stdout is check_urdf's stdout (the tree, or nothing when ROS's parser refuses the
file) followed by workbench's findings; stderr carries urdfdom's ``Error:`` and
``Warning:`` lines as check_urdf prints them.
"""

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
    return check(args.file, as_json=args.json, load=not args.no_load)


def check(file: str, *, as_json: bool = False, load: bool = True) -> int:
    """check_urdf's report of a description plus workbench's findings, as text or JSON.

    Args:
        file: A ``.urdf``, ``.sdf`` or ``.xacro`` path, or a name from ``urdf/``.
        as_json: Print the report as JSON (an unreadable file is reported there too).
        load: Also load the model into Drake (slower; finds what only Drake rejects).

    Returns:
        0 when there is no error (warnings allowed), else 1.

    Raises:
        ModelError: The file cannot be read (text output only).
    """
    from workbench.errors import ModelError
    from workbench.model.check import check_robot

    try:
        report = check_robot(file, load=load)
    except ModelError as error:
        if not as_json:
            raise
        print(json.dumps(_unreadable(file, error), indent=2))
        return 1
    if as_json:
        print(json.dumps(report.to_dict(), indent=2))
    else:
        # check_urdf's stderr (urdfdom's log), then its stdout followed by the findings.
        if report.ros_messages:
            sys.stdout.flush()
            sys.stderr.write("".join(line + "\n" for line in report.ros_messages))
            sys.stderr.flush()
        sys.stdout.write(report.format(_display_path(file, report.path)))
    return 0 if report.ok else 1


def _unreadable(file: str, error) -> dict:
    finding = {
        "severity": "error",
        "code": "unreadable",
        "element": "file",
        "message": error.message,
        "hint": error.hint or "",
        "line": error.line,
    }
    return {
        "path": error.path or file,
        "ok": False,
        "errors": 1,
        "warnings": 0,
        "loaded": False,
        "robot": None,
        "root": None,
        "tree": [],
        "urdfdom": [],
        "findings": [finding],
    }
