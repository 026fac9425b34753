"""Packages by name: ROS_PACKAGE_PATH first, as rospkg crawls it, then workbench's own.

The differential test runs Debian's rospkg (``rospkg.RosPack(ros_paths).get_path``, the
lookup behind ``rospack find``, ``$(find)`` and ``package://``) in ``/usr/bin/python3`` on
seeded trees of packages and compares every name with ours. What it matches is
rospkg/rospack.py ``list_by_path``: a folder with a package.xml is a package (named by its
``<name>``, not its folder) and is not entered further; a folder holding ``CATKIN_IGNORE``
or ``rospack_nosubdirs`` is not entered; hidden folders are skipped; metapackages are not
packages; the first path entry holding a name wins.
"""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest
from skipping import ros_python

from workbench import ros_packages
from workbench.bus.launch import LaunchError, load_launch
from workbench.model.packages import PackageResolver
from workbench.paths import examples_dir


def make_package(folder: Path, name: str, *, metapackage: bool = False) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    export = "<export><metapackage/></export>" if metapackage else ""
    (folder / "package.xml").write_text(
        f'<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
        f"<version>1.0.0</version><description>d</description>"
        f'<maintainer email="m@example.com">m</maintainer><license>BSD</license>'
        f"{export}</package>\n"
    )
    return folder


@pytest.fixture
def no_path(monkeypatch, tmp_path):
    for variable in ros_packages.ENV_VARIABLES:
        monkeypatch.delenv(variable, raising=False)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    return monkeypatch


def test_a_package_on_ros_package_path_shadows_the_shipped_one(no_path, tmp_path):
    workspace = tmp_path / "ws" / "src"
    real = make_package(
        workspace / "turtlebot3_simulations" / "turtlebot3_gazebo", "turtlebot3_gazebo"
    )
    shipped = examples_dir() / "packages" / "turtlebot3_gazebo"
    assert ros_packages.find_package("turtlebot3_gazebo") == shipped

    no_path.setenv("ROS_PACKAGE_PATH", str(workspace))
    found = ros_packages.locate_package("turtlebot3_gazebo")
    assert found.path == real
    assert found.origin == "ROS_PACKAGE_PATH"
    assert found.shadows == (shipped,)
    # The packages workbench ships stay reachable under names the user does not have.
    assert ros_packages.locate_package("gazebo_ros").origin == ros_packages.ORIGIN_EMULATED
    assert ros_packages.locate_package("workbench_urdf").origin == ros_packages.ORIGIN_SHIPPED


def test_path_entries_in_order_and_workbench_path_first(no_path, tmp_path):
    first, second, own = (make_package(tmp_path / d / "pkg", "pkg") for d in ("a", "b", "c"))
    no_path.setenv("ROS_PACKAGE_PATH", f"{tmp_path / 'a'}{os.pathsep}{tmp_path / 'b'}")
    assert ros_packages.find_package("pkg") == first
    no_path.setenv("ROS_PACKAGE_PATH", f"{tmp_path / 'b'}{os.pathsep}{tmp_path / 'a'}")
    assert ros_packages.find_package("pkg") == second
    no_path.setenv("WORKBENCH_PACKAGE_PATH", str(tmp_path / "c"))
    assert ros_packages.locate_package("pkg").path == own
    assert ros_packages.locate_package("pkg").shadows == (second, first)


def test_crawl_rules(no_path, tmp_path):
    root = tmp_path / "root"
    make_package(root / "deep" / "er" / "than" / "three" / "levels", "deep_pkg")
    outer = make_package(root / "outer", "outer_pkg")
    make_package(outer / "inner", "inner_pkg")  # inside a package: not entered
    make_package(root / "ignored" / "pkg", "ignored_pkg")
    (root / "ignored" / "CATKIN_IGNORE").write_text("")
    make_package(root / "nosub" / "pkg", "nosub_pkg")
    (root / "nosub" / "rospack_nosubdirs").write_text("")
    make_package(root / ".hidden" / "pkg", "hidden_pkg")
    make_package(root / "meta", "meta_pkg", metapackage=True)
    make_package(root / "meta" / "member", "member_pkg")  # a metapackage's folder is entered
    make_package(root / "folder_name", "declared_name")
    (root / "loop").symlink_to(root)
    no_path.setenv("ROS_PACKAGE_PATH", str(root))

    names = {name for name, _ in ros_packages.crawl(str(root))}
    assert names == {"deep_pkg", "outer_pkg", "member_pkg", "declared_name"}
    for missing in (
        "inner_pkg",
        "ignored_pkg",
        "nosub_pkg",
        "hidden_pkg",
        "meta_pkg",
        "folder_name",
    ):
        with pytest.raises(ros_packages.PackageLookupError, match=f"'{missing}' not found"):
            ros_packages.find_package(missing)


def test_an_unreadable_or_huge_package_xml_is_no_package(no_path, tmp_path):
    root = tmp_path / "root"
    (root / "broken").mkdir(parents=True)
    (root / "broken" / "package.xml").write_text("<package><name>broken")
    make_package(root / "broken" / "below", "below_broken")
    (root / "fifo").mkdir()
    os.mkfifo(root / "fifo" / "package.xml")
    no_path.setenv("ROS_PACKAGE_PATH", str(root))
    names = {name for name, _ in ros_packages.crawl(str(root))}
    assert names == {"below_broken"}


