"""benchmarks/corpus.py on a small folder of packages written here in the shapes of real ones
(package.xml, launch/, urdf/, worlds/, Gazebo models, a map_server map):

* which files it finds, and as what;
* every class (works, warnings, correct refusal, refusal by design, no oracle, wrong,
  traceback, hang, crash) from commands injected in place of workbench and roslaunch, and
  from real child processes that hang, abort or raise;
* the real workbench beside the real oracles: Debian's roslaunch through
  benchmarks/roslaunch_oracle.py (the same plan, compared by benchmarks/launch_compare.py),
  urdfdom's check_urdf and urdf_to_graphviz (same tree and graph), libsdformat (same
  verdict on models and worlds).
"""

from __future__ import annotations

import json
import os
import sys
import textwrap
import time
from pathlib import Path

import pytest
from benchmark_modules import benchmark_modules
from skipping import ros_python, skip_or_fail

TIMEOUT = 120.0  # s per command: the machines that run the tests are often loaded


@pytest.fixture(scope="module")
def corpus():  # type: ignore[no-untyped-def]
    names = ("corpus", "corpus_files", "corpus_jobs", "corpus_oracles", "corpus_run")
    with benchmark_modules(*names, "launch_compare") as modules:
        keys = ("main", "files", "jobs", "oracles", "run", "compare")
        yield dict(zip(keys, modules, strict=True))


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def package(root: Path, name: str) -> Path:
    write(
        root / name / "package.xml",
        f"""
        <?xml version="1.0"?>
        <package format="2">
          <name>{name}</name>
          <version>0.1.0</version>
          <description>{name}</description>
          <maintainer email="lab@example.com">lab</maintainer>
          <license>BSD</license>
          <buildtool_depend>catkin</buildtool_depend>
        </package>
        """,
    )
    return root / name


URDF = """
<?xml version="1.0"?>
<robot name="demo">
  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/>
    <child link="base_link"/>
    <origin xyz="0 0 0.01" rpy="0 0 0"/>
  </joint>
  <link name="base_link">
    <visual><geometry><box size="0.2 0.2 0.1"/></geometry></visual>
    <collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision>
    <inertial>
      <mass value="1.0"/>
      <inertia ixx="0.004" ixy="0" ixz="0" iyy="0.004" iyz="0" izz="0.007"/>
    </inertial>
  </link>
  <joint name="wheel_joint" type="continuous">
    <parent link="base_link"/>
    <child link="wheel_link"/>
    <origin xyz="0 0.1 0" rpy="-1.57 0 0"/>
    <axis xyz="0 0 1"/>
  </joint>
  <link name="wheel_link">
    <visual><geometry><cylinder radius="0.03" length="0.02"/></geometry></visual>
    <collision><geometry><cylinder radius="0.03" length="0.02"/></geometry></collision>
    <inertial>
      <mass value="0.1"/>
      <inertia ixx="0.00003" ixy="0" ixz="0" iyy="0.00003" iyz="0" izz="0.00005"/>
    </inertial>
  </link>
</robot>
"""

MACROS = """
<?xml version="1.0"?>
<robot name="demo_macros" xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:property name="wheel_radius" value="0.033"/>
  <xacro:macro name="wheel" params="side">
    <link name="wheel_${side}_link"/>
  </xacro:macro>
</robot>
"""

MODEL_CONFIG = """
<?xml version="1.0"?>
<model>
  <name>{name}</name>
  <version>1.0</version>
  <sdf version="1.4">model-1_4.sdf</sdf>
  <sdf version="1.6">model.sdf</sdf>
  <author><name>lab</name><email>lab@example.com</email></author>
  <description>{name}</description>
</model>
"""

BOX_SDF = """
<?xml version="1.0"?>
<sdf version="1.6">
  <model name="{name}">
    <static>true</static>
    <link name="link">
      <collision name="collision"><geometry><box><size>1 1 1</size></box></geometry></collision>
      <visual name="visual"><geometry><box><size>1 1 1</size></box></geometry></visual>
    </link>
  </model>
</sdf>
"""

WORLD = """
<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <physics type="ode">
      <max_step_size>0.001</max_step_size>
      <real_time_update_rate>1000</real_time_update_rate>
    </physics>
    <include><uri>model://{model}</uri></include>
  </world>
</sdf>
"""


