"""The hostile-input corpus (``tests/data/hostile/``): each input gets its own one-line message.

Every case runs its ``workbench`` command in this process and must print exactly what the
corpus records (format and regeneration: ``tests/hostile_corpus.py``). The CLI's last-resort
guard is not what makes these pass: each message is raised where the input is read.
"""

from __future__ import annotations

import pytest
from hostile_corpus import HOSTILE, case_ids, cases, run_case

KINDS = tuple(sorted(p.parent.name for p in HOSTILE.glob("*/cases.yaml")))

CASES = [(kind, case) for kind in KINDS for case in cases(kind)]


@pytest.mark.parametrize(
    ("kind", "case"), CASES, ids=[f"{kind}: {name}" for kind in KINDS for name in case_ids(kind)]
)
def test_hostile_input_gets_its_own_message(kind, case, tmp_path):
    result = run_case(case, kind, tmp_path)
    assert result["stderr"] == case["stderr"]
    assert result["status"] == case["status"]
    for line in case.get("stdout", []):
        assert line in result["stdout"]
    assert not list(tmp_path.rglob("*pwned*")), "a hostile input ran a command"
    if case["status"] != 0:
        assert len(result["stderr"].splitlines()) == 1
        assert "please report this" not in result["stderr"]
