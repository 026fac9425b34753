"""`workbench show`: snapshots, PNGs, and the live server with joint sliders."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import urllib.request

import pytest

from workbench.cli import main
from workbench.viz.snapshot import snapshot_paths


def test_show_html_snapshot_has_every_link_and_the_camera(tmp_path, capsys):
    out = tmp_path / "robot_arm.html"
    assert main(["show", "robot_arm", "--q", "shoulder_pitch_joint=0.5", "--html", str(out)]) == 0
    assert capsys.readouterr().out == f"Wrote {out}\n"
    paths = set(snapshot_paths(out))
    for link in ("base_link", "shoulder_pitch_link", "gripper_finger_link2"):
        assert f"/robots/robot_arm/{link}" in paths
    assert "/Cameras/default/rotated/<object>" in paths
    html = out.read_text()
    assert "<script" in html and "http://" not in html.split("<script", 1)[0]


def test_show_rejects_a_bad_joint_value(capsys):
    assert main(["show", "arm3", "--q", "elbow_pitch_joint=abc", "--html", "x.html"]) == 1
    assert "--q 'elbow_pitch_joint=abc' is not JOINT=VALUE" in capsys.readouterr().err


@pytest.mark.browser
def test_show_png(run_cli, tmp_path, require_program):
    from PIL import Image

    require_program("chromium")
    result = run_cli(
        "show", "arm3", "--png", "arm3.png", "--width", "320", "--height", "240", cwd=tmp_path
    )
    assert result.returncode == 0, result.stderr
    image = Image.open(tmp_path / "arm3.png")
    assert image.size == (320, 240)


@pytest.mark.multiprocess
def test_show_serves_until_interrupted(tmp_path):
    env = dict(os.environ)
    env.pop("WORKBENCH_DEBUG", None)
    process = subprocess.Popen(
        [sys.executable, "-m", "workbench", "show", "arm3"],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
    )
    try:
        url = None
        deadline = time.monotonic() + 120
        while url is None and time.monotonic() < deadline:
            line = process.stdout.readline()
            if not line:
                break
            if line.startswith("Open "):
                url = line.split()[1]
        assert url and url.startswith("http://127.0.0.1:"), process.stderr.read()
        with urllib.request.urlopen(url, timeout=30) as response:
            assert response.status == 200
            assert b"meshcat" in response.read().lower()
        process.send_signal(signal.SIGINT)
        assert process.wait(timeout=60) == 130  # stopped by SIGINT
        assert "stopped" in process.stdout.read()
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