@pytest.fixture
def tree(tmp_path: Path) -> tuple[Path, Path]:
    """(root, models): two packages of a robot, a Gazebo model folder."""
    root, models = tmp_path / "src", tmp_path / "models"
    description = package(root, "demo_description")
    write(description / "urdf" / "demo.urdf", URDF)
    write(description / "urdf" / "macros.xacro", MACROS)
    bringup = package(root, "demo_bringup")
    write(
        bringup / "launch" / "bringup.launch",
        """
        <launch>
          <arg name="rate" default="50.0"/>
          <arg name="robot" default="demo"/>
          <param name="robot_description" textfile="$(find demo_description)/urdf/demo.urdf"/>
          <rosparam ns="limits">
            speed: 0.5
            turn: {max: 2.0, min: -2.0}
          </rosparam>
          <group ns="$(arg robot)">
            <remap from="cmd_vel" to="/mux/cmd_vel"/>
            <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"
                  args="--verbose -x 1">
              <param name="publish_frequency" type="double" value="$(arg rate)"/>
              <remap from="joint_states" to="/demo/joint_states"/>
            </node>
          </group>
          <node pkg="turtlesim" type="turtlesim_node" name="sim" ns="/tools"/>
        </launch>
        """,
    )
    write(
        bringup / "launch" / "needs_robot.launch",
        """
        <launch>
          <arg name="robot"/>
          <node pkg="turtlesim" type="turtlesim_node" name="$(arg robot)"/>
        </launch>
        """,
    )
    write(  # roslaunch accepts it; workbench refuses a machine elsewhere, on purpose
        bringup / "launch" / "remote.machine",
        """
        <launch>
          <machine name="far" address="far.example.com" default="true"/>
          <node pkg="turtlesim" type="turtlesim_node" name="sim"/>
        </launch>
        """,
    )
    write(
        bringup / "launch" / "include.launch.xml",
        """
        <launch>
          <include file="$(dirname)/bringup.launch">
            <arg name="rate" value="10.0"/>
          </include>
        </launch>
        """,
    )
    write(
        bringup / "maps" / "map.yaml",
        """
        image: map.pgm
        resolution: 0.050000
        origin: [-1.0, -1.0, 0.000000]
        negate: 0
        occupied_thresh: 0.65
        free_thresh: 0.196
        """,
    )
    (bringup / "maps" / "map.pgm").write_bytes(b"P5\n4 4\n255\n" + bytes([254] * 8 + [0] * 8))
    write(root / "demo_gazebo" / "worlds" / "demo.world", WORLD.format(model="demo_box"))
    write(root / "demo_gazebo" / "worlds" / "missing.world", WORLD.format(model="no_such_model"))
    for name in ("demo_box", "demo_crate"):
        write(models / name / "model.config", MODEL_CONFIG.format(name=name))
        write(models / name / "model.sdf", BOX_SDF.format(name=name))
        write(models / name / "model-1_4.sdf", BOX_SDF.format(name=name).replace("1.6", "1.4"))
    write(
        models / "demo_shelf" / "model.config",
        MODEL_CONFIG.format(name="demo_shelf").replace('<sdf version="1.6">model.sdf</sdf>', ""),
    )
    write(
        models / "demo_shelf" / "model-1_4.sdf",
        """
        <?xml version="1.0"?>
        <sdf version="1.4">
          <model name="demo_shelf">
            <include><uri>model://no_such_part</uri></include>
          </model>
        </sdf>
        """,
    )
    return root, models


# --- finding the files -------------------------------------------------------------------


def test_each_file_is_found_as_its_kind(corpus, tree) -> None:  # type: ignore[no-untyped-def]
    root, models = tree
    items = corpus["files"].discover(root, [models])
    found = {(item.kind, item.path.relative_to(item.path.parents[2]).as_posix()) for item in items}
    assert found == {
        ("description", "demo_description/urdf/demo.urdf"),
        ("description", "demo_description/urdf/macros.xacro"),
        ("launch", "demo_bringup/launch/bringup.launch"),
        ("launch", "demo_bringup/launch/needs_robot.launch"),
        ("launch", "demo_bringup/launch/include.launch.xml"),
        ("launch", "demo_bringup/launch/remote.machine"),
        ("map", "demo_bringup/maps/map.yaml"),
        ("world", "demo_gazebo/worlds/demo.world"),
        ("world", "demo_gazebo/worlds/missing.world"),
        # Gazebo reads the newest SDF the model.config names (1.6 over 1.4).
        ("model", "models/demo_box/model.sdf"),
        ("model", "models/demo_crate/model.sdf"),
        ("model", "models/demo_shelf/model-1_4.sdf"),
    }
    only = corpus["files"].discover(root, [models], only=["launch"])
    assert {item.kind for item in only} == {"launch"} and len(only) == 4


