"""Launch files: the XML subset and the YAML form, parsed without starting anything."""

from __future__ import annotations

import pytest

from workbench.bus.launch import LaunchError, load_launch
from workbench.cli.launch import launch, split_target


def test_manual_start_demo(data_dir):
    plan = load_launch(data_dir / "bus" / "start_demo.launch")
    assert [n.full_name for n in plan.nodes] == [
        "/sim",
        "/teleop",
        "/turtle1_tf_broadcaster",
        "/turtle2_tf_broadcaster",
    ]
    assert plan.nodes[1].output == "screen" and plan.nodes[0].output == "log"
    assert plan.params == {
        "/turtle1_tf_broadcaster/turtle": "turtle1",
        "/turtle2_tf_broadcaster/turtle": "turtle2",
    }


def test_features(data_dir):
    plan = load_launch(data_dir / "bus" / "features.launch", {"robot": "r2"})
    params = plan.params
    assert params["/use_sim_time"] is False
    assert params["/rate"] == 10 and params["/gain"] == 0.5 and params["/label"] == "42"
    assert params["/description"].startswith("obstacle_range")
    assert params["/local_costmap/raytrace_range"] == 3.0
    assert params["/local_costmap/footprint"][0] == [-0.2, -0.2]
    assert params["/inline/a"] == 1  # roslaunch sets a loaded dict leaf by leaf
    assert params["/r2/talker/unused"] == "x"
    assert params["/owner"] == "r2" and params["/adder/offset"] == 3
    talker = next(n for n in plan.nodes if n.name == "talker")
    assert talker.full_name == "/r2/talker" and talker.respawn and talker.args == ["--fast"]
    assert talker.remaps == {"cmd_vel": "/r2/cmd_vel", "chatter": "speech"}
    assert [n.name for n in plan.nodes] == ["talker", "adder"]  # listener is if=false
    adder = plan.nodes[1]
    assert adder.remaps["add_two_ints"] == "/sum" and adder.output == "screen"


def test_a_rosparam_dict_adds_to_its_namespace_as_roslaunch_unrolls_it(tmp_path):
    """roslaunch's loader.py add_param unrolls dicts: move_base's costmap files load the common
    keys with ns="global_costmap", then a ``global_costmap:`` block at the node's namespace."""
    (tmp_path / "common.yaml").write_text("obstacle_range: 2.5\nscan: {topic: scan}\n")
    (tmp_path / "global.yaml").write_text("global_costmap: {global_frame: map, scan: {a: 1}}\n")
    (tmp_path / "nav.launch").write_text(
        """<launch><node pkg="move_base" type="move_base" name="move_base">
        <rosparam file="$(dirname)/common.yaml" command="load" ns="global_costmap"/>
        <rosparam file="$(dirname)/global.yaml" command="load"/>
        <rosparam param="empty">{}</rosparam>
        </node></launch>"""
    )
    plan = load_launch(tmp_path / "nav.launch")
    assert plan.params == {
        "/move_base/global_costmap/obstacle_range": 2.5,
        "/move_base/global_costmap/scan/topic": "scan",
        "/move_base/global_costmap/global_frame": "map",
        "/move_base/global_costmap/scan/a": 1,
    }


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("<launch><node pkg='a'/></launch>", "needs a 'type' attribute"),
        (
            "<launch><param name='x' value='$(arg nope)'/></launch>",
            r"\$\(arg nope\) is not set",
        ),
        ("<robot/>", "root element is <robot>"),
        ("<launch><node", "cannot parse launch file"),
        ("<launch><include file='missing.launch'/></launch>", "does not exist"),
        (
            "<launch><node pkg='a' type='b' name='n'/><node pkg='a' type='c' name='n'/></launch>",
            "node name /n is used twice",
        ),
        ("<launch><param name='p' type='int' value='x'/></launch>", "invalid literal"),
    ],
)
def test_bad_launch_files(tmp_path, text, message):
    path = tmp_path / "bad.launch"
    path.write_text(text)
    with pytest.raises(LaunchError, match=message) as info:
        load_launch(path)
    assert "bad.launch" in info.value.one_line()


def test_undeclared_argument_is_ignored_with_a_warning(data_dir):
    """roslaunch ignores a command-line value that no <arg> declares (roslaunch/xmlloader.py
    checks unused args only for <include>); the plan is the same and a warning names it."""
    plain = load_launch(data_dir / "bus" / "start_demo.launch")
    given = load_launch(data_dir / "bus" / "start_demo.launch", {"colour": "red"})
    assert given.nodes == plain.nodes and given.params == plain.params
    assert [w for w in given.warnings if "'colour' is not declared; ignored" in w]


def test_cli_dry_run_and_errors(run_cli, data_dir, tmp_path):
    result = run_cli("launch", data_dir / "bus" / "features.launch", "robot:=r9", "--dry-run")
    assert result.returncode == 0, result.stderr
    assert "node /r9/talker: beginner_tutorials/talker.py --fast" in result.stdout
    assert "param /owner = 'r9'" in result.stdout
    missing = run_cli("launch", tmp_path / "none.launch")
    assert missing.returncode == 1
    assert (
        missing.stderr.startswith("workbench launch: error:") and "does not exist" in missing.stderr
    )
    unknown = run_cli("run", "nopkg", "nonode", env={"WORKBENCH_MASTER_URI": "inproc"})
    assert unknown.returncode == 1
    assert "no node 'nonode' in package 'nopkg'" in unknown.stderr


def test_launch_handler_in_process(data_dir, capsys):
    path, values = split_target([str(data_dir / "bus" / "features.launch"), "robot:=r9"])
    assert path == data_dir / "bus" / "features.launch" and values == {"robot": "r9"}
    assert launch(path, values, dry_run=True) == 0
    out = capsys.readouterr().out
    assert "node /r9/talker: beginner_tutorials/talker.py --fast" in out
    assert "param /owner = 'r9'" in out


def test_launch_handler_rejects_bad_targets(tmp_path):
    with pytest.raises(LaunchError, match="give a launch file, or a package and a launch file"):
        split_target(["a", "b", "c"])
    with pytest.raises(LaunchError, match="does not exist"):
        launch(tmp_path / "none.launch", dry_run=True)
