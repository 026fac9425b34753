"""workbench's launch loader against ROS 1's own roslaunch, on the same files.

ROS's side is Debian's ``python3-roslaunch``: ``roslaunch.xmlloader.XmlLoader().load(file,
ROSLaunchConfig(), argv=...)`` in ``/usr/bin/python3`` (``benchmarks/roslaunch_oracle.py``),
no master, no process started. workbench's side is ``load_launch`` with the same
``ROS_PACKAGE_PATH``, environment and arguments. Compared (``benchmarks/launch_compare.py``,
which ``benchmarks/corpus.py`` uses too):
every node and test (package, type, name, namespace, args split as a shell splits them,
remappings, ``<env>``, output, respawn, respawn_delay, required, launch-prefix, cwd,
machine), every parameter with its YAML type (rosparam's ``!degrees``/``!radians``
included), cleared namespaces, ``rosparam delete/dump`` and machines; or, when one refuses
a file, that the other refuses it too. ``$(anon)`` names are numbered on both sides, and
``command=`` runs on neither (both give the substituted command).

Inputs: launch files written here in the shapes of Universal Robots' ``ur_gazebo`` bringup
chain (``pass_all_args``, xacro ``command=``, ``$(eval)`` conditions, a controllers
``<rosparam file=>``, spawners) and ROBOTIS' ``turtlebot3_slam`` (``$(arg)``-built include
names, per-method files, ``<group if="$(eval ...)">``) (:mod:`launch_shapes`), and 50
seeded random files of nested groups, includes, arguments, remappings and parameters
(:mod:`launch_random`).

Where workbench differs on purpose (not exercised here): it refuses a ``<machine>`` that is
not this computer, ``binfile=`` outside a dry run, and a negative or NaN ``respawn_delay``;
a ``<node>`` without ``name`` takes its type's name (roslaunch requires one); an argument
given on the command line that no ``<arg>`` declares is ignored, as roslaunch ignores it,
but with a warning.

Skips (fails under WORKBENCH_REQUIRE_ALL=1) without ``/usr/bin/python3`` able to import
roslaunch (``python3-roslaunch``) and catkin (``python3-catkin``, which roslaunch's
``$(find pkg)/path`` imports).
"""

from __future__ import annotations

import pytest
from benchmark_modules import benchmark_modules
from launch_random import random_case
from launch_shapes import write_packages
from skipping import ros_python

RANDOM_CASES = 50


@pytest.fixture(scope="module")
def corpus():
    ros_python("roslaunch", "python3-roslaunch")
    ros_python("catkin.find_in_workspaces", "python3-catkin")  # roslaunch's $(find pkg)/path
    with benchmark_modules("launch_compare") as (module,):
        yield module


def _compare(corpus, jobs):
    theirs = corpus.roslaunch_plans(jobs)
    results = []
    for job, their in zip(jobs, theirs, strict=True):
        ours = corpus.workbench_plan(job)
        kind, why = corpus.classify(ours, their)
        results.append((job, kind, why, ours, their))
    return results


def test_real_shaped_launch_files_resolve_as_roslaunch_resolves_them(corpus, tmp_path):
    files = write_packages(tmp_path / "src")
    env = {"ROS_PACKAGE_PATH": str(tmp_path / "src"), "BOT_MODEL": "small"}
    jobs = [
        {"file": str(files["arm5_bringup"]), "argv": [], "env": env},
        {"file": str(files["arm5_bringup"]), "argv": ["gui:=false", "paused:=true"], "env": env},
        {"file": str(files["bot_slam"]), "argv": [], "env": env},
        {"file": str(files["bot_slam"]), "argv": ["slam_methods:=cartographer"], "env": env},
        {
            "file": str(files["bot_slam"]),
            "argv": ["slam_methods:=hector", "open_rviz:=false"],
            "env": {**env, "BOT_LOG_LEVEL": "debug"},
        },
        {"file": str(files["empty_world"]), "argv": ["debug:=true"], "env": env},
        {  # both refuse: the model comes from an unset variable
            "file": str(files["bot_slam"]),
            "argv": [],
            "env": {"ROS_PACKAGE_PATH": env["ROS_PACKAGE_PATH"]},
        },
    ]
    results = _compare(corpus, jobs)
    for job, kind, why, _ours, _theirs in results[:-1]:
        assert kind == "agree", (job["file"], job["argv"], why)
    assert results[-1][1] == "both refuse", results[-1][2]

    # the comparison saw what it should: a non-trivial plan on both sides
    _job, _kind, _why, arm, arm_theirs = results[0]
    names = [node["name"] for node in arm["nodes"]]
    assert names == [n["name"] for n in arm_theirs["nodes"]]
    assert "robot_state_publisher" in names and "gazebo_gui" in names
    params = arm["params"]
    assert params["/robot_description"].startswith("<command: ")
    assert "robot_model:=arm5" in params["/robot_description"]  # pass_all_args + override
    assert params["/limits/joint_limits/shoulder_pan/max_position"] == pytest.approx(6.283185307)
    assert params["/limits/joint_limits/elbow_joint/soft_limit"] == pytest.approx(1.570796327)
    assert params["/safety_active"] is True and params["/margin_mm"] == 150
    assert params["/model_family"] == "ARM5_4"
    assert params["/eff_joint_traj_controller/gains/shoulder_pan_joint/p"] == 4000
    _job, _kind, _why, bot, _ = results[2]
    gmapping = next(n for n in bot["nodes"] if n["name"] == "bot_slam_gmapping")
    assert gmapping["namespace"] == "/slam" and ["scan", "/base_scan"] in gmapping["remaps"]
    assert dict(gmapping["env"]) == {
        "BOT_LOG_LEVEL": "info and more",
        "SLAM_THREADS": "2",
        "GMAPPING_VERBOSE": "0",
    }
    assert gmapping["machine"] == "here"
    assert [t["test_name"] for t in bot["tests"]] == ["slam_map_test"]


def test_seeded_random_launch_files_resolve_as_roslaunch_resolves_them(corpus, tmp_path):
    jobs = []
    for seed in range(RANDOM_CASES):
        top, argv = random_case(seed, tmp_path / f"case{seed}")
        env = {"ROS_PACKAGE_PATH": str(tmp_path), "WB_RANDOM_1": "from env"}
        jobs.append({"file": str(top), "argv": argv, "env": env})
    results = _compare(corpus, jobs)
    kinds = [kind for _job, kind, _why, _o, _t in results]
    for job, kind, why, _ours, _theirs in results:
        assert kind in ("agree", "both refuse"), (job["file"], job["argv"], kind, why)
    # most cases are valid files that resolve; some are refused by both, on purpose
    assert kinds.count("agree") >= RANDOM_CASES * 0.6, kinds
    nodes = sum(len(ours.get("nodes", [])) for _j, _k, _w, ours, _t in results)
    params = sum(len(ours.get("params", {})) for _j, _k, _w, ours, _t in results)
    assert nodes > 50 and params > 100, (nodes, params)