def test_an_srdf_gets_the_description_its_planning_context_loads(corpus, tmp_path) -> None:  # type: ignore[no-untyped-def]
    root = tmp_path / "src"
    description = package(root, "arm_description")
    write(description / "urdf" / "arm.urdf.xacro", URDF)
    config = package(root, "arm_moveit_config")
    srdf = write(config / "config" / "arm.srdf", '<robot name="demo"><group name="arm"/></robot>')
    write(
        config / "launch" / "planning_context.launch",
        """
        <launch>
          <arg name="load_robot_description" default="false"/>
          <arg name="robot_description" default="robot_description"/>
          <param if="$(arg load_robot_description)" name="$(arg robot_description)"
                 command="xacro '$(find arm_description)/urdf/arm.urdf.xacro'"/>
          <param name="$(arg robot_description)_semantic"
                 textfile="$(find arm_moveit_config)/config/arm.srdf"/>
        </launch>
        """,
    )
    (item,) = corpus["files"].discover(root, only=["srdf"])
    assert item.path == srdf
    assert item.extra == description / "urdf" / "arm.urdf.xacro"


# --- classes, from injected commands -----------------------------------------------------


class FakeTools:
    """Answers in place of workbench and roslaunch, by the launch file's name.

    ``roslaunch`` (the Python given as ``ros_python``) accepts every file but
    ``needs_arg`` and ``ros_refuses``; workbench's dry run behaves as the name says.
    """

    ROS = "/fake/ros/python3"

    def __init__(self, modules) -> None:  # type: ignore[no-untyped-def]
        self.modules = modules
        self.calls: list[list[str]] = []

    def plan(self, args: list[str] | str) -> dict:
        """A plan in roslaunch_oracle.py's shape (roslaunch gives args as one string)."""
        node = {
            "pkg": "turtlesim",
            "type": "turtlesim_node",
            "name": "sim",
            "namespace": "/",
            "args": args,
            "remaps": [],
            "env": [],
            "launch_prefix": None,
            "cwd": None,
            "machine": None,
            "output": None,
            "respawn": False,
            "respawn_delay": 0.0,
            "required": False,
        }
        return {
            "nodes": [node],
            "tests": [],
            "params": {"/rate": 50.0},
            "clear_params": [],
            "executables": [],
            "machines": {},
        }

    def __call__(self, argv, env, cwd, timeout):  # type: ignore[no-untyped-def]
        run = self.modules["run"]
        self.calls.append(list(argv))
        name = next(Path(a).stem for a in argv if a.endswith(".launch"))
        if argv[0] == self.ROS:
            assert argv[1] == str(self.modules["compare"].ORACLE)
            if name == "needs_arg":
                answer = {"error": "XmlParseException: [x] requires the 'robot' arg to be set"}
            elif name == "ros_refuses":
                answer = {"error": "ResourceNotFound: demo_missing"}
            else:
                answer = self.plan("--rate 50")
            return run.Outcome(0, json.dumps(answer), "")
        if argv[1] == str(self.modules["jobs"].LAUNCH_COMPARE):
            ours = self.plan(["--rate", "10" if name == "differs" else "50"])
            dry = "the dry run finds nodes [], not ['sim']" if name == "dry_differs" else None
            return run.Outcome(0, json.dumps({"plan": ours, "dry_run": dry}), "")
        cli = {
            "hangs": run.Outcome(None, "", "", timed_out=True, seconds=timeout),
            "aborts": run.Outcome(-6, "", "terminate called after throwing an instance\n"),
            "stopped": run.Outcome(143, "", ""),  # workbench stopped by a SIGTERM
            "traceback": run.Outcome(
                1,
                "",
                "Traceback (most recent call last):\n  File \"x.py\", line 1\nKeyError: 'rate'\n",
            ),
            "internal": run.Outcome(
                70, "", "workbench launch: internal error: KeyError: 'rate' (while running: ...)\n"
            ),
            "warns": run.Outcome(
                0, "node /sim: turtlesim/turtlesim_node\n", "[WARN] launch-prefix is ignored\n"
            ),
            "remote": run.Outcome(
                1,
                "",
                "workbench launch: error: remote.launch:2: <machine name='far' address='far'>: "
                'workbench runs every node on this computer (use address="localhost")\n',
            ),
        }
        if name in cli:
            return cli[name]
        if name in ("refuses", "needs_arg"):
            return run.Outcome(
                1, "", f"workbench launch: error: {name}.launch:2: argument 'robot' has no value\n"
            )
        return run.Outcome(0, "node /sim: turtlesim/turtlesim_node\n", "")


