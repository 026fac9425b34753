"""``workbench check`` and ``workbench graph`` against ROS's own urdfdom tools.

Runs Debian's ``check_urdf`` and ``urdf_to_graphviz`` (liburdfdom-tools, urdfdom
3.0.1 on TinyXML) and workbench on every model in ``urdf/``, on 40 random trees
from a seeded generator, and on malformed variants. What is claimed, and so
compared exactly:

* check stdout: workbench's stdout *starts with* check_urdf's stdout, byte for
  byte: robot name, banner, root, children ordered by joint name (urdfdom keeps
  joints in a ``std::map``, model.h ``initTree``), indented by ``printTree``; and
  nothing at all when urdfdom refuses the file (``parseURDF`` returns null).
  After it, workbench adds a blank line and its own findings, asserted on their
  own: every case urdfdom logs an error for is an error in workbench's report.
* check stderr: urdfdom's console_bridge lines (``Error:   ...``/``Warning: ...``)
  in the same order, without console_bridge's second line that names urdfdom's
  C++ source file. A malformed ``<visual>``/``<collision>``/``<inertial>`` is
  logged and skipped while the link is kept (link.cpp ``parseLink``, whose result
  model.cpp ignores); a malformed joint, a duplicate name, an unknown link or a
  second root refuses the whole file.
* graph: the ``.gv`` file is identical, byte for byte (urdf_to_graphviz.cpp):
  numbers as a C++ ostream prints doubles (6 significant digits, ``-0`` kept) and
  rpy printed back from the quaternion by urdfdom_headers' ``Rotation::getRPY``.

Where urdfdom refuses a file workbench also fails, with its own one-line error
(urdfdom's TinyXML messages are not reproduced). Skips without the tools
(fails under WORKBENCH_REQUIRE_ALL=1) through conftest's ``require_program``
fixture: a module-level ``from conftest import`` would find ``tests/bus/conftest.py``
when the whole suite runs. Install them with ``apt-get install liburdfdom-tools``.
"""

from __future__ import annotations

import math
import subprocess
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from urdfdom_tools import Tools, run_cli

REPO_ROOT = Path(__file__).resolve().parents[2]
LAB_MODELS = sorted((REPO_ROOT / "urdf").glob("*.urdf"))
RANDOM_CASES = 40


# --- running both sides ----------------------------------------------------------------


@dataclass
class Run:
    status: int
    stdout: str
    stderr: list[str]
    gv: str | None


def run_ros(tools: Tools, path: Path, tmp_path: Path) -> Run:
    """check_urdf's output and urdf_to_graphviz's .gv (dot kept off PATH: no rendering)."""
    env = {"PATH": str(tmp_path / "no-programs"), "LC_ALL": "C"}
    done = subprocess.run(
        [tools.check_urdf, str(path)], capture_output=True, text=True, env=env, timeout=60
    )
    stderr = [line for line in done.stderr.splitlines() if not line.startswith("         at ")]
    out = tmp_path / "ros"
    out.unlink(missing_ok=True)
    Path(f"{out}.gv").unlink(missing_ok=True)
    subprocess.run(
        [tools.urdf_to_graphviz, str(path), str(out)], capture_output=True, env=env, timeout=60
    )
    gv = Path(f"{out}.gv")
    return Run(done.returncode, done.stdout, stderr, gv.read_text() if gv.exists() else None)


def run_workbench(path: Path, tmp_path: Path, load: bool = False) -> Run:
    status, stdout, stderr = run_cli("check", str(path), *([] if load else ["--no-load"]))
    gv = tmp_path / "wb.gv"
    gv.unlink(missing_ok=True)
    graph_status, _, graph_error = run_cli("graph", str(path), "-o", str(gv))
    if graph_status != 0:
        assert graph_error.count("\n") == 1 and "Traceback" not in graph_error, graph_error
    return Run(status, stdout, stderr.splitlines(), gv.read_text() if gv.exists() else None)


def split_report(stdout: str) -> tuple[str, list[str]]:
    """(check_urdf's part, workbench's findings lines) of workbench check's stdout.

    The report is check_urdf's stdout, a blank line when that is not empty, then
    the findings block starting "workbench found".
    """
    lines = stdout.splitlines(keepends=True)
    at = next(i for i, line in enumerate(lines) if line.startswith("workbench found"))
    head = "".join(lines[:at])
    return head.removesuffix("\n") if head else head, [line.rstrip("\n") for line in lines[at:]]


