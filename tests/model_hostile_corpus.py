"""Run the cases of the hostile-input corpus (``tests/data/hostile_models/cases.yaml``).

Shared by ``tests/test_model_hostile_corpus.py`` and ``tests/data/hostile_models/regenerate.py``.
A case runs in-process through ``workbench.cli.main`` in its own empty folder, which
is also the working directory.
"""

from __future__ import annotations

import contextlib
import io
import os
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO / "tests" / "data" / "hostile_models"
CASES: list[dict[str, Any]] = yaml.safe_load((CORPUS / "cases.yaml").read_text())
#: Folders no case may write into (compared before and after each case).
WATCHED = (CORPUS, REPO / "planning", REPO / "urdf")


@dataclass
class Outcome:
    """What a case printed and returned."""

    status: int
    stdout: str
    stderr: str


def fill(text: str, tmp: Path) -> str:
    """``text`` with ``{dir}`` and ``{tmp}`` replaced."""
    return text.replace("{dir}", str(CORPUS)).replace("{tmp}", str(tmp))


def prepare(case: dict[str, Any], tmp: Path) -> list[str]:
    """Copy and make the case's files in ``tmp``; returns its command line."""
    for name in case.get("copy", []):
        shutil.copy(CORPUS / name, tmp / Path(name).name)
    made = case.get("make", {})
    for name, size in made.get("sparse", {}).items():
        with open(tmp / name, "wb") as handle:
            handle.truncate(int(size))
    for name in made.get("fifo", []):
        os.mkfifo(tmp / name)
    for name, links in made.get("sdf_chain", {}).items():
        (tmp / name).write_text(sdf_chain(int(links)))
    return [fill(str(arg), tmp) for arg in case["args"]]


def sdf_chain(links: int) -> str:
    """An SDF model of ``links`` + 1 links in one chain of fixed joints."""
    parts = ['<?xml version="1.0"?>', '<sdf version="1.7">', '<model name="chain">']
    parts += [f'<link name="l{i}"/>' for i in range(links + 1)]
    parts += [
        f'<joint name="j{i}" type="fixed"><parent>l{i}</parent><child>l{i + 1}</child></joint>'
        for i in range(links)
    ]
    return "\n".join([*parts, "</model>", "</sdf>", ""])


def inputs(case: dict[str, Any]) -> set[str]:
    """The names :func:`prepare` puts into the case's folder."""
    made = case.get("make", {})
    names = {Path(name).name for name in case.get("copy", [])}
    return (
        names
        | set(made.get("sparse", {}))
        | set(made.get("fifo", []))
        | set(made.get("sdf_chain", {}))
    )


def snapshot(folders: tuple[Path, ...] = WATCHED) -> dict[str, tuple[int, int]]:
    """Every file below ``folders`` with its size and modification time."""
    found = {}
    for folder in folders:
        for path in folder.rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts:
                info = path.stat()
                found[str(path)] = (info.st_size, info.st_mtime_ns)
    return found


def run_case(case: dict[str, Any], tmp: Path) -> Outcome:
    """Run one case in ``tmp`` (the working directory meanwhile)."""
    from workbench.cli import main

    args = prepare(case, tmp)
    stdout, stderr = io.StringIO(), io.StringIO()
    previous = Path.cwd()
    os.chdir(tmp)
    try:
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            status = main(args)
    finally:
        os.chdir(previous)
    return Outcome(status, stdout.getvalue(), stderr.getvalue())


def expected_line(outcome: Outcome) -> dict[str, Any]:
    """The expectation fields a case's outcome gives (what ``regenerate.py`` writes)."""
    result: dict[str, Any] = {"status": outcome.status}
    errors = [line for line in outcome.stdout.splitlines() if ": error: " in line]
    if errors:
        result["stdout"] = errors[0]
    elif outcome.stderr.strip():
        result["stderr"] = outcome.stderr.strip()
    else:
        lines = outcome.stdout.strip().splitlines()
        result["stdout"] = lines[-1] if lines else ""
    return result
