"""roslaunch's elements and substitutions in workbench's loader: what ROS does and where the
sandbox and bounds hold (the differential test against roslaunch itself is
``test_launch_roslaunch_differential.py``)."""

from __future__ import annotations

import math

import pytest

from workbench.bus.launch import Deferred, LaunchError, RosparamCommand, load_launch
from workbench.cli.launch import launch, print_args
from workbench.model.launch_eval import evaluate_launch_expression


def _load(tmp_path, text, args=None, **options):
    path = tmp_path / "a.launch"
    path.write_text(text)
    options.setdefault("evaluate", evaluate_launch_expression)
    return load_launch(path, args, **options)


def _refused(tmp_path, text, match, args=None, **options):
    with pytest.raises(LaunchError, match=match) as info:
        _load(tmp_path, text, args, **options)
    line = info.value.one_line()
    assert "\n" not in line and "a.launch" in line, line
    return line


def test_eval_sees_arguments_functions_math_and_safe_builtins(tmp_path, monkeypatch):
    monkeypatch.setenv("WB_TEST_ENV", "here")
    plan = _load(
        tmp_path,
        """<launch>
        <arg name="x" default="3"/><arg name="model" default="burger"/>
        <param name="a" value="$(eval x * 2 + pi)"/>
        <param name="b" value="$(eval arg('model') == 'burger' and x > 2)"/>
        <param name="c" value="$(eval len(model) + sum([1, 2]))"/>
        <param name="d" value="$(eval env('WB_TEST_ENV') + optenv('WB_NOT_SET', '-'))"/>
        <param name="e" value="$(eval dirname() != '')"/>
        <param name="f" value="$(eval sorted(map(lambda v: v * 2, [3, 1])))"/>
        <group if="$(eval model.startswith('bur'))"><param name="g" value="in"/></group>
        <group unless="$(eval true)"><param name="h" value="out"/></group>
        </launch>""",
    )
    assert plan.params["/a"] == pytest.approx(6 + math.pi)
    assert plan.params["/b"] is True and plan.params["/c"] == 9
    assert plan.params["/d"] == "here-" and plan.params["/e"] is True
    assert plan.params["/f"] == "[2, 6]" and plan.params["/g"] == "in" and "/h" not in plan.params


@pytest.mark.parametrize(
    ("expression", "match"),
    [
        ("().__class__.__bases__", "may not contain '__'"),
        ("'{0.real}'.format(1)", "'str.format' is not available in a launch file"),
        ("open('/etc/passwd')", "name 'open' is not defined"),
        ("len(str(10 ** 10 ** 8))", "more than|too large|at most"),
        ("[1] * 10 ** 9", "more than"),
        ("nope + 1", "name 'nope' is not defined"),
        ("arg('missing')", r"\$\(arg missing\) is not set"),
    ],
)
def test_eval_runs_in_the_sandbox(tmp_path, expression, match):
    _refused(tmp_path, f'<launch><param name="p" value="$(eval {expression})"/></launch>', match)


def test_eval_needs_the_sandbox_and_the_whole_value(tmp_path):
    _refused(
        tmp_path,
        '<launch><param name="p" value="$(eval 1 + 1)"/></launch>',
        "needs workbench's expression sandbox",
        evaluate=None,
    )
    # roslaunch evaluates only a value that is all $(eval ...)
    _refused(
        tmp_path,
        '<launch><param name="p" value="x $(eval 1)"/></launch>',
        r"unknown substitution \$\(eval 1\)",
    )


def test_substitutions_as_roslaunch_resolves_them(tmp_path, monkeypatch):
    monkeypatch.delenv("WB_UNSET", raising=False)
    plan = _load(
        tmp_path,
        """<launch>
        <arg name="pkgdir" default="$(dirname)"/>
        <param name="opt" value="$(optenv WB_UNSET a   b  c)"/>
        <param name="anon" value="$(anon talker)"/>
        <param name="again" value="$(anon talker)"/>
        <param name="dir" value="$(arg pkgdir)/x"/>
        <param name="typed" value=" 1e3 "/><param name="under" value="1_000"/>
        <param name="float" value="2."/><param name="boolean" value="TRUE"/>
        <param name="s" type="str" value=" padded "/>
        </launch>""",
    )
    params = plan.params
    assert params["/opt"] == "a b c"  # roslaunch joins the default's words with one space
    assert params["/anon"] == params["/again"] and params["/anon"].startswith("talker_")
    assert params["/dir"] == f"{tmp_path}/x"
    assert params["/typed"] == "1e3" and params["/under"] == "1_000"  # roslaunch's auto type
    assert params["/float"] == 2.0 and params["/boolean"] is True and params["/s"] == "padded"
    _refused(tmp_path, '<launch><param name="p" value="$(arg $(arg x))"/></launch>', "'\\$'")
    _refused(tmp_path, '<launch><param name="p" value="$(bogus x)"/></launch>', "unknown")