def test_every_class_from_injected_commands(corpus, tmp_path) -> None:  # type: ignore[no-untyped-def]
    run, jobs, files = corpus["run"], corpus["jobs"], corpus["files"]
    fake = FakeTools(corpus)
    ctx = jobs.Context(
        root=tmp_path, models=[], work=tmp_path, timeout=5.0, runner=fake, ros_python=FakeTools.ROS
    )
    expected = {
        "same": (run.WORKS, ""),
        "warns": (run.WARNINGS, "launch-prefix"),
        "needs_arg": (run.REFUSAL, "needs args: "),
        "refuses": (run.WRONG, "refused, roslaunch accepts: "),
        "differs": (run.WRONG, "differs from roslaunch: node sim args: ours ['--rate', '10']"),
        "dry_differs": (run.WRONG, "differs from roslaunch: the dry run finds nodes []"),
        "remote": (run.DESIGN, "remote.launch:2: <machine name='far'"),
        "ros_refuses": (run.WRONG, "accepted, roslaunch refuses: ResourceNotFound"),
        "traceback": (run.TRACEBACK, "KeyError: 'rate'"),
        "internal": (run.TRACEBACK, "internal error"),
        "hangs": (run.HANG, "no answer within"),
        "aborts": (run.CRASH, "killed by SIGABRT"),
        "stopped": (run.CRASH, "stopped by SIGTERM from outside (exit 143)"),
    }
    for name, (cls, message) in expected.items():
        (result,) = jobs.run_launch(ctx, files.Item("launch", tmp_path / f"{name}.launch"))
        assert (result.cls, result.ros.split(":")[0]) == (
            cls,
            "refuses" if name in ("needs_arg", "ros_refuses") else "accepts",
        ), (name, result)
        assert result.message.startswith(message) or message in result.message, (name, result)
    # A hang is given a second chance with twice the time before it counts.
    hung = [call for call in fake.calls if call[-1].endswith("hangs.launch") and "launch" in call]
    assert len(hung) == 2
    # So is a command that a signal from outside stopped.
    stopped = [c for c in fake.calls if c[-1].endswith("stopped.launch") and "launch" in c]
    assert len(stopped) == 2

    # Without roslaunch, a refusal cannot be judged.
    ctx.ros_python = None
    (result,) = jobs.run_launch(ctx, files.Item("launch", tmp_path / "refuses.launch"))
    assert (result.cls, result.ros) == (run.UNVERIFIED, "no oracle")


def test_the_table_counts_what_ros_accepts(corpus) -> None:  # type: ignore[no-untyped-def]
    run, main, jobs = corpus["run"], corpus["main"], corpus["jobs"]

    def result(cls: str, ros: str) -> object:
        return jobs.Result("launch", "launch --dry-run", "f.launch", cls, "", ros, 0.1)

    rows = main.summarize(
        [
            result(run.WORKS, "accepts"),
            result(run.WARNINGS, "no oracle"),
            result(run.REFUSAL, "refuses: needs args"),
            result(run.WRONG, "accepts"),
            result(run.HANG, "accepts"),
        ]
    )
    (row,) = rows
    assert row["files"] == 5 and row["ros_accepts"] == 4 and row["runs_of_accepted"] == 2
    assert row["runs_of_accepted_pct"] == 50.0
    assert row[run.REFUSAL] == row[run.WRONG] == row[run.HANG] == 1


