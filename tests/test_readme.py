"""The README's two set-up commands, and .ci/run running exactly the test one."""

from __future__ import annotations

import re
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent


def _command_after(marker: str) -> str:
    text = (REPO_ROOT / "README.md").read_text()
    match = re.search(rf"<!-- {marker} -->\s*```bash\n(.+?)\n```", text, re.S)
    assert match, f"README.md has no ```bash block after <!-- {marker} -->"
    return match.group(1).strip()


def test_readme_has_exactly_two_setup_commands():
    text = (REPO_ROOT / "README.md").read_text()
    quick_start = text.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    assert quick_start.count("```bash") == 2


def test_ci_runs_exactly_the_readme_test_command():
    command = _command_after("test-command")
    ci_lines = [line.strip() for line in (REPO_ROOT / ".ci" / "run").read_text().splitlines()]
    assert command in ci_lines


def test_main_command_installs_then_runs_workbench():
    command = _command_after("main-command")
    assert "pip install" in command
    assert re.search(r"&& workbench \w+", command)
