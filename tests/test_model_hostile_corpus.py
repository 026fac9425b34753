"""The hostile-input corpus of issue 17: every input gives its own one line, and nothing else.

Each case of ``tests/data/hostile_models/cases.yaml`` runs in-process in an empty folder.
Its exit status and its line (the whole of stderr, or a finding of ``check`` on
stdout) must be the recorded ones; nothing may be written but the files the case
names (a model that ran ``touch`` would leave a file behind), nor anywhere in the
corpus, ``planning/`` or ``urdf/``; no line may be a traceback or the top-level
guard's "internal error" (the corpus must not lean on the guard). A few cases also
run through the real command line in a fresh process.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from model_fuzz_helpers import run_workbench
from model_hostile_corpus import CASES, CORPUS, WATCHED, fill, inputs, prepare, run_case, snapshot


@pytest.fixture(autouse=True)
def _quiet_environment(monkeypatch, tmp_path):
    monkeypatch.delenv("WORKBENCH_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("WORKBENCH_DEBUG", raising=False)
    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / ".cache"))


def test_every_corpus_file_is_used():
    used = {Path(fill(str(arg), Path("/tmp"))) for case in CASES for arg in case["args"]}
    used |= {CORPUS / name for case in CASES for name in case.get("copy", [])}
    helpers = {"package.xml", "cube.obj", "not_a_mesh.obj", "cases.yaml", "regenerate.py"}
    for path in CORPUS.rglob("*"):
        if path.is_file() and path.name not in helpers and "__pycache__" not in path.parts:
            assert path in used or path.parent in used, f"{path} is in no case"
    assert len({case["id"] for case in CASES}) == len(CASES)


@pytest.mark.parametrize("case", CASES, ids=[case["id"] for case in CASES])
def test_case_gives_its_line(case, tmp_path):
    folder = tmp_path / "run"
    folder.mkdir()
    before = snapshot()
    outcome = run_case(case, folder)
    text = outcome.stdout + outcome.stderr
    assert "Traceback" not in text and "internal error" not in text, text[-2000:]
    assert outcome.status == case["status"], text[-2000:]
    if "stderr" in case:
        assert outcome.stderr.splitlines() == [fill(case["stderr"], folder)]
    if "stdout" in case:
        assert fill(case["stdout"], folder) in outcome.stdout.splitlines()
        # check's stderr is urdfdom's log, as check_urdf prints it, and nothing else
        for line in outcome.stderr.splitlines():
            assert line.startswith(("Error:", "Warning:", "ERROR:")), line
    written = {path.name for path in folder.iterdir()} - inputs(case)
    assert written == set(case.get("files", [])), "files written"
    for name, lines in case.get("contains", {}).items():
        assert set(lines) <= set((folder / name).read_text().splitlines())
    assert snapshot() == before, "a file changed in " + ", ".join(map(str, WATCHED))


def _cli_case(case_id: str) -> dict:
    return next(case for case in CASES if case["id"] == case_id)


@pytest.mark.parametrize(
    "case_id",
    ["xacro_frames", "xacro_power_check", "nan_limit_sdf", "long_name_show", "show_q_nan"],
)
def test_the_real_command_line(case_id, tmp_path):
    """In a fresh process: no signal (Drake aborted on some of these), no traceback."""
    case = _cli_case(case_id)
    args = prepare(case, tmp_path)
    env = {**_environment(), "WORKBENCH_CACHE_DIR": str(tmp_path / ".cache")}
    result = run_workbench(args, tmp_path, case_id, env)
    assert result.returncode == case["status"], result.stderr[-2000:]
    assert result.stderr.splitlines() == [fill(case["stderr"], tmp_path)]
    assert sorted(path.name for path in tmp_path.iterdir() if path.name != ".cache") == []


_INTERRUPTED = """
import sys
import xacro
import workbench.model.check, workbench.model.xacro_sandbox
from workbench.cli import main
print("ready", flush=True)
sys.exit(main(["check", sys.argv[1]]))
"""


def test_ctrl_c_stops_an_expanding_xacro(tmp_path):
    """SIGINT reaches a xacro expansion in progress: no computation runs long in C."""
    import signal
    import time

    source = CORPUS / "models" / "xacro_work.urdf.xacro"  # about 2 s of bounded work
    process = subprocess.Popen(
        [sys.executable, "-c", _INTERRUPTED, str(source)],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=_environment(),
    )
    try:
        assert process.stdout is not None
        assert process.stdout.readline() == "ready\n"
        time.sleep(0.5)  # into the expansion
        process.send_signal(signal.SIGINT)
        _, stderr = process.communicate(timeout=120)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 130, stderr[-2000:]
    assert "Traceback" not in stderr


def _environment() -> dict[str, str]:
    import os

    env = dict(os.environ)
    for name in ("WORKBENCH_DEBUG", "WORKBENCH_PACKAGE_PATH", "ROS_PACKAGE_PATH"):
        env.pop(name, None)
    return env