def compare(
    tools: Tools, path: Path, tmp_path: Path, load: bool = False
) -> tuple[Run, Run, list[str]]:
    """Assert everything claimed to match; returns both runs and workbench's findings."""
    ros, wb = run_ros(tools, path, tmp_path), run_workbench(path, tmp_path, load)
    assert "Traceback" not in wb.stdout + "".join(wb.stderr)
    if wb.stdout == "":  # workbench cannot read the file at all: one line, and ROS refuses too
        assert wb.status == 1 and len(wb.stderr) == 1, wb.stderr
        assert wb.stderr[0].startswith("workbench check: error: ")
        assert ros.status != 0 and ros.stdout == "" and ros.gv is None
        assert wb.gv is None
        return ros, wb, []
    tree, findings = split_report(wb.stdout)
    assert tree == ros.stdout
    assert wb.stderr == ros.stderr
    assert wb.gv == ros.gv
    if ros.status != 0 or any(line.startswith("Error:") for line in ros.stderr):
        assert wb.status == 1, "workbench passes what ROS refuses or skips"
    return ros, wb, findings


def elements_in_error(findings: list[str]) -> set[str]:
    """The elements workbench's findings give an error on (``link 'arm'``)."""
    return {line.split(": error: ")[1].split(":")[0] for line in findings if ": error: " in line}


# --- the lab's models ------------------------------------------------------------------


@pytest.mark.parametrize("path", LAB_MODELS, ids=[path.name for path in LAB_MODELS])
def test_lab_models_match(ros_tools, tmp_path, path):
    ros, wb, _ = compare(ros_tools, path, tmp_path)
    assert ros.status == 0 and ros.gv is not None
    assert wb.stdout.startswith("robot name is: ")


# --- random trees ------------------------------------------------------------------------

NAMES = ["base", "Base2", "arm", "arm_10", "arm_9", "wheel", "Z", "a", "link-x", "tool0", "_t"]
JOINT_TYPES = ["revolute", "continuous", "prismatic", "fixed", "floating", "planar"]


def _number(rng: np.random.Generator) -> str:
    """A coordinate as people write them: -0, integers, exponents, long and short decimals."""
    choice = int(rng.integers(8))
    value = float(rng.normal(0.0, 1.5))
    return [
        "-0",
        "0",
        f"{value:.3f}",
        repr(value),
        f"{value * 1e-6:e}",
        f"{int(value * 100)}",
        f"{value * 1e5:.1f}",
        f"+{abs(value):.2f}",
    ][choice]


def _angle(rng: np.random.Generator) -> str:
    """An angle, often outside ±pi, at a quarter turn, or at the pitch poles."""
    choice = int(rng.integers(6))
    if choice == 0:
        return f"{rng.uniform(-10.0, 10.0):.6f}"
    if choice == 1:
        return repr(float(rng.integers(-6, 7)) * math.pi / 2)
    if choice == 2:
        return str(rng.choice(["3.14159", "-3.14159", "-4.71238898038", "1.5708", "-0"]))
    return _number(rng)


def _vector(rng: np.random.Generator, angles: bool = False) -> str:
    pick = _angle if angles else _number
    separator = str(rng.choice([" ", " ", "  "]))
    return separator.join(pick(rng) for _ in range(3))


def random_robot(seed: int) -> str:
    """A valid URDF tree: shuffled links and joints, names whose order differs from the file's."""
    rng = np.random.default_rng(seed)
    count = int(rng.integers(1, 9))
    links = [f"{NAMES[int(i)]}_{k}" for k, i in enumerate(rng.integers(len(NAMES), size=count))]
    body = ['<?xml version="1.0"?>', f'<robot name="random_{seed}">']
    for name in rng.permutation(links):
        shape = str(rng.choice(['<box size="0.1 0.2 0.3"/>', '<sphere radius="0.05"/>']))
        body.append(f'  <link name="{name}"><visual><geometry>{shape}</geometry></visual></link>')
    joints = []
    for index in range(1, count):
        parent = links[int(rng.integers(index))]
        kind = JOINT_TYPES[int(rng.integers(len(JOINT_TYPES)))]
        name = f"{NAMES[int(rng.integers(len(NAMES)))]}_j{int(rng.integers(100))}_{index}"
        parts = [f'<parent link="{parent}"/>', f'<child link="{links[index]}"/>']
        if rng.random() < 0.85:
            attributes = []
            if rng.random() < 0.9:
                attributes.append(f'xyz="{_vector(rng)}"')
            if rng.random() < 0.9:
                attributes.append(f'rpy="{_vector(rng, angles=True)}"')
            parts.append(f"<origin {' '.join(attributes)}/>")
        if kind in ("revolute", "prismatic") or rng.random() < 0.2:
            parts.append('<limit lower="-1" upper="1" effort="10" velocity="1"/>')
        if kind not in ("fixed", "floating"):
            parts.append('<axis xyz="0 0 1"/>')
        joints.append(f'  <joint name="{name}" type="{kind}">{"".join(parts)}</joint>')
    body += [joints[int(i)] for i in rng.permutation(len(joints))]
    body.append("</robot>")
    return "\n".join(body) + "\n"


