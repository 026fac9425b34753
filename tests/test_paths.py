"""How workbench finds its data: $WORKBENCH_HOME, the checkout, then the installed copy."""

from __future__ import annotations

from pathlib import Path

import pytest

from workbench import paths
from workbench.errors import WorkbenchError

REPO_ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture
def clean_env(monkeypatch):
    for name in ("WORKBENCH_HOME", "WORKBENCH_DATA_DIR", "XDG_DATA_HOME"):
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


@pytest.fixture
def installed(clean_env, tmp_path):
    """Pretend the package is installed from a wheel: no checkout, data in ``_data``."""
    data = tmp_path / "site-packages" / "workbench" / "_data"
    (data / "planning" / "arm3").mkdir(parents=True)
    (data / "planning" / "arm3" / "planning.yaml").write_text("robot: arm3\n")
    (data / "planning" / "scenes").mkdir()
    (data / "planning" / "scenes" / "table.yaml").write_text("objects: []\n")
    (data / "urdf").mkdir()
    clean_env.setattr(paths, "checkout_root", lambda: None)
    clean_env.setattr(paths, "INSTALLED_DATA", data)
    clean_env.setenv("WORKBENCH_DATA_DIR", str(tmp_path / "user"))
    return data


def test_checkout_is_used_in_place(clean_env):
    assert paths.project_root() == REPO_ROOT
    assert paths.urdf_dir() == REPO_ROOT / "urdf"
    assert paths.planning_dir() == REPO_ROOT / "planning"
    assert paths.mapping_dir() == REPO_ROOT / "mapping"
    assert paths.examples_dir() == REPO_ROOT / "examples"


def test_workbench_home_comes_first(clean_env, tmp_path):
    clean_env.setenv("WORKBENCH_HOME", str(tmp_path))
    assert paths.project_root() == tmp_path
    assert paths.planning_dir() == tmp_path / "planning"  # a user's own copy: used in place


def test_workbench_home_that_is_not_a_directory_is_an_error(clean_env, tmp_path):
    clean_env.setenv("WORKBENCH_HOME", str(tmp_path / "missing"))
    with pytest.raises(WorkbenchError, match="WORKBENCH_HOME=.*is not a directory"):
        paths.project_root()


def test_installed_data_is_found_and_planning_goes_to_the_user_data_dir(installed, tmp_path):
    assert paths.project_root() == installed
    assert paths.urdf_dir() == installed / "urdf"
    planning = paths.planning_dir()
    assert planning == tmp_path / "user" / "planning"
    assert (planning / "arm3" / "planning.yaml").read_text() == "robot: arm3\n"
    assert (planning / "scenes" / "table.yaml").is_file()
    assert not list(planning.rglob(".*.seed"))


def test_seeding_keeps_what_the_user_wrote(installed, tmp_path):
    written = paths.planning_dir() / "arm3" / "planning.yaml"
    written.write_text("robot: arm3\nvelocity_scaling: 0.5\n")
    (paths.planning_dir() / "scenes" / "table.yaml").unlink()
    planning = paths.planning_dir()
    assert written.read_text() == "robot: arm3\nvelocity_scaling: 0.5\n"
    assert (planning / "scenes" / "table.yaml").is_file()  # a missing shipped file comes back


def test_unwritable_user_data_dir_is_a_clear_error(installed, clean_env, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    clean_env.setenv("WORKBENCH_DATA_DIR", str(blocker))
    with pytest.raises(WorkbenchError, match="cannot copy the shipped planning configs"):
        paths.planning_dir()


def test_no_data_anywhere_is_a_clear_error(installed, clean_env, tmp_path):
    clean_env.setattr(paths, "INSTALLED_DATA", tmp_path / "nowhere")
    with pytest.raises(WorkbenchError, match="data .* is neither beside"):
        paths.project_root()


def test_user_data_root_order(clean_env, tmp_path):
    clean_env.setattr(Path, "home", lambda: tmp_path / "home")
    assert paths.user_data_root() == tmp_path / "home" / ".local" / "share" / "workbench"
    clean_env.setenv("XDG_DATA_HOME", str(tmp_path / "xdg"))
    assert paths.user_data_root() == tmp_path / "xdg" / "workbench"
    clean_env.setenv("WORKBENCH_DATA_DIR", str(tmp_path / "explicit"))
    assert paths.user_data_root() == tmp_path / "explicit"
