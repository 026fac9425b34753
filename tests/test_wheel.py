"""The built wheel works on its own: data, console script and nodes, outside the checkout.

Builds the wheel from a copy of the checkout, installs it with ``--no-deps`` into a
fresh virtual environment under ``tmp_path`` and lets that environment see this
interpreter's site-packages through a ``.pth`` line (drake and the rest are not
installed twice). A plain path in a ``.pth`` file does not run the ``.pth`` files
it contains, so the checkout's editable-install finder stays inactive and the
wheel's copy of ``workbench`` is the one imported (asserted below).
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parent.parent
DATA_DIRS = ("urdf", "planning", "mapping", "examples")
# Left out of the copy the wheel is built from: not part of the package, or large.
_NOT_BUILT = (".git", ".venv*", "build", "dist", "*.egg-info", "__pycache__", ".*_cache")
_NOT_BUILT += ("notebooks", "benchmarks", "tests", "*.html", "*.bag")

pytestmark = pytest.mark.slow


def _run(command: list[str], **kwargs) -> subprocess.CompletedProcess[str]:
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, (
        f"{' '.join(map(str, command))} exited {result.returncode}\n"
        f"stdout:\n{result.stdout[-3000:]}\nstderr:\n{result.stderr[-3000:]}"
    )
    return result


def _build_wheel(work: Path) -> Path:
    """The wheel built from a copy of the checkout (the build leaves no files behind in it)."""
    source = work / "src"
    shutil.copytree(REPO_ROOT, source, ignore=shutil.ignore_patterns(*_NOT_BUILT))
    _run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(work), str(source)])
    (built,) = work.glob("workbench-*.whl")
    return built


def _check_wheel_contents(wheel: Path) -> None:
    names = set(zipfile.ZipFile(wheel).namelist())
    for directory in DATA_DIRS:
        shipped = {n for n in names if n.startswith(f"workbench/_data/{directory}/")}
        in_checkout = {
            f"workbench/_data/{p.relative_to(REPO_ROOT).as_posix()}"
            for p in (REPO_ROOT / directory).rglob("*")
            if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc"
        }
        assert in_checkout, directory
        assert shipped == in_checkout, directory
    assert "workbench/py.typed" in names
    assert "workbench/msgs/geometry_msgs.pyi" in names
    assert any(n.endswith(".dist-info/entry_points.txt") for n in names)


def _install(wheel: Path, base: Path) -> tuple[Path, Path]:
    """A fresh venv holding the wheel; returns its python and its site-packages."""
    venv = base / "venv"
    _run([sys.executable, "-m", "venv", str(venv)])
    python = venv / "bin" / "python"
    _run([str(python), "-m", "pip", "install", "-q", "--no-deps", "--no-index", str(wheel)])
    purelib = "import sysconfig; print(sysconfig.get_paths()['purelib'])"
    site = Path(_run([str(python), "-c", purelib]).stdout.strip())
    outer = dict.fromkeys([sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]])
    (site / "zz_test_dependencies.pth").write_text("".join(f"{p}\n" for p in outer))
    return python, site


def _environment(bin_dir: Path, data_home: Path) -> dict[str, str]:
    """No checkout on the path, the venv's scripts first, its own user data directory."""
    environment = dict(os.environ)
    for name in ("PYTHONPATH", "WORKBENCH_HOME", "WORKBENCH_DATA_DIR", "VIRTUAL_ENV"):
        environment.pop(name, None)
    environment["XDG_DATA_HOME"] = str(data_home)
    environment["WORKBENCH_MASTER_URI"] = "inproc"
    environment["PATH"] = f"{bin_dir}{os.pathsep}{environment.get('PATH', '')}"
    return environment


def _duration(plan_output: str) -> float:
    line = next(line for line in plan_output.splitlines() if line.startswith("duration"))
    return float(line.split()[1])


def _talker_until_sigint(cwd: Path, env: dict[str, str]) -> None:
    process = subprocess.Popen(
        ["workbench", "run", "beginner_tutorials", "talker.py"],
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    seen = []
    try:
        assert process.stdout is not None
        for line in process.stdout:
            seen.append(line)
            if "hello world" in line:
                break
        process.send_signal(signal.SIGINT)
        rest, _ = process.communicate(timeout=120)  # a hang guard, not a speed limit
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert any("hello world" in line for line in seen), "".join(seen)
    assert process.returncode in (0, 130, -signal.SIGINT), "".join(seen) + rest


def test_wheel_installs_and_runs_outside_the_checkout(tmp_path: Path):
    wheel = _build_wheel(tmp_path / "build")
    _check_wheel_contents(wheel)
    python, site = _install(wheel, tmp_path)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    user_planning = tmp_path / "xdg" / "workbench" / "planning"
    env = _environment(python.parent, tmp_path / "xdg")

    where = (
        "import workbench, workbench.paths as p\n"
        "for path in (workbench.__file__, p.project_root(), p.urdf_dir(), p.mapping_dir(),"
        " p.examples_dir()):\n"
        "    print(path)\n"
    )
    printed = _run([str(python), "-c", where], cwd=elsewhere, env=env).stdout.splitlines()
    module, root, urdf, mapping, examples = (Path(line) for line in printed)
    assert module.is_relative_to(site), f"imported {module}, not the wheel's copy in {site}"
    assert root == site / "workbench" / "_data"
    assert (urdf / "robot_arm.urdf").is_file() and (urdf / "meshes").is_dir()
    assert (mapping / "demo_rooms.yaml").is_file()
    assert (examples / "talker.py").is_file()

    check = _run(["workbench", "check", "robot_arm"], cwd=elsewhere, env=env).stdout
    assert "robot name is: robot_arm" in check
    assert "workbench found no problems" in check

    plan = ["workbench", "plan", "arm3", "--to", "home", "--from", "random", "--seed", "1"]
    shipped = _run(plan, cwd=elsewhere, env=env).stdout
    assert "collision re-check        passed" in shipped
    assert (user_planning / "arm3" / "planning.yaml").is_file()  # the shipped config, copied
    assert (user_planning / "scenes" / "arm3_table.yaml").is_file()

    # `workbench setup` writes to the user data directory, and the planner reads it there.
    _run(["workbench", "setup", "arm3", "--velocity-scaling", "0.5"], cwd=elsewhere, env=env)
    assert "velocity_scaling: 0.5" in (user_planning / "arm3" / "planning.yaml").read_text()
    slower = _run(plan, cwd=elsewhere, env=env).stdout
    assert _duration(slower) > 1.2 * _duration(shipped)

    # worlds, plugins and the Gazebo launch packages ship too
    sim = ["workbench", "sim", "velodyne", "--headless", "--fast", "--until", "0.2"]
    simulated = _run(sim, cwd=elsewhere, env=env).stdout
    assert "plugin loaded: velodyne_control" in simulated and "stopped at t = 0.200 s" in simulated
    dry = ["workbench", "launch", "--dry-run", "gazebo_worlds", "table.launch"]
    assert "gazebo/spawn_model" in _run(dry, cwd=elsewhere, env=env).stdout

    _talker_until_sigint(elsewhere, env)
