"""The generated message stubs: current, and what a type checker makes of them."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

from workbench.msgs import _stubgen

REPO_ROOT = Path(__file__).resolve().parents[2]


def require_mypy() -> None:
    """Skip (fail under WORKBENCH_REQUIRE_ALL=1) when mypy, a test extra, is not installed."""
    if importlib.util.find_spec("mypy") is None:
        from skipping import skip_or_fail

        skip_or_fail("mypy is not installed (it is in the test extra: pip install -e '.[test]')")


def test_committed_stubs_equal_a_fresh_generation():
    fresh = _stubgen.render_all()
    committed = {p.name: p.read_text(encoding="utf-8") for p in _stubgen.MSGS_DIR.glob("*.pyi")}
    assert set(fresh) == set(committed), "run: python -m workbench.msgs._stubgen"
    stale = [name for name in fresh if fresh[name] != committed[name]]
    assert not stale, f"stale stubs {stale}; run: python -m workbench.msgs._stubgen"


def test_every_package_module_has_a_stub():
    modules = {p.stem for p in _stubgen.MSGS_DIR.glob("*.py") if not p.stem.startswith("_")}
    assert "geometry_msgs" in modules and "builtin_interfaces" in modules
    assert {p.stem for p in _stubgen.MSGS_DIR.glob("*.pyi")} == modules


def test_each_stub_declares_exactly_the_classes_its_module_exports():
    import ast
    import importlib

    for stub in sorted(_stubgen.MSGS_DIR.glob("*.pyi")):
        module = importlib.import_module(f"workbench.msgs.{stub.stem}")
        tree = ast.parse(stub.read_text(encoding="utf-8"))
        classes = {node.name for node in tree.body if isinstance(node, ast.ClassDef)}
        assert classes == set(module.__all__), stub.name
        for cls in classes:  # every message field, in order, as the runtime class has them
            runtime = getattr(module, cls)
            if (
                hasattr(runtime, "__slots__")
                and runtime.__slots__
                and stub.stem != "builtin_interfaces"
            ):
                node = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == cls)
                init = next(
                    f for f in node.body if isinstance(f, ast.FunctionDef) and f.name == "__init__"
                )
                assert [a.arg for a in init.args.args[1:]] == list(runtime.__slots__), cls


def test_stubs_declare_every_field_and_constant_the_classes_have():
    from workbench.msgs import get_type

    text = (_stubgen.MSGS_DIR / "visualization_msgs.pyi").read_text(encoding="utf-8")
    marker = get_type("visualization_msgs/Marker")
    body = text.split("class Marker(Message):", 1)[1].split("\nclass ", 1)[0]
    for field in marker.__slots__:
        assert f" {field}" in body, field
    assert f"ARROW: Final = {marker.ARROW}" in body
    assert "def points(self) -> list[geometry_msgs.Point]: ..." in body
    assert "def header(self) -> std_msgs.Header: ..." in body


def _mypy(tmp_path: Path, source: str) -> subprocess.CompletedProcess[str]:
    require_mypy()
    program = tmp_path / "program.py"
    program.write_text(source)
    env = dict(os.environ, MYPYPATH=str(REPO_ROOT))
    return subprocess.run(
        [
            sys.executable,
            "-m",
            "mypy",
            "--config-file",
            str(REPO_ROOT / "pyproject.toml"),
            "--cache-dir",
            str(REPO_ROOT / ".mypy_cache" / "stub-tests"),
            str(program),
        ],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
    )


def test_mypy_accepts_what_the_classes_allow(tmp_path):
    result = _mypy(
        tmp_path,
        "from workbench.msgs.builtin_interfaces import Duration, Time\n"
        "from workbench.msgs.geometry_msgs import Twist, Vector3\n"
        "from workbench.msgs.sensor_msgs import JointState\n"
        "from workbench.msgs.turtlesim import Spawn\n"
        "from workbench.msgs.visualization_msgs import Marker\n"
        "twist = Twist(linear=Vector3(x=1.0), angular={'z': 2})\n"
        "speed: float = twist.linear.x + 1.0\n"
        "state = JointState(name=['a', 'b'])\n"
        "state.position = [0.1, 0.2]\n"
        "total: float = float(state.position.sum())\n"
        "first: str = state.name[0]\n"
        "age: Duration = state.header.stamp - Time(1.5)\n"
        "later: Time = state.header.stamp + age\n"
        "seconds: float = age.to_sec()\n"
        "name: str = Spawn.Request(x=1.0, y=2.0, name='t2').name\n"
        "kind: int = Marker.ARROW\n"
        "from workbench.msgs import geometry_msgs, turtlesim\n"
        "lab: float = geometry_msgs.msg.Twist().angular.z\n"
        "spawn: turtlesim.SpawnRequest = turtlesim.srv.Spawn.Request(name='t3')\n"
        "reveal_type(state.position)\n",
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "ndarray" in result.stdout and "float64" in result.stdout


def test_mypy_rejects_fields_and_types_the_classes_reject(tmp_path):
    result = _mypy(
        tmp_path,
        "from workbench.msgs.geometry_msgs import Twist\n"
        "a = Twist().linear.nope\n"
        "Twist().linear.x = 'fast'\n"
        "Twist(linaer={})\n",
    )
    assert result.returncode == 1, result.stdout + result.stderr
    assert 'program.py:2: error: "Vector3" has no attribute "nope"' in result.stdout
    assert "program.py:3: error: Incompatible types in assignment" in result.stdout
    assert 'program.py:4: error: Unexpected keyword argument "linaer"' in result.stdout
