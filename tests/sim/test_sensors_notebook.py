from __future__ import annotations

import re

import pytest

from workbench.bag import read_messages


@pytest.mark.notebook
def test_sensors_notebook_runs(run_notebook, tmp_path):
    notebook = run_notebook("07_sensors_worlds.ipynb")
    text = notebook.text
    out = tmp_path / "output" / "07_sensors_worlds"
    assert f"files go to {out}" in text
    assert "building 'two_rooms': 1 level, 5 walls, 1 door, 1 window" in text
    assert "the same walls: True" in text
    assert (out / "two_rooms.world").is_file() and (out / "demo_rooms.world").is_file()
    assert re.search(r"building 'demo_rooms': 1 level, \d+ walls", text), text
    assert text.count("SpawnModel: Successfully spawned entity") == 2
    assert "plugin: gpu_laser (libgazebo_ros_gpu_laser.so, model custom_bot)" in text
    drove = float(re.search(r"drove ([0-9.]+) m", text).group(1))
    assert drove == pytest.approx(0.5, abs=0.05)  # 0.25 m/s for 2 s
    assert "beams: 720, from -90.4 to 90.4 deg" in text
    before = float(re.search(r"straight ahead before: ([0-9.]+) m", text).group(1))
    after = float(re.search(r"straight ahead after: ([0-9.]+) m", text).group(1))
    assert before > 3.0  # through the door to the far wall
    assert after == pytest.approx(0.85, abs=0.02)  # the block's face, 1 m - 0.15 m ahead
    centre = float(re.search(r"centre pixel ([0-9.]+) m", text).group(1))
    assert centre == pytest.approx(0.79, abs=0.02)  # the camera sits 6 cm ahead of the laser
    assert "depth image 80 x 60" in text and "point cloud: 4800 points" in text
    assert re.search(r"LaserScan\s+\{'Topic': 'OK'\}", text), text
    assert re.search(r"PointCloud2\s+\{'Topic': 'OK'\}", text), text
    scans, clouds = map(int, re.search(r"drawn: (\d+) scans, (\d+) point cloud", text).groups())
    assert scans >= 1 and clouds == 1
    assert (out / "sensors_rviz.html").stat().st_size > 0
    counts = {t: int(n) for t, n in re.findall(r"bag: (/\w+) (\d+) messages", text)}
    assert set(counts) == {"/scan", "/odom", "/tf"} and min(counts.values()) > 0
    assert counts["/odom"] >= 250  # 100 Hz for over 2.5 simulated s
    assert counts["/scan"] >= 100  # 40 Hz
    scans = [m.msg for m in read_messages(out / "sensors.bag", ["/scan"])]
    assert len(scans) == counts["/scan"] and len(scans[-1].ranges) == 720
    assert min(scans[-1].ranges[355:365]) == pytest.approx(0.85, abs=0.02)
