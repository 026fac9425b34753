"""Rewrite the expected lines of the hostile-input corpus from the current code.

Run from anywhere: ``python tests/data/hostile_models/regenerate.py``, then read the diff
(``git diff tests/data/hostile_models/cases.yaml``): every change must be one you meant.
The absolute paths of the checkout and of each case's folder become ``{dir}`` and
``{tmp}`` again, so the file is the same on every machine.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1]))

from model_hostile_corpus import CASES, CORPUS, expected_line, run_case  # noqa: E402

HEADER = (HERE / "cases.yaml").read_text().split("\n- id:")[0].rstrip() + "\n"
KEYS = ("id", "issue", "copy", "make", "args", "status", "stderr", "stdout", "files", "contains")


def main() -> None:
    cases = []
    for case in CASES:
        with tempfile.TemporaryDirectory() as folder:
            tmp = Path(folder)
            outcome = run_case(case, tmp)
            fields = expected_line(outcome)
        updated = {
            key: value for key, value in case.items() if key not in ("status", "stderr", "stdout")
        }
        for key, value in fields.items():
            updated[key] = (
                value.replace(str(tmp), "{tmp}").replace(str(CORPUS), "{dir}")
                if isinstance(value, str)
                else value
            )
        cases.append({key: updated[key] for key in KEYS if key in updated})
        print(f"{case['id']}: {fields}", file=sys.stderr)
    text = yaml.safe_dump(
        cases, sort_keys=False, allow_unicode=True, width=100, default_flow_style=None
    )
    (HERE / "cases.yaml").write_text(HEADER + text)


if __name__ == "__main__":
    main()
