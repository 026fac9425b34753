"""``workbench slam`` and ``workbench map show``: their functions and their one-line errors."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.cli import main
from workbench.cli import map as map_cli
from workbench.cli import slam as slam_cli
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


def test_slam_writes_map_picture_and_trajectory(capsys, sim_log, tmp_path):
    assert slam_cli.slam(str(sim_log), out=str(tmp_path / "room"), resolution=0.1) == 0
    result = capsys.readouterr()
    assert "loop closures" in result.out and "real time" in result.out
    assert "100%" in result.err  # the progress bar
    grid = load_map(tmp_path / "room.yaml")
    assert grid.resolution == pytest.approx(0.1)
    assert (grid.data == 100).sum() > 100 and (grid.data == 0).sum() > 1000
    assert (tmp_path / "room.png").read_bytes()[:4] == b"\x89PNG"
    rows = np.loadtxt(tmp_path / "room.csv", delimiter=",", skiprows=1)
    assert rows.shape[1] == 4 and len(rows) == len(loop_trajectory(step=0.4))
    assert (tmp_path / "room.csv").read_text().startswith("t,x,y,theta\n")

    shown = map_cli.show(
        str(tmp_path / "room.yaml"),
        png=str(tmp_path / "s.png"),
        trajectory=str(tmp_path / "room.csv"),
    )
    assert shown == 0
    out = capsys.readouterr().out
    assert "at 0.100 m/cell" in out and "occupied" in out
    assert (tmp_path / "s.png").exists()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["slam", "{tmp}/absent.log"], "log file not found"),
        (["slam", "{log}", "--out", "{tmp}/no/dir/map"], "output directory does not exist"),
        (["slam", "{log}", "--resolution", "-1"], "--resolution"),
        (["slam", "{log}", "--max-range", "0"], "--max-range"),
        (["slam", "{tmp}/empty.log"], "no laser lines"),
        (["map", "show", "{tmp}/absent.yaml"], "map YAML not found"),
        (["map", "show", "{tmp}/nokey.yaml"], "no 'resolution' key"),
    ],
)
def test_bad_input_is_one_line_error(capsys, sim_log, tmp_path, args, message):
    (tmp_path / "empty.log").write_text("ODOM 0 0 0 0 0 0 1 host 1\n")
    (tmp_path / "nokey.yaml").write_text("image: x.pgm\n")
    args = [a.format(tmp=tmp_path, log=sim_log) for a in args]
    if args[0] == "slam" and "--out" not in args:
        args += ["--out", str(tmp_path / "m")]
    assert main(args) == 1
    stderr = capsys.readouterr().err
    assert message in stderr
    errors = [line for line in stderr.splitlines() if "error:" in line]
    assert len(errors) == 1 and "Traceback" not in stderr


def test_slam_error_from_a_real_process(run_cli, tmp_path):
    result = run_cli("slam", tmp_path / "absent.log", "--out", tmp_path / "m")
    assert result.returncode == 1
    assert result.stderr.strip().splitlines() == [
        line
        for line in result.stderr.strip().splitlines()
        if line.startswith("workbench slam: error:")
    ]
    assert "log file not found" in result.stderr
