"""The package skeleton: cheap import, the command line front end, the error hierarchy."""

from __future__ import annotations

import subprocess
import sys

import pytest

from workbench import errors
from workbench.cli import COMMANDS, available_commands


def test_import_workbench_does_not_import_heavy_libraries():
    code = (
        "import sys, workbench, workbench.cli, workbench.errors, workbench.paths;"
        "heavy = [m for m in ('pydrake', 'ompl', 'zenoh', 'toppra', 'matplotlib') if m in sys.modules];"
        "print(','.join(heavy))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_help_lists_every_available_command(run_cli):
    result = run_cli("--help")
    assert result.returncode == 0
    for name in available_commands():
        assert name in result.stdout
    assert "usage: workbench" in result.stdout


def test_unknown_command_is_refused_with_usage(run_cli):
    result = run_cli("frobnicate")
    assert result.returncode == 2
    assert "invalid choice: 'frobnicate'" in result.stderr


def test_version(run_cli):
    result = run_cli("--version")
    assert result.returncode == 0
    assert result.stdout.startswith("workbench ")


def test_every_command_module_has_the_command_protocol():
    import importlib

    for name in available_commands():
        module = importlib.import_module(f"workbench.cli.{name}")
        assert callable(module.configure), name
        assert callable(module.run), name
    assert set(available_commands()) <= set(COMMANDS)


def test_error_one_line_names_file_line_and_hint():
    error = errors.ModelError("joint 'j1' has no parent", path="arm.urdf", line=12, hint="add one")
    assert str(error) == "arm.urdf:12: joint 'j1' has no parent (add one)"
    assert isinstance(error, errors.WorkbenchError)


def test_missing_dependency_is_an_import_error_naming_the_extra(monkeypatch):
    from workbench.optional import require

    monkeypatch.setitem(sys.modules, "ompl", None)  # makes `import ompl` fail
    with pytest.raises(ImportError) as info:
        require("ompl")
    assert "workbench[plan]" in str(info.value)


def test_a_missing_extra_is_one_line_naming_the_extra(tmp_path):
    # A command whose optional package is missing reports the extra, not a traceback.
    blocker = tmp_path / "sitecustomize.py"
    blocker.write_text(
        "import sys\n"
        "class _Block:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name == 'ompl' or name.startswith('ompl.'):\n"
        "            raise ModuleNotFoundError(\"No module named 'ompl'\", name='ompl')\n"
        "sys.meta_path.insert(0, _Block())\n"
    )
    env = {"PYTHONPATH": str(tmp_path)}
    import os

    result = subprocess.run(
        [sys.executable, "-m", "workbench", "plan", "arm3", "--to", "home"],
        capture_output=True,
        text=True,
        env={**os.environ, **env},
        timeout=300,
    )
    assert result.returncode == 1
    assert "Traceback" not in result.stderr
    assert "workbench[plan]" in result.stderr