def test_arguments_are_scoped_and_passed_as_roslaunch_passes_them(tmp_path):
    (tmp_path / "inner.launch").write_text(
        """<launch><arg name="a"/><arg name="b" default="bd"/>
        <param name="inner_a" value="$(arg a)"/><param name="inner_b" value="$(arg b)"/>
        </launch>"""
    )
    plan = _load(
        tmp_path,
        """<launch><arg name="a" default="top"/><arg name="b" default="topb"/>
        <group ns="g"><arg name="scoped" default="1"/></group>
        <arg name="scoped" default="2"/>
        <include file="$(dirname)/inner.launch" pass_all_args="true" ns="all"/>
        <include file="$(dirname)/inner.launch"><arg name="a" value="$(arg b)"/></include>
        </launch>""",
        {"a": "given"},
    )
    assert plan.params["/inner_a"] == "topb" and plan.params["/inner_b"] == "bd"
    assert plan.params["/all/inner_a"] == "given" and plan.params["/all/inner_b"] == "topb"
    assert plan.args[0].name == "a" and plan.args[0].default == "top"
    _refused(
        tmp_path,
        """<launch><arg name="a" default="1"/>
        <include file="$(dirname)/inner.launch"><arg name="a" value="1"/>
        <arg name="c" value="2"/></include></launch>""",
        "does not declare the argument 'c'",
    )
    _refused(tmp_path, '<launch><arg name="x" value="1"/></launch>', "fixed value", {"x": "2"})
    _refused(tmp_path, '<launch><arg name="x"/><arg name="x"/></launch>', "declared twice")
    ignored = tmp_path / "ignored.launch"
    ignored.write_text('<launch><arg name="x" default="1"/></launch>')
    assert any(
        "'y' is not declared; ignored" in w for w in load_launch(ignored, {"y": "1"}).warnings
    )
    # declared without a value is fine until it is used
    assert _load(tmp_path, '<launch><arg name="x"/></launch>').params == {}


def test_remaps_env_and_private_params_are_scoped(tmp_path):
    plan = _load(
        tmp_path,
        """<launch>
        <remap from="a" to="top_a"/><env name="E" value="top"/><param name="~rate" value="5"/>
        <group ns="g">
          <remap from="a" to="group_a"/><env name="G" value="1"/><param name="~inner" value="1"/>
          <node pkg="p" type="t" name="n1"><remap from="b" to="own_b"/>
            <env name="E" value="node"/><param name="/abs" value="1"/></node>
        </group>
        <node pkg="p" type="t" name="n2" cwd="node" launch-prefix="nice -n 5"/>
        </launch>""",
    )
    n1, n2 = plan.nodes
    assert n1.full_name == "/g/n1" and n1.remaps == {"a": "group_a", "b": "own_b"}
    assert n1.env == {"E": "node", "G": "1"}
    assert n2.remaps == {"a": "top_a"} and n2.env == {"E": "top"}
    assert n2.cwd == "node" and n2.launch_prefix == "nice -n 5"
    assert plan.params == {
        "/g/n1/rate": 5,
        "/g/n1/inner": 1,
        "/g/n1/abs": 1,  # roslaunch puts even a global name under the node
        "/n2/rate": 5,
    }


def test_rosparam_commands_tags_and_substitution(tmp_path):
    plan = _load(
        tmp_path,
        """<launch><arg name="speed" default="0.5"/>
        <rosparam ns="limits">{a: !degrees 180, b: deg(90), c: rad(pi/2), d: !radians 2*pi}</rosparam>
        <rosparam subst_value="true" ns="s">v: $(arg speed)</rosparam>
        <rosparam param="scalar">42</rosparam>
        <rosparam command="delete" param="old"/>
        <rosparam command="dump" file="out.yaml" param="limits"/>
        <group ns="clean" clear_params="true"/>
        <node pkg="p" type="t" name="n" clear_params="true"/>
        </launch>""",
    )
    limits = {k: v for k, v in plan.params.items() if k.startswith("/limits/")}
    assert limits == pytest.approx(
        {
            "/limits/a": math.pi,
            "/limits/b": math.pi / 2,
            "/limits/c": math.pi / 2,
            "/limits/d": 2 * math.pi,
        }
    )
    assert plan.params["/s/v"] == 0.5 and plan.params["/scalar"] == 42
    assert plan.rosparam_commands == [
        RosparamCommand("delete", "/old"),
        RosparamCommand("dump", "/limits", "out.yaml"),
    ]
    assert plan.deletes == ["/old"] and plan.clear_params == ["/clean", "/n"]
    _refused(
        tmp_path,
        "<launch><rosparam>{a: !radians __import__('os')}</rosparam></launch>",
        "invalid radian expression",
    )
    _refused(tmp_path, "<launch><rosparam>{a: !degrees ninety}</rosparam></launch>", "degree")
    _refused(tmp_path, "<launch><rosparam>[1, 2]</rosparam></launch>", "must be a dictionary")
    _refused(tmp_path, '<launch><rosparam command="wipe"/></launch>', "not load, dump or delete")