@pytest.mark.parametrize("seed", range(RANDOM_CASES))
def test_random_trees_match(ros_tools, tmp_path, seed):
    path = tmp_path / f"random_{seed}.urdf"
    path.write_text(random_robot(seed))
    ros, wb, _ = compare(ros_tools, path, tmp_path)
    assert ros.status == 0 and wb.gv is not None


# --- malformed variants ------------------------------------------------------------------

BASE = """<?xml version="1.0"?>
<robot name="mutant">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><origin xyz="0 0 0.1" rpy="0 0 0"/><geometry><box size="0.2 0.2 0.2"/></geometry><material name="grey"/></visual>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <link name="arm">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><geometry><cylinder radius="0.05" length="0.5"/></geometry></visual>
    <collision><geometry><cylinder radius="0.05" length="0.5"/></geometry></collision>
  </link>
  <link name="hand">
    <inertial><mass value="0.5"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
    <collision><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="arm"/>
    <origin xyz="0 -0 0.2" rpy="0 0 -4.71238898038"/>
    <axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>
  </joint>
  <joint name="elbow" type="fixed">
    <parent link="arm"/><child link="hand"/>
    <origin xyz="0 0 0.5" rpy="3.14159 0 0"/>
  </joint>
</robot>
"""


def _sub(*pairs: str) -> Callable[[str], str]:
    """A mutation replacing each ``old`` by its ``new`` (given as old, new, old, new, ...)."""

    def mutate(text: str) -> str:
        for old, new in zip(pairs[::2], pairs[1::2], strict=True):
            assert old in text, old
            text = text.replace(old, new, 1)
        return text

    return mutate


@dataclass(frozen=True)
class Mutation:
    """A malformed variant of BASE.

    Attributes:
        name: What is wrong.
        mutate: BASE -> the variant.
        ros_status: check_urdf's exit status (255: urdfdom refuses the file).
        error_on: The element workbench reports an error on below check_urdf's part;
            "" for none (the report passes), None when workbench cannot read the file.
    """

    name: str
    mutate: Callable[[str], str]
    ros_status: int
    error_on: str | None


HEAD = '<?xml version="1.0"?>'
LIMIT = '<limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>'
ARM_SHAPE = '<cylinder radius="0.05" length="0.5"/></geometry></visual>'
HAND_SHAPE = '<sphere radius="0.05"/>'
LAST = "</robot>"


def _joint(name: str, parent: str, child: str) -> str:
    return f'<joint name="{name}" type="fixed"><parent link="{parent}"/><child link="{child}"/></joint>\n</robot>'