def test_the_comparison_names_each_difference(corpus) -> None:  # type: ignore[no-untyped-def]
    compare = corpus["compare"]
    theirs = FakeTools(corpus).plan("a 'b c'")
    theirs["nodes"][0].update(namespace="/ns/", remaps=[["x", "/y/"]])
    theirs["params"] = {"/ns/n/rate": 1, "/flag": True}
    ours = json.loads(json.dumps(theirs))
    # The same plan spelt as workbench spells it: args as words, canonical names,
    # an integer-valued float, the default output.
    ours["nodes"][0].update(namespace="/ns", args=["a", "b c"], remaps=[["x", "/y"]], output="log")
    ours["params"]["/ns/n/rate"] = 1.0
    assert compare.differences(compare.normalise(ours), compare.normalise(theirs)) == []
    ours["params"]["/flag"] = 1
    ours["nodes"][0]["remaps"] = [["x", "/z"]]
    ours["nodes"][0]["respawn"] = True
    problems = compare.differences(compare.normalise(ours), compare.normalise(theirs))
    assert any(p.startswith("node sim remaps") for p in problems), problems
    assert any(p.startswith("node sim respawn") for p in problems)
    assert any(p.startswith("param /flag") for p in problems), problems
    assert compare.classify(ours, {"error": "x"})[0] == "ours only"


# --- real child processes -----------------------------------------------------------------


FAKE_WORKBENCH = """
import os, sys, time
name = os.path.basename(sys.argv[-1]).split(".")[0]
if name == "hangs":
    time.sleep(3600)
if name == "aborts":
    os.abort()
if name == "traceback":
    raise KeyError("rate")
if name == "refuses":
    sys.exit("workbench launch: error: refuses.launch:2: argument 'robot' has no value")
print("node /sim: turtlesim/turtlesim_node")
"""


def test_real_processes_that_hang_abort_or_raise(corpus, tmp_path) -> None:  # type: ignore[no-untyped-def]
    run, jobs, files, main = corpus["run"], corpus["jobs"], corpus["files"], corpus["main"]
    fake = write(tmp_path / "fake_workbench.py", FAKE_WORKBENCH)
    ctx = jobs.Context(
        root=tmp_path,
        models=[],
        work=tmp_path,
        timeout=20.0,
        workbench=[sys.executable, str(fake)],
        retry_hangs=False,
    )
    names = ["works", "refuses", "traceback", "aborts", "hangs"]
    items = [files.Item("launch", tmp_path / f"{name}.launch") for name in names]
    results = main.run_all(ctx, items, jobs=2)
    assert [r.cls for r in results] == [
        run.WORKS,
        run.UNVERIFIED,
        run.TRACEBACK,
        run.CRASH,
        run.HANG,
    ]
    assert "argument 'robot' has no value" in results[1].message
    assert results[2].message == "KeyError: 'rate'"


def test_a_timeout_kills_what_the_command_started(corpus, tmp_path) -> None:  # type: ignore[no-untyped-def]
    run = corpus["run"]
    pid_file = tmp_path / "child.pid"
    parent = (
        "import subprocess, sys, time\n"
        "child = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(3600)'])\n"
        f"open({str(pid_file)!r}, 'w').write(str(child.pid))\n"
        "time.sleep(3600)\n"
    )
    outcome = run.run_process([sys.executable, "-c", parent], dict(os.environ), tmp_path, 10.0)
    assert outcome.timed_out and outcome.returncode is None
    assert run.failure(outcome)[0] == run.HANG
    child = int(pid_file.read_text())
    # Killed with its group: soon gone, or a zombie waiting for init to reap it.
    deadline = time.monotonic() + 60
    while (state := process_state(child)) not in ("gone", "Z", "X"):
        assert time.monotonic() < deadline, f"the command's child {child} still runs ({state})"
        time.sleep(0.05)


