"""``workbench slam`` and ``workbench map show`` on the command line."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.mapping import load_map
from workbench.mapping.carmen import write_carmen
from workbench.mapping.simulate import demo_world, loop_trajectory, simulate_scans


@pytest.fixture(scope="module")
def sim_log(tmp_path_factory):
    path = tmp_path_factory.mktemp("logs") / "room.log"
    scans = simulate_scans(
        demo_world(), loop_trajectory(step=0.4), odometry_noise=(0.02, 0.01), seed=11
    )
    return write_carmen(path, scans)


def test_slam_writes_map_picture_and_trajectory(run_cli, sim_log, tmp_path):
    result = run_cli("slam", sim_log, "--out", tmp_path / "room", "--resolution", "0.1")
    assert result.returncode == 0, result.stderr
    assert "loop closures" in result.stdout and "real time" in result.stdout
    assert "100%" in result.stderr  # the progress bar
    grid = load_map(tmp_path / "room.yaml")
    assert grid.resolution == pytest.approx(0.1)
    assert (grid.data == 100).sum() > 100 and (grid.data == 0).sum() > 1000
    assert (tmp_path / "room.png").read_bytes()[:4] == b"\x89PNG"
    rows = np.loadtxt(tmp_path / "room.csv", delimiter=",", skiprows=1)
    assert rows.shape[1] == 4 and len(rows) == len(loop_trajectory(step=0.4))
    assert (tmp_path / "room.csv").read_text().startswith("t,x,y,theta\n")

    shown = run_cli(
        "map",
        "show",
        tmp_path / "room.yaml",
        "--png",
        tmp_path / "s.png",
        "--trajectory",
        tmp_path / "room.csv",
    )
    assert shown.returncode == 0, shown.stderr
    assert "at 0.100 m/cell" in shown.stdout and "occupied" in shown.stdout
    assert (tmp_path / "s.png").exists()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["slam", "{tmp}/absent.log"], "log file not found"),
        (["slam", "{log}", "--out", "{tmp}/no/dir/map"], "output directory does not exist"),
        (["slam", "{log}", "--resolution", "-1"], "--resolution"),
        (["slam", "{tmp}/empty.log"], "no laser lines"),
        (["map", "show", "{tmp}/absent.yaml"], "map YAML not found"),
        (["map", "show", "{tmp}/nokey.yaml"], "no 'resolution' key"),
    ],
)
def test_bad_input_is_one_line_error(run_cli, sim_log, tmp_path, args, message):
    (tmp_path / "empty.log").write_text("ODOM 0 0 0 0 0 0 1 host 1\n")
    (tmp_path / "nokey.yaml").write_text("image: x.pgm\n")
    args = [a.format(tmp=tmp_path, log=sim_log) for a in args]
    result = (
        run_cli(*args, "--out", tmp_path / "m")
        if args[0] == "slam" and "--out" not in args
        else run_cli(*args)
    )
    assert result.returncode == 1
    assert message in result.stderr
    errors = [line for line in result.stderr.splitlines() if "error:" in line]
    assert len(errors) == 1 and "Traceback" not in result.stderr