# fmt: off
MUTATIONS = [
    Mutation("unchanged", _sub(), 0, ""),
    # ROS reads these (TinyXML knows no namespaces and takes any declaration).
    Mutation("xml version 0.0", _sub(HEAD, '<?xml version="0.0"?>'), 0, ""),
    Mutation("declaration after a comment", _sub(HEAD, f"<!-- by hand -->\n{HEAD}"), 0, ""),
    Mutation("undeclared prefix", _sub(LAST, '<gazebo><sensor:ray name="r"/></gazebo>\n' + LAST), 0, ""),
    Mutation("robot version 1.0", _sub('name="mutant"', 'name="mutant" version="1.0"'), 0, ""),
    Mutation("numbers C++ reads", _sub('xyz="0 0 0.5"', 'xyz="+.5 1. -0e3"'), 0, ""),
    # urdfdom logs an error, skips the element (and the rest of the link), prints the tree.
    Mutation("box with 2 sizes", _sub('size="0.2 0.2 0.2"', 'size="0.2 0.2"'), 0, "link 'base'"),
    Mutation("rpy with 4 numbers", _sub('rpy="0 0 0"', 'rpy="0 0 0 1"'), 0, "link 'base'"),
    Mutation("mesh without filename", _sub(ARM_SHAPE, "<mesh/></geometry></visual>"), 0, "link 'arm'"),
    Mutation("empty geometry", _sub(HAND_SHAPE, ""), 0, "link 'hand'"),
    Mutation("unknown geometry", _sub(HAND_SHAPE, '<cone radius="1"/>'), 0, "link 'hand'"),
    Mutation("inertia without ixy", _sub('ixx="0.001" ixy="0"', 'ixx="0.001"'), 0, "link 'hand'"),
    Mutation("nameless material", _sub('<material name="grey">', "<material>"), 0, "material ''"),
    Mutation("colourless material", _sub('<color rgba="0.5 0.5 0.5 1"/>', ""), 0, "material 'grey'"),
    # urdfdom warns (twice: it assigns a link's first visual twice); workbench warns.
    Mutation("undefined material", _sub('<material name="grey"/>', '<material name="tin"/>'), 0, ""),
    # urdfdom keeps these shapes; workbench warns and leaves them out of what Drake gets
    # (Drake would abort the whole process on them).
    Mutation("negative radius", _sub('radius="0.05" length', 'radius="-0.05" length'), 0, ""),
    Mutation("zero box", _sub('"0.2 0.2 0.2"/></geometry></c', '"0 1 1"/></geometry></c'), 0, ""),
    # A link with two parents: urdfdom prints it under both; workbench calls it an error.
    Mutation("two parents", _sub(LAST, _joint("again", "base", "hand")), 0, "joint 'again'"),
    # urdfdom refuses the file: check_urdf prints nothing on stdout.
    Mutation("revolute without limit", _sub(LIMIT, ""), 255, "joint 'shoulder'"),
    Mutation("prismatic without limit", _sub(LIMIT, "", '"revolute"', '"prismatic"'), 255, "joint 'shoulder'"),
    Mutation("limit without effort", _sub('effort="10" ', ""), 255, "joint 'shoulder'"),
    Mutation("trailing space in a number", _sub('velocity="1"', 'velocity="1 "'), 255, "joint 'shoulder'"),
    Mutation("line break in a number", _sub('xyz="0 -0 0.2"', 'xyz="0\n0 0.2"'), 255, "joint 'shoulder'"),
    Mutation("calibration not a number", _sub(LIMIT, LIMIT + '<calibration rising="x"/>'), 255, "joint 'shoulder'"),
    Mutation("mimic without joint", _sub(LIMIT, LIMIT + '<mimic multiplier="2"/>'), 255, "joint 'shoulder'"),
    Mutation("robot version 2.0", _sub('name="mutant"', 'name="mutant" version="2.0"'), 255, "robot 'mutant'"),
    Mutation("duplicate material", _sub("  <link", '  <material name="grey"/>\n  <link'), 255, "material 'grey'"),
    Mutation("duplicate link", _sub('  <link name="hand">', '  <link name="arm"/><link name="hand">'), 255, "link 'arm'"),
    Mutation("two roots", _sub('  <link name="hand">', '  <link name="loose"/><link name="hand">'), 255, "robot 'mutant'"),
    Mutation("undefined parent", _sub('<parent link="arm"/>', '<parent link="ghost"/>'), 255, "joint 'elbow'"),
    Mutation("no root", _sub(LAST, _joint("back", "hand", "base")), 255, "link 'base'"),
    # urdfdom refuses, and workbench cannot read the joint either (one line on stderr).
    Mutation("joint rpy with 4 numbers", _sub('rpy="3.14159 0 0"', 'rpy="3.14159 0 0 0"'), 255, None),
    Mutation("unknown joint type", _sub('type="fixed"', 'type="hinge"'), 255, None),
    Mutation("joint without child", _sub('<child link="hand"/>', ""), 255, None),
]
# fmt: on


@pytest.mark.parametrize("case", MUTATIONS, ids=[case.name for case in MUTATIONS])
def test_malformed_variants(ros_tools, tmp_path, case):
    path = tmp_path / "mutant.urdf"
    path.write_text(case.mutate(BASE))
    # Drake's load runs once here, on the shape it would abort the process on.
    ros, wb, findings = compare(ros_tools, path, tmp_path, load=case.name == "negative radius")
    assert ros.status == case.ros_status
    if case.error_on is None:
        assert wb.stdout == ""
    elif case.error_on == "":
        assert wb.status == 0, findings
    else:
        # workbench's own part: an error on the element urdfdom skipped, refused or misread.
        assert wb.status == 1
        assert case.error_on in elements_in_error(findings), findings


def test_a_loop_below_the_root_is_an_error_not_a_crash(tmp_path):
    """The one tree the ROS tools cannot print: a link reached again below itself.

    check_urdf and urdf_to_graphviz recurse around the loop, each level indented
    further, until the stack overflows (SIGSEGV after gigabytes of output, so the
    real tools are not run here); workbench prints no tree and says why.
    """
    path = tmp_path / "loop.urdf"
    path.write_text(_sub(LAST, _joint("up", "hand", "arm"))(BASE))
    status, stdout, stderr = run_cli("check", str(path), "--no-load")
    tree, findings = split_report(stdout)
    assert status == 1 and tree == "" and stderr == ""
    assert "link 'arm' already has parent joint 'shoulder'" in "\n".join(findings)
    status, _, stderr = run_cli("graph", str(path), "-o", str(tmp_path / "loop.gv"))
    assert status == 1 and "already has parent joint" in stderr
    assert not (tmp_path / "loop.gv").exists()
