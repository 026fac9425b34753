"""Shared test helpers.

* ``require_program("dot")`` skips a test when a system program is missing,
  and fails it instead when ``WORKBENCH_REQUIRE_ALL=1`` (as ``.ci/run`` sets).
* ``intel_log`` is the Intel Research Lab log shipped in ``mapping/logs/``.
* ``run_notebook(name)`` executes ``notebooks/<name>`` in a real kernel with
  ``WORKBENCH_NOTEBOOK_MODE=short``.
* ``run_cli(*args)`` runs ``python -m workbench`` in a subprocess.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from workbench.optional import find_program

REPO_ROOT = Path(__file__).resolve().parent.parent
DATA_DIR = Path(__file__).resolve().parent / "data"

# Tests never join a core the developer happens to be running on the default
# port; multiprocess tests start their own on a free port and set the URI.
os.environ.setdefault("WORKBENCH_MASTER_URI", "inproc")


from skipping import require_all, skip_or_fail  # noqa: E402,F401 - re-exported for tests


@pytest.fixture
def require_program():
    def _require(name: str) -> str:
        path = find_program(name)
        if path is None:
            skip_or_fail(f"system program '{name}' is not installed")
        return path

    return _require


@pytest.fixture(scope="session")
def intel_log() -> Path:
    """The Intel Research Lab log (CARMEN, corrected), shipped in ``mapping/logs/``."""
    return REPO_ROOT / "mapping" / "logs" / "intel-corrected.log.gz"


@pytest.fixture(scope="session")
def repo_root() -> Path:
    return REPO_ROOT


@pytest.fixture(scope="session")
def data_dir() -> Path:
    return DATA_DIR


@pytest.fixture
def run_cli():
    """Run ``python -m workbench ARGS`` and return the CompletedProcess (text mode)."""

    def _run(*args: str, cwd: Path | None = None, timeout: float = 300, env=None, input=None):
        full_env = dict(os.environ)
        full_env.pop("WORKBENCH_DEBUG", None)
        if env:
            full_env.update(env)
        return subprocess.run(
            [sys.executable, "-m", "workbench", *map(str, args)],
            cwd=cwd,
            capture_output=True,
            text=True,
            timeout=timeout,
            env=full_env,
            input=input,
        )

    return _run


class ExecutedNotebook:
    """A notebook after execution: ``.notebook``, its code cells' ``.outputs`` and their ``.text``."""

    def __init__(self, notebook) -> None:
        self.notebook = notebook
        self.outputs = [
            output
            for cell in notebook.cells
            if cell.cell_type == "code"
            for output in cell.get("outputs", [])
        ]
        self.text = "".join(output.get("text", "") for output in self.outputs)


@pytest.fixture
def run_notebook(tmp_path, monkeypatch):
    """Execute a notebook from ``notebooks/`` in short mode; returns an :class:`ExecutedNotebook`.

    The kernel (and every process it starts) works in the empty folder
    ``tmp_path/"cwd"``, which stands for ``notebooks/``; ``WORKBENCH_OUTPUT_DIR`` is
    ``tmp_path/"output"``. Afterwards the working folder must still be empty and
    files may exist only under ``tmp_path/"output"/<notebook name>``: running a
    notebook leaves ``notebooks/`` as cloned.
    """

    def _run(name: str, timeout: float = 600):
        import nbformat
        from nbclient import NotebookClient

        path = REPO_ROOT / "notebooks" / name
        notebook = nbformat.read(path, as_version=4)
        cwd = tmp_path / "cwd"
        output = tmp_path / "output"
        cwd.mkdir()
        monkeypatch.setenv("WORKBENCH_NOTEBOOK_MODE", "short")
        monkeypatch.setenv("WORKBENCH_OUTPUT_DIR", str(output))
        client = NotebookClient(
            notebook,
            timeout=timeout,
            kernel_name="python3",
            resources={"metadata": {"path": str(cwd)}},
        )
        client.execute()
        left = sorted(str(p.relative_to(cwd)) for p in cwd.rglob("*"))
        assert not left, f"{name} wrote into its working folder (notebooks/): {left}"
        stray = sorted(p.name for p in tmp_path.iterdir() if p not in (cwd, output))
        assert not stray, f"{name} wrote beside its output folder: {stray}"
        lab = Path(name).stem
        if output.exists():
            others = sorted(p.name for p in output.iterdir() if p.name != lab)
            assert not others, f"{name} wrote outside notebook_output({lab!r}): {others}"
        return ExecutedNotebook(notebook)

    return _run


@pytest.fixture
def free_uri() -> str:
    """A ``tcp/127.0.0.1:PORT`` core address on a port free right now."""
    import socket

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return f"tcp/127.0.0.1:{sock.getsockname()[1]}"
