"""Rewrite the expected output of the hostile-input corpus from the current code.

Run from anywhere: ``python tests/data/hostile/regenerate_data.py [KIND ...]`` (default:
every kind). Then read the diff (``git diff tests/data/hostile``): every change must be one
you meant. The format of ``cases.yaml`` is described in ``tests/hostile_corpus.py``.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1]))  # tests/, for hostile_corpus

from hostile_corpus import cases, run_case  # noqa: E402

KINDS = ("parameters", "launch", "bags", "logs", "maps", "rviz", "serial")

HEADER = """\
# Hostile {kind}: each case's command and what it must print (format: tests/hostile_corpus.py).
# Regenerate after a deliberate message change with: python tests/data/hostile/regenerate_data.py
# and review the diff.
"""


def regenerate(kind: str) -> None:
    entries = []
    for case in cases(kind):
        with tempfile.TemporaryDirectory() as tmp:
            result = run_case(case, kind, Path(tmp))
        entry = {key: case[key] for key in ("name", "make", "argv") if key in case}
        entry["status"] = result["status"]
        entry["stderr"] = result["stderr"]
        keep = case.get("stdout")
        if keep:
            entry["stdout"] = keep
        entries.append(entry)
    text = yaml.safe_dump(
        entries, sort_keys=False, width=200, allow_unicode=True, default_flow_style=None
    )
    (HERE / kind / "cases.yaml").write_text(HEADER.format(kind=kind) + text)


if __name__ == "__main__":
    os.environ["WORKBENCH_MASTER_URI"] = "inproc"
    for kind in sys.argv[1:] or KINDS:
        if (HERE / kind / "cases.yaml").is_file():
            regenerate(kind)
            print(f"rewrote {HERE / kind / 'cases.yaml'}")