def test_find_in_a_launch_file_from_any_working_directory(no_path, tmp_path):
    workspace = tmp_path / "ws" / "src"
    robot = make_package(workspace / "my_robot", "my_robot")
    (robot / "launch").mkdir()
    (robot / "launch" / "a.launch").write_text(
        '<launch><param name="where" value="$(find my_robot)"/>'
        '<param name="sim" value="$(find turtlebot3_gazebo)"/></launch>'
    )
    other = make_package(tmp_path / "overlay" / "turtlebot3_gazebo", "turtlebot3_gazebo")
    no_path.setenv("ROS_PACKAGE_PATH", f"{tmp_path / 'overlay'}{os.pathsep}{workspace}")
    plan = load_launch(ros_packages.find_package("my_robot") / "launch" / "a.launch")
    assert plan.params == {"/where": str(robot), "/sim": str(other)}


def test_find_of_an_unknown_package_names_the_file_and_line(no_path, tmp_path):
    launch = tmp_path / "a.launch"
    launch.write_text('<launch>\n  <param name="x" value="$(find no_such_pkg)/x"/>\n</launch>\n')
    with pytest.raises(LaunchError) as caught:
        load_launch(launch)
    text = caught.value.one_line()
    assert f"{launch}:2:" in text and "no_such_pkg" in text and "ROS_PACKAGE_PATH" in text


def test_package_uris_follow_the_same_order(no_path, tmp_path):
    description = make_package(tmp_path / "src" / "robot_description", "robot_description")
    no_path.setenv("ROS_PACKAGE_PATH", str(tmp_path / "src"))
    resolver = PackageResolver(tmp_path / "elsewhere" / "model.urdf")
    mesh = resolver.resolve("package://robot_description/meshes/base.stl", None)
    assert mesh == description / "meshes" / "base.stl"


def test_workbench_launch_which(no_path, tmp_path):
    real = make_package(tmp_path / "src" / "gazebo_ros", "gazebo_ros")
    env = {**os.environ, "ROS_PACKAGE_PATH": str(tmp_path / "src")}
    done = subprocess.run(
        [sys.executable, "-m", "workbench", "launch", "--which", "gazebo_ros"],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == f"{real}  (ROS_PACKAGE_PATH)", done.stdout
    assert lines[1] == f"  shadows {examples_dir() / 'packages' / 'gazebo_ros'}"
    missing = subprocess.run(
        [sys.executable, "-m", "workbench", "launch", "--which", "no_such_pkg"],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )
    assert missing.returncode == 1
    assert "Traceback" not in missing.stderr
    assert len(missing.stderr.strip().splitlines()) == 1
    assert "package 'no_such_pkg' not found" in missing.stderr


_ROSPKG = """
import json, sys, rospkg
paths = json.loads(sys.argv[1]); names = json.loads(sys.argv[2])
pack = rospkg.RosPack(ros_paths=paths)
out = {}
for name in names:
    try:
        out[name] = pack.get_path(name)
    except rospkg.ResourceNotFound:
        out[name] = None
print(json.dumps(out))
"""


def _random_tree(rng: random.Random, root: Path, names: list[str]) -> None:
    """Packages at random depths, with ignored, hidden, nested and metapackage folders.

    The packages rospkg can find in one root have distinct names (between two folders of
    one name in one root, rospkg's pick is the file system's order); across roots, names
    repeat and the first root must win.
    """
    unused = list(names)
    rng.shuffle(unused)
    for index in range(rng.randint(3, 9)):
        depth = rng.randint(0, 4)
        folder = root.joinpath(*(f"d{rng.randint(0, 2)}" for _ in range(depth)), f"p{index}")
        if not unused or any((p / "package.xml").exists() for p in [folder, *folder.parents]):
            continue
        kind = rng.random()
        if kind < 0.1:
            make_package(folder, rng.choice(names), metapackage=True)
            continue
        make_package(folder, unused.pop())
        if kind < 0.2:
            make_package(folder / "nested", rng.choice(names))
        elif kind < 0.3:
            (folder.parent / "CATKIN_IGNORE").write_text("")
        elif kind < 0.35:
            make_package(root / f".hidden{index}" / "p", rng.choice(names))


@pytest.mark.parametrize("seed", range(12))
def test_lookup_matches_rospkg(no_path, tmp_path, seed):
    python = ros_python("rospkg", "python3-rospkg")
    rng = random.Random(seed)
    names = [f"pkg_{i}" for i in range(8)]
    roots = []
    for index in range(rng.randint(1, 3)):
        root = tmp_path / f"root{index}"
        root.mkdir()
        _random_tree(rng, root, names)
        roots.append(root)
    no_path.setenv("ROS_PACKAGE_PATH", os.pathsep.join(map(str, roots)))
    done = subprocess.run(
        [python, "-c", _ROSPKG, json.dumps(list(map(str, roots))), json.dumps(names)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout)
    ours: dict[str, str | None] = {}
    for name in names:
        try:
            found = ros_packages.locate_package(name)
            ours[name] = str(found.path) if found.origin == "ROS_PACKAGE_PATH" else None
        except ros_packages.PackageLookupError:
            ours[name] = None
    assert ours == expected
    assert any(expected.values())


def test_workbench_run_finds_a_script_of_a_package_on_the_path(no_path, tmp_path):
    package = make_package(tmp_path / "ws" / "src" / "my_tools", "my_tools")
    (package / "scripts").mkdir()
    (package / "scripts" / "hello.py").write_text("import sys\nprint('hello', *sys.argv[1:])\n")
    env = {**os.environ, "ROS_PACKAGE_PATH": str(tmp_path / "ws" / "src")}
    done = subprocess.run(
        [sys.executable, "-m", "workbench", "run", "my_tools", "hello.py", "a", "b"],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "hello a b"