def test_tests_machines_and_unknown_elements(tmp_path):
    plan = _load(
        tmp_path,
        """<launch>
        <machine name="here" address="localhost" default="true"/>
        <node pkg="p" type="t" name="n"/>
        <test test-name="check" pkg="p" type="check.py" time-limit="30" retry="2"/>
        <bogus/>
        </launch>""",
    )
    assert plan.machines == {"here": "localhost"} and plan.nodes[0].machine == "here"
    (test,) = plan.tests
    assert (test.name, test.test_name, test.time_limit, test.retry) == ("check", "check", 30, 2)
    assert any("unknown element <bogus> is ignored" in w for w in plan.warnings)
    line = _refused(
        tmp_path,
        '<launch>\n<machine name="c1" address="robot-two.local"/></launch>',
        "workbench runs every node on this computer",
    )
    assert line.startswith(f"{tmp_path / 'a.launch'}:2: <machine name='c1'")
    _refused(tmp_path, '<launch><node pkg="p" type="t" name="n" machine="c2"/></launch>', "c2")
    _refused(
        tmp_path, '<launch><test test-name="t" pkg="p" type="t" respawn="true"/></launch>', "no"
    )


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ('<node pkg="p" type="t" name="n" respawn="yes"/>', "respawn='yes' is not true or false"),
        ('<node pkg="p" type="t" name="n" respawn="true" required="true"/>', "both respawn"),
        ('<node pkg="p" type="t" name="n" output="file"/>', "not log or screen"),
        ('<node pkg="p" type="t" name="n" cwd="/tmp"/>', "not ROS_HOME or node"),
        ('<node pkg="p" type="t" name="a/b"/>', "has a '/'"),
        ('<group ns="" />', "ns is empty"),
        ('<group clear_params="true"/>', "clear_params needs an ns"),
        ('<param name="p" value="1" if="maybe"/>', "if='maybe' is not true, false, 1 or 0"),
        ('<param name="p" value="1" if="true" unless="false"/>', "both 'if' and 'unless'"),
        ('<param name="p" value="1" textfile="x"/>', "exactly one of"),
        ('<param name="p" type="bool" value="yes"/>', "not a 'bool' type"),
        ('<param name="p" type="$(arg t)" value="1"/>', "unknown type"),
        ('<remap from="a b" to="c"/>', "not a legal ROS name"),
        ('<env name="" value="c"/>', "name is empty"),
    ],
)
def test_bad_attributes_are_one_line_errors(tmp_path, text, match):
    _refused(tmp_path, f"<launch>\n{text}\n</launch>", match)


def test_binfile_is_listed_in_a_dry_run_and_refused_in_a_real_one(tmp_path):
    (tmp_path / "blob.bin").write_bytes(b"\x00\x01")
    text = '<launch><param name="b" binfile="$(dirname)/blob.bin"/></launch>'
    plan = _load(tmp_path, text, dry_run=True)
    assert plan.params["/b"] == Deferred("contents of binary file", str(tmp_path / "blob.bin"))
    _refused(tmp_path, text, "binary parameter", command_runner=lambda c, p: "")


def test_dry_run_and_ros_args_show_what_roslaunch_would(tmp_path, capsys):
    path = tmp_path / "a.launch"
    path.write_text(
        """<launch>
        <arg name="model" doc="robot model"/><arg name="rate" default="10" doc="Hz"/>
        <arg name="fixed" value="1"/>
        <env name="E" value="1"/><group ns="g" clear_params="true"/>
        <rosparam command="delete" param="old"/>
        <node pkg="p" type="t" name="n" launch-prefix="nice" cwd="ROS_HOME" required="true"/>
        <test test-name="check" pkg="p" type="check.py"/>
        <unknown/>
        </launch>"""
    )
    assert print_args(path, {}) == 0
    out = capsys.readouterr().out
    assert out.splitlines() == [
        "Required Arguments:",
        "  model: robot model",
        "Optional Arguments:",
        '  rate (default "10"): Hz',
    ]
    assert launch(path, {"model": "m"}, dry_run=True) == 0
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    assert "clear /g/*" in lines and "rosparam delete /old (before the params)" in lines
    assert "node /n: p/t" in lines
    assert {"    env E=1", "    launch-prefix 'nice'", "    cwd ROS_HOME", "    required"} <= set(
        lines
    )
    assert any(line.startswith("test /check: p/check.py") and "not run" in line for line in lines)
    assert "unknown element <unknown> is ignored" in captured.err
