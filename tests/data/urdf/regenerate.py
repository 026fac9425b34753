"""Rewrite the golden files of the model tests from the current code.

Run from anywhere: ``python tests/data/urdf/regenerate.py``. Then read the
diff (``git diff tests/data/urdf``): every change must be one you meant.

Writes:
  golden/NAME.check.txt  `workbench check urdf/NAME.urdf` report for each model in urdf/
  golden/NAME.gv         `workbench graph urdf/NAME.urdf` graph for each model in urdf/
  bad/cases.yaml         the expected one-line message of each broken file in bad/
"""

from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[2]

CASES_HEADER = """\
# The bad-input corpus: each broken description and the one line it must produce.
#   check: the line `workbench check FILE` prints for its first error ({path} = FILE as given,
#          {dir} = this directory). Lines starting "workbench check: error:" go to stderr
#          (the file cannot be read at all); the others are findings in the report on stdout.
#   load:  the one-line error of load_robot(FILE), or "loads" when Drake accepts the model
#          (physics errors that only `workbench check` finds).
# Regenerate after a deliberate message change with: python tests/data/urdf/regenerate.py
# and review the diff.
"""


def model_files() -> list[Path]:
    return sorted(
        path
        for path in (REPO / "urdf").iterdir()
        if path.suffix == ".urdf" or path.name.endswith(".urdf.xacro")
    )


def golden() -> None:
    from workbench.model.check import check_robot
    from workbench.model.graph import graph_source
    from workbench.model.loader import load_document

    out = HERE / "golden"
    out.mkdir(exist_ok=True)
    for path in model_files():
        shown = f"urdf/{path.name}"
        stem = path.name.removesuffix(".xacro").removesuffix(".urdf")
        if path.name.endswith(".xacro"):
            stem += ".xacro"
        report = check_robot(path)
        (out / f"{stem}.check.txt").write_text(report.format(shown))
        (out / f"{stem}.gv").write_text(graph_source(load_document(path)))


def cases() -> None:
    from workbench.cli import main
    from workbench.errors import WorkbenchError
    from workbench.model import load_robot

    bad = HERE / "bad"
    entries = []
    for path in sorted(bad.iterdir()):
        if path.suffix == ".yaml":
            continue
        stdout, stderr = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            main(["check", str(path)])
        text = stdout.getvalue() + stderr.getvalue()
        line = next(
            item
            for item in text.splitlines()
            if "error:" in item and not item.startswith("workbench found")
        )
        try:
            load_robot(path)
            load = "loads"
        except WorkbenchError as error:
            load = error.one_line()
        entries.append(
            {
                "file": path.name,
                "check": line.replace(str(path), "{path}").replace(str(bad), "{dir}"),
                "load": load.replace(str(path), "{path}").replace(str(bad), "{dir}"),
            }
        )
    text = yaml.safe_dump(entries, sort_keys=False, width=200, allow_unicode=True)
    (bad / "cases.yaml").write_text(CASES_HEADER + text)


if __name__ == "__main__":
    os.environ.pop("WORKBENCH_PACKAGE_PATH", None)
    os.environ.pop("ROS_PACKAGE_PATH", None)
    golden()
    cases()
    print(f"rewrote the golden files under {HERE}")
