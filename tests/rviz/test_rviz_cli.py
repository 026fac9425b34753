"""`workbench rviz` with the manual's programs, RViz configs, snapshots and bad configs."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from process_helpers import private_core, wait_for

from workbench.viz.snapshot import snapshot_paths

CONFIG = """Panels: []
Visualization Manager:
  Class: ""
  Displays:
    - Class: rviz/Grid
      Name: Grid
      Enabled: true
      Plane Cell Count: 10
      Cell Size: 1
    - Class: rviz/Marker
      Name: Shapes
      Enabled: true
      Marker Topic: visualization_marker
    - Class: rviz/InteractiveMarkers
      Name: Controls
      Enabled: true
      Update Topic: /simple_marker/update
    - Class: rviz/InteractiveMarkers
      Name: Basic
      Enabled: true
      Update Topic: /basic_controls/update
    - Class: rviz/Camera
      Name: Camera
      Enabled: true
      Image Topic: /camera/image_raw
  Global Options:
    Fixed Frame: my_frame
"""


def _env(uri: str) -> dict[str, str]:
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    return env


@contextlib.contextmanager
def _started(args: list[str], uri: str, cwd: Path, log_name: str):
    log = open(cwd / log_name, "w")  # noqa: SIM115 - closed in finally
    process = subprocess.Popen(
        [sys.executable, "-m", "workbench", *args], env=_env(uri), cwd=cwd,
        stdout=log, stderr=subprocess.STDOUT, start_new_session=True,
    )  # fmt: skip
    try:
        yield process
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
        log.close()


def _wait_for_publishers(uri: str, topics: set[str], timeout: float = 120.0) -> None:
    """Until every topic has a publisher on the core (the programs are up), however busy."""
    from workbench.bus import Bus

    def ready() -> set[str]:
        graph = bus.graph()
        return {t for t in topics if t in graph.topics and graph.topics[t].publishers}

    with Bus.connect(uri) as bus:
        assert wait_for(lambda: ready() == topics, timeout), f"no publishers on {topics - ready()}"


@pytest.mark.multiprocess
@pytest.mark.slow
def test_the_manual_programs_draw_in_workbench_rviz(tmp_path):
    (tmp_path / "lab.rviz").write_text(CONFIG)
    with (
        private_core(tmp_path) as uri,  # up before the programs, or they run in-process
        _started(["run", "using_markers", "basic_shapes.py"], uri, tmp_path, "shapes.log"),
        _started(["run", "using_markers", "simple_marker.py"], uri, tmp_path, "simple.log"),
        _started(["run", "using_markers", "points_and_lines.py"], uri, tmp_path, "lines.log"),
        _started(["run", "using_markers", "basic_controls.py"], uri, tmp_path, "basic.log"),
    ):
        _wait_for_publishers(
            uri,
            {"/visualization_marker", "/simple_marker/update", "/basic_controls/update"},
        )
        done = subprocess.run(
            [sys.executable, "-m", "workbench", "rviz", "-d", "lab.rviz", "--after", "4",
             "--html", "view.html"],
            env=_env(uri), cwd=tmp_path, capture_output=True, text=True, timeout=120,
        )  # fmt: skip
    assert done.returncode == 0, done.stdout + done.stderr
    assert "not drawn here (unknown display classes): Camera (rviz/Camera)" in done.stderr
    assert "fixed frame: my_frame" in done.stdout
    paths = set(snapshot_paths(tmp_path / "view.html"))
    assert "/rviz/Shapes/basic_shapes/0" in paths  # the cycling shape
    assert {f"/rviz/Shapes/points_and_lines/{i}" for i in range(3)} <= paths
    assert any(p.startswith("/rviz/Controls/my_marker") for p in paths)
    for name in ("simple_6dof", "quadrocopter", "chess_piece", "context_menu", "button", "mesh"):
        assert any(p.startswith(f"/rviz/Basic/{name}/") for p in paths), name
    assert "Please create a subscriber to the marker" in (tmp_path / "shapes.log").read_text()


def test_rviz_node_name_and_snapshot_without_a_bus(tmp_path, run_cli):
    done = run_cli(
        "run", "rviz", "rviz", "--fixed-frame", "map", "--after", "0.2", "--html", "empty.html",
        cwd=tmp_path, env={"WORKBENCH_MASTER_URI": "inproc"},
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "/rviz/Grid" in snapshot_paths(tmp_path / "empty.html")


@pytest.mark.parametrize(
    "text, message",
    [
        ("a: [unclosed", "not valid YAML"),
        ("Panels: []\n", "not an RViz config: no 'Visualization Manager' section"),
    ],
)
def test_bad_configs_are_one_line_errors(tmp_path, run_cli, text, message):
    (tmp_path / "bad.rviz").write_text(text)
    done = run_cli(
        "rviz",
        "-d",
        "bad.rviz",
        "--after",
        "0",
        cwd=tmp_path,
        env={"WORKBENCH_MASTER_URI": "inproc"},
    )
    assert done.returncode != 0
    lines = [line for line in done.stderr.splitlines() if line.strip() and "Meshcat" not in line]
    assert len(lines) == 1 and message in lines[0] and "bad.rviz" in lines[0], done.stderr