def process_state(pid: int) -> str:
    """The state letter in /proc/PID/stat (R, S, Z ...), or 'gone'."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return "gone"


# --- the real workbench beside the real oracles --------------------------------------------


def real_context(corpus, tree, tmp_path, **oracles):  # type: ignore[no-untyped-def]
    root, models = tree
    work = tmp_path / "work"
    work.mkdir()
    return corpus["jobs"].Context(root=root, models=[models], work=work, timeout=TIMEOUT, **oracles)


def test_launch_files_resolve_as_roslaunch_resolves_them(corpus, tree, tmp_path) -> None:  # type: ignore[no-untyped-def]
    run, jobs, files = corpus["run"], corpus["jobs"], corpus["files"]
    ctx = real_context(
        corpus, tree, tmp_path, ros_python=ros_python("roslaunch", "python3-roslaunch")
    )
    root, _ = tree
    launch = root / "demo_bringup" / "launch"
    (same,) = jobs.run_launch(ctx, files.Item("launch", launch / "bringup.launch"))
    # roslaunch's nodes (rsp in /demo with both remappings, sim in /tools), args, params
    # (/limits/speed, /limits/turn/max ..., /demo/rsp/publish_frequency = 50.0) and
    # workbench's are the same.
    assert (same.cls, same.ros) == (run.WORKS, "accepts"), same
    (included,) = jobs.run_launch(ctx, files.Item("launch", launch / "include.launch.xml"))
    assert (included.cls, included.ros) == (run.WORKS, "accepts"), included
    # An argument without a default is given NAME:=value on both sides.
    (needs,) = jobs.run_launch(ctx, files.Item("launch", launch / "needs_robot.launch"))
    assert (needs.cls, needs.ros) == (run.WORKS, "accepts"), needs
    # A machine elsewhere: roslaunch accepts it, workbench refuses it on purpose.
    (remote,) = jobs.run_launch(ctx, files.Item("launch", launch / "remote.machine"))
    assert (remote.cls, remote.ros) == (run.DESIGN, "accepts"), remote
    assert "workbench runs every node on this computer" in remote.message
    # A changed copy of what workbench resolves is caught.
    ctx.python = str(
        write(
            tmp_path / "python_changing_args.py",
            f"""
            #!{sys.executable}
            import subprocess, sys
            done = subprocess.run([{sys.executable!r}, *sys.argv[1:]], capture_output=True, text=True)
            sys.stdout.write(done.stdout.replace("--verbose", "--quiet"))
            sys.exit(done.returncode)
            """,
        )
    )
    os.chmod(ctx.python, 0o755)
    (changed,) = jobs.run_launch(ctx, files.Item("launch", launch / "bringup.launch"))
    assert changed.cls == run.WRONG and "args" in changed.message, changed


def test_roslaunch_finds_the_stand_ins_where_workbench_does(corpus, tree, tmp_path) -> None:  # type: ignore[no-untyped-def]
    run, jobs, files = corpus["run"], corpus["jobs"], corpus["files"]
    ctx = real_context(
        corpus,
        tree,
        tmp_path,
        ros_python=ros_python("roslaunch", "python3-roslaunch"),
        oracle_packages=corpus["main"].oracle_packages(),
    )
    root, _ = tree
    package(root, "gazebo_ros")  # the user's own copy shadows workbench's stand-in
    launch = write(
        root / "demo_bringup" / "launch" / "finds.launch",
        """
        <launch>
          <param name="gazebo_ros" value="$(find gazebo_ros)"/>
          <param name="robot_description"
                 command="$(find xacro)/xacro $(find demo_description)/urdf/demo.urdf"/>
        </launch>
        """,
    )
    # Both find the user's gazebo_ros in the root and workbench's xacro at the same path
    # (a different path would differ in the parameters).
    (finds,) = jobs.run_launch(ctx, files.Item("launch", launch))
    assert (finds.cls, finds.ros) == (run.WORKS, "accepts"), finds
    ctx.oracle_packages = []  # without the stand-ins roslaunch does not know xacro
    (alone,) = jobs.run_launch(ctx, files.Item("launch", launch))
    assert alone.cls == run.WRONG and "ResourceNotFound: xacro" in alone.message, alone


def test_descriptions_check_and_graph_as_urdfdom_does(
    corpus, tree, tmp_path, require_program
) -> None:  # type: ignore[no-untyped-def]
    run, jobs, files = corpus["run"], corpus["jobs"], corpus["files"]
    ctx = real_context(
        corpus,
        tree,
        tmp_path,
        check_urdf=require_program("check_urdf"),
        urdf_to_graphviz=require_program("urdf_to_graphviz"),
    )
    root, _ = tree
    urdf = root / "demo_description" / "urdf"
    check, graph = jobs.run_description(ctx, files.Item("description", urdf / "demo.urdf"))
    # The tree workbench prints is check_urdf's and its .gv is urdf_to_graphviz's.
    assert (check.command, check.cls, check.ros) == ("check", run.WORKS, "accepts"), check
    assert (graph.command, graph.cls, graph.ros) == ("graph", run.WORKS, "accepts"), graph
    check, graph = jobs.run_description(ctx, files.Item("description", urdf / "macros.xacro"))
    # A file of macros only expands to a robot without links: both refuse it.
    assert check.cls == graph.cls == run.REFUSAL, (check, graph)
    assert "No link elements" in check.ros


@pytest.mark.slow
def test_models_and_worlds_as_libsdformat_reads_them(corpus, tree, tmp_path) -> None:  # type: ignore[no-untyped-def]
    run, jobs, files, oracles = corpus["run"], corpus["jobs"], corpus["files"], corpus["oracles"]
    checker = oracles.build_sdf_check(tmp_path)
    if checker is None:
        skip_or_fail(
            "libsdformat's headers or g++ are missing (apt-get install libsdformat-dev g++)"
        )
    ctx = real_context(corpus, tree, tmp_path, sdf_check=checker)
    root, models = tree
    (box,) = jobs.run_model(ctx, files.Item("model", models / "demo_box" / "model.sdf"))
    assert (box.cls, box.ros) == (run.WORKS, "accepts"), box
    shelf = models / "demo_shelf" / "model-1_4.sdf"
    (broken,) = jobs.run_model(ctx, files.Item("model", shelf))
    assert broken.cls == run.REFUSAL and "no_such_part" in broken.ros, broken
    worlds = root / "demo_gazebo" / "worlds"
    (world,) = jobs.run_world(ctx, files.Item("world", worlds / "demo.world"))
    assert (world.cls, world.ros) == (run.WORKS, "accepts"), world
    (missing,) = jobs.run_world(ctx, files.Item("world", worlds / "missing.world"))
    assert missing.cls == run.REFUSAL and "no_such_model" in missing.ros, missing


def test_the_script_prints_the_table_and_writes_json(corpus, tree, tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    root, models = tree
    out = tmp_path / "corpus.json"
    status = corpus["main"].main(
        ["--root", str(root), "--models", str(models), "--only", "map", "--json", str(out)]
    )
    printed = capsys.readouterr().out
    assert status == 0
    assert "| map         | map show" in printed and "machine:" in printed
    payload = json.loads(out.read_text())
    assert payload["benchmark"] == "corpus" and payload["machine"]["cores"]
    (row,) = payload["rows"]
    assert (row["kind"], row["files"], row["works"], row["runs_of_accepted_pct"]) == (
        "map",
        1,
        1,
        100.0,
    )
    assert payload["results"][0]["file"].endswith("maps/map.yaml")


def test_commands_see_the_packages_the_models_and_their_own_cache(corpus, tree, tmp_path) -> None:  # type: ignore[no-untyped-def]
    root, models = tree
    work = tmp_path / "work"
    work.mkdir()
    shim = corpus["main"].oracle_packages()
    assert "xacro" in {folder.name for folder in shim}
    ctx = corpus["jobs"].Context(
        root=root,
        models=[models],
        work=work,
        timeout=1.0,
        oracle_packages=shim,
        cache=work / "c",
        environment={"LDS_MODEL": "LDS-02"},
    )
    ours, ros = ctx.env(), ctx.env(oracle=True)
    assert ours["ROS_PACKAGE_PATH"] == str(root)
    assert ros["ROS_PACKAGE_PATH"] == os.pathsep.join(map(str, [root, *shim]))
    assert ours["GAZEBO_MODEL_PATH"] == ros["GAZEBO_MODEL_PATH"] == str(models)
    assert ours["WORKBENCH_MASTER_URI"] == "inproc"
    assert ours["WORKBENCH_CACHE_DIR"] == str(work / "c")
    assert ours["LDS_MODEL"] == ros["LDS_MODEL"] == "LDS-02"  # --env over the default
    assert ours["TURTLEBOT3_MODEL"] == os.environ.get("TURTLEBOT3_MODEL", "burger")
    assert "PYTHONPATH" not in ros
