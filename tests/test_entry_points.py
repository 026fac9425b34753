"""Nodes as entry points: declared in pyproject.toml, found by name, run with only their module."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

if sys.version_info >= (3, 11):
    import tomllib
else:  # pytest depends on tomli before 3.11
    import tomli as tomllib

from workbench.bus import registry
from workbench.cli import main as cli_main
from workbench.cli.run import list_nodes, run_node
from workbench.entry_points import (
    _RUNTIME,
    GROUP,
    UnknownNodeError,
    declared_nodes,
    find_node,
    load_node,
    register_node,
)

REPO_ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture
def node_module(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> str:
    """A module ``probe_nodes`` whose ``main`` writes its argv to ``argv.json`` and returns 3."""
    (tmp_path / "probe_nodes.py").write_text(
        textwrap.dedent(
            f"""
            import json

            def main(argv):
                with open({str(tmp_path / "argv.json")!r}, "w") as out:
                    json.dump(argv, out)
                return 3

            def quiet(argv):
                return None

            not_a_function = 1
            """
        )
    )
    (tmp_path / "broken_nodes.py").write_text("import no_such_dependency_xyz\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    saved = dict(_RUNTIME)
    yield "probe_nodes"
    _RUNTIME.clear()
    _RUNTIME.update(saved)
    for name in ("probe_nodes", "broken_nodes"):
        sys.modules.pop(name, None)


def test_every_node_of_pyproject_is_declared_and_loads() -> None:
    table = tomllib.loads((REPO_ROOT / "pyproject.toml").read_text())
    wanted = table["project"]["entry-points"][GROUP]
    assert "turtlesim/turtlesim_node" in wanted and len(wanted) >= 9
    declared = declared_nodes()
    stale = {name: target for name, target in wanted.items() if declared.get(name) != target}
    assert not stale, f"installed metadata is stale, re-run `pip install -e .`: {stale}"
    for target in wanted.values():
        assert callable(load_node(target))


def test_both_spellings_of_an_executable_find_the_node(node_module: str) -> None:
    assert find_node("turtlesim", "turtlesim_node") == "workbench.turtlesim.node:main"
    assert find_node("turtlesim", "turtlesim_node.py") == "workbench.turtlesim.node:main"
    register_node("rosserial_python/serial_node.py", f"{node_module}:main")
    assert find_node("rosserial_python", "serial_node") == f"{node_module}:main"
    assert find_node("rosserial_python", "serial_node.py") == f"{node_module}:main"
    assert find_node("turtlesim", "no_such_node") is None


def test_run_calls_the_node_with_its_arguments(node_module: str, tmp_path: Path) -> None:
    register_node("probe/talker", f"{node_module}:main")
    assert run_node("probe", "talker.py", ["chatter:=/x", "_rate:=5"]) == 3
    assert json.loads((tmp_path / "argv.json").read_text()) == ["chatter:=/x", "_rate:=5"]
    register_node("probe/quiet", f"{node_module}:quiet")
    assert run_node("probe", "quiet", []) == 0


def test_run_falls_back_to_a_script(tmp_path: Path) -> None:
    (tmp_path / "hello.py").write_text(
        f"import sys, json\njson.dump(sys.argv[1:], open({str(tmp_path / 'out.json')!r}, 'w'))\n"
    )
    assert run_node("my_pkg", "hello.py", ["a", "b"], near=tmp_path) == 0
    assert json.loads((tmp_path / "out.json").read_text()) == ["a", "b"]


def test_unknown_node_is_one_line_listing_the_known_nodes(capsys: pytest.CaptureFixture) -> None:
    with pytest.raises(UnknownNodeError) as error:
        run_node("turtlesim", "no_such_node", [])
    line = error.value.one_line()
    assert "\n" not in line
    assert "no node 'no_such_node' in package 'turtlesim'" in line
    assert "turtlesim/turtlesim_node" in line and "tf2_ros/static_transform_publisher" in line
    assert cli_main(["run", "turtlesim", "no_such_node"]) == error.value.exit_code
    assert "turtlesim/turtlesim_node" in capsys.readouterr().err
    with pytest.raises(UnknownNodeError, match="give a package and an executable"):
        run_node("turtlesim", None)


def test_bad_entry_points_say_what_is_wrong(node_module: str) -> None:
    with pytest.raises(UnknownNodeError, match="no module 'no_such_module_xyz'"):
        load_node("no_such_module_xyz:main")
    with pytest.raises(UnknownNodeError, match="has no 'missing'"):
        load_node(f"{node_module}:missing")
    with pytest.raises(UnknownNodeError, match="is not a function"):
        load_node(f"{node_module}:not_a_function")
    # A missing dependency of the node is not an unknown node: the CLI names the extra.
    with pytest.raises(ModuleNotFoundError, match="no_such_dependency_xyz"):
        load_node("broken_nodes:main")
    with pytest.raises(Exception, match="cannot register node"):
        register_node("no-slash", "m:f")


def test_list_prints_every_declared_node(capsys: pytest.CaptureFixture) -> None:
    assert list_nodes() == 0
    lines = capsys.readouterr().out.splitlines()
    assert "turtlesim/turtlesim_node  (workbench.turtlesim.node:main)" in lines
    assert len(lines) == len(declared_nodes())
    assert cli_main(["run", "--list"]) == 0
    assert capsys.readouterr().out.splitlines() == lines


def test_bus_registry_keeps_its_names() -> None:
    assert registry.registered_nodes() == declared_nodes()
    assert registry.entry_point("tf", "static_transform_publisher") == (
        "workbench.tf.nodes:static_transform_publisher"
    )
    with pytest.raises(registry.UnknownNodeError, match="known nodes"):
        registry.entry_point("tf", "nothing")


def test_workbench_run_imports_only_the_nodes_module(tmp_path: Path) -> None:
    """Through the CLI front end, in a fresh interpreter: no bus, no launcher, no pydrake."""
    code = textwrap.dedent(
        """
        import json, sys
        from workbench.entry_points import register_node
        register_node("probe/modules", "probe_modules:main")
        from workbench.cli import main
        sys.exit(main(["run", "probe", "modules", "x"]))
        """
    )
    (tmp_path / "probe_modules.py").write_text(
        textwrap.dedent(
            f"""
            import json, sys
            def main(argv):
                names = sorted(n for n in sys.modules if n.startswith(("workbench", "pydrake")))
                json.dump(names, open({str(tmp_path / "modules.json")!r}, "w"))
                return 0
            """
        )
    )
    env_path = f"{tmp_path}:{REPO_ROOT}"
    result = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": env_path},
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stderr
    imported = json.loads((tmp_path / "modules.json").read_text())
    heavy = [n for n in imported if n.startswith(("workbench.bus", "pydrake", "workbench.model"))]
    assert not heavy, f"`workbench run` imported {heavy} before the node ran"
    assert "workbench.cli.run" in imported and "workbench.entry_points" in imported


def test_stale_metadata_is_named_in_the_error(monkeypatch: pytest.MonkeyPatch) -> None:
    import workbench.entry_points as module

    monkeypatch.setattr(module, "entry_points", lambda group: [])
    with pytest.raises(UnknownNodeError, match=r"known nodes: none.*run `pip install -e \.`"):
        run_node("turtlesim", "turtlesim_node", [])


def test_a_third_party_distribution_adds_nodes(node_module: str, tmp_path: Path) -> None:
    """An installed distribution (a ``.dist-info`` on sys.path) that declares the group."""
    info = tmp_path / "my_robot-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: my_robot\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(
        f"[{GROUP}]\nmy_robot/driver_node.py = {node_module}:main\n"
    )
    assert declared_nodes()["my_robot/driver_node.py"] == f"{node_module}:main"
    assert run_node("my_robot", "driver_node", ["/dev/ttyACM0"]) == 3
    assert json.loads((tmp_path / "argv.json").read_text()) == ["/dev/ttyACM0"]
