"""What ROS's URDF parser accepts, workbench accepts: check_urdf against ``workbench check``.

Generated URDF variants (seeded) carry the quirks real descriptions have and
urdfdom 3.0.1 (Debian's liburdfdom-tools, behind check_urdf, RViz and MoveIt)
reads without an error. For every variant Debian's ``check_urdf`` and
``workbench check`` run on the same file, and:

* check_urdf accepts (exit 0, no ``Error:`` line) ⇔ ``workbench check`` exits 0
  (warnings allowed) and Drake loaded the model; where check_urdf errors,
  workbench errors;
* workbench's report starts with check_urdf's stdout and prints its stderr lines
  (as in ``test_urdfdom_differential.py``), and ``workbench graph`` writes
  urdf_to_graphviz's ``.gv``.

Each quirk says where urdfdom decides it (urdfdom 3.0.1 ``urdf_parser/src``, and
urdfdom_headers 1.0.5 for colours); ``ros_accepts`` is asserted against the real
tool too, so a quirk that stops being what it claims fails here.

Three things urdfdom accepts stay errors, because nothing downstream of it in ROS
shows them either (test_accepted_by_urdfdom_but_broken_downstream): a zero joint
axis, a link with two parents, a mesh file that is not there.
"""

from __future__ import annotations

import json
import subprocess
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest
from urdfdom_tools import Tools, run_cli

SEEDS = 24
INERTIAL = (
    '<inertial><mass value="1"/>'
    '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>'
)
LIMIT = '<limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>'


@dataclass
class Model:
    """A URDF in parts, so that quirks compose: a chain base - l1 - l2 - l3 - l4 - tool."""

    materials: list[str] = field(
        default_factory=lambda: ['<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>']
    )
    links: dict[str, list[str]] = field(default_factory=dict)
    joints: dict[str, list[str]] = field(default_factory=dict)
    kinds: dict[str, str] = field(default_factory=dict)
    after: list[str] = field(default_factory=list)

    @classmethod
    def base(cls) -> Model:
        model = cls()
        chain = [
            ("j1", "revolute", "base", "l1"),
            ("j2", "revolute", "l1", "l2"),
            ("j3", "continuous", "l2", "l3"),
            ("j4", "prismatic", "l3", "l4"),
            ("j5", "fixed", "l4", "tool"),
        ]
        for name in ("base", "l1", "l2", "l3", "l4", "tool"):
            model.links[name] = [
                INERTIAL,
                '<visual><origin xyz="0 0 0.05" rpy="0 0 0"/><geometry><box size="0.1 0.1 0.1"/>'
                '</geometry><material name="grey"/></visual>',
                '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>',
            ]
        for joint, kind, parent, child in chain:
            parts = [f'<parent link="{parent}"/>', f'<child link="{child}"/>']
            parts.append('<origin xyz="0 0 0.1" rpy="0 0 0"/>')
            if kind != "fixed":
                parts.append('<axis xyz="0 0 1"/>')
            if kind in ("revolute", "prismatic"):
                parts.append(LIMIT)
            model.joints[joint], model.kinds[joint] = parts, kind
        return model

    def text(self) -> str:
        lines = ['<?xml version="1.0"?>', '<robot name="quirky">']
        lines += [f"  {material}" for material in self.materials]
        for name, parts in self.links.items():
            lines.append(f'  <link name="{name}">')
            lines += [f"    {part}" for part in parts]
            lines.append("  </link>")
        for name, parts in self.joints.items():
            lines.append(f'  <joint name="{name}" type="{self.kinds[name]}">')
            lines += [f"    {part}" for part in parts]
            lines.append("  </joint>")
        lines += [f"  {extra}" for extra in self.after]
        lines.append("</robot>")
        return "\n".join(lines) + "\n"

    def visual(self, link: str, geometry: str, material: str = "") -> None:
        self.links[link] = [p for p in self.links[link] if not p.startswith("<visual")]
        self.links[link].append(f"<visual><geometry>{geometry}</geometry>{material}</visual>")

    def replace(self, link: str, prefix: str, part: str | None) -> None:
        kept = [p for p in self.links[link] if not p.startswith(prefix)]
        self.links[link] = kept + ([part] if part is not None else [])

    def limit(self, joint: str, text: str) -> None:
        self.joints[joint] = [p for p in self.joints[joint] if not p.startswith("<limit")]
        self.joints[joint].append(text)


def _transmission(name: str, body: str) -> str:
    return f'<transmission name="{name}">{body}</transmission>'


SIMPLE = "<type>transmission_interface/SimpleTransmission</type>"
EFFORT = "<hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>"


@dataclass(frozen=True)
class Quirk:
    """One thing real descriptions do.

    Attributes:
        name: What it is.
        apply: Changes the model.
        ros_accepts: Whether urdfdom reads it without an error.
        source: Where urdfdom decides it.
    """

    name: str
    apply: Callable[[Model], None]
    ros_accepts: bool
    source: str


def _material_before_colour(model: Model) -> None:
    model.visual("l1", '<sphere radius="0.05"/>', '<material name="late"/>')
    model.visual(
        "l3", '<sphere radius="0.05"/>', '<material name="late"><color rgba="1 0 0 1"/></material>'
    )


def _two_colours_one_name(model: Model) -> None:
    model.links["l2"].append(
        '<visual><geometry><sphere radius="0.02"/></geometry>'
        '<material name="paint"><color rgba="0 1 0 1"/></material></visual>'
    )
    model.links["l2"].append(
        '<visual><geometry><sphere radius="0.03"/></geometry>'
        '<material name="paint"><color rgba="0 0 1 1"/></material></visual>'
    )


def _mesh(name: str, scale: str) -> Callable[[Model], None]:
    def apply(model: Model) -> None:
        model.visual("l4", f'<mesh filename="{name}" scale="{scale}"/>')
        model.replace(
            "l4",
            "<collision",
            f'<collision><geometry><mesh filename="{name}"/></geometry></collision>',
        )

    return apply


# fmt: off
QUIRKS = [
    # --- materials (link.cpp parseMaterial/parseVisual, model.cpp parseURDF/assignMaterial) ---
    Quirk("empty material name in a visual", lambda m: m.visual("l1", '<box size="0.1 0.1 0.1"/>', '<material name=""><color rgba="0.4 0.4 0.4 1.0"/></material>'), True,
          "parseVisual only needs the name attribute; assignMaterial returns early for an empty name"),
    Quirk("empty robot-level material name", lambda m: m.materials.append('<material name=""><color rgba="1 1 1 1"/></material>'), True,
          "parseURDF inserts it under the name '' (getMaterial('') finds none before)"),
    Quirk("material used before its colour", _material_before_colour, True,
          "assignMaterial: logWarn 'material ... undefined.', the link is kept"),
    Quirk("robot-level material after the links", lambda m: (m.materials.clear(), m.after.append('<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>')), True,
          "parseURDF reads every robot-level <material> before any <link>"),
    Quirk("rgba with three numbers", lambda m: m.visual("l4", '<box size="0.1 0.1 0.1"/>', '<material name="three"><color rgba="0.5 0.5 0.5"/></material>'), True,
          "urdfdom_headers Color::init returns false without throwing; parseMaterial ignores it"),
    Quirk("rgba with five numbers", lambda m: m.visual("l2", '<box size="0.1 0.1 0.1"/>', '<material name="five"><color rgba="1 0 0 1 1"/></material>'), True,
          "Color::init returns false for any count but four"),
    Quirk("one name, two colours", _two_colours_one_name, True,
          "assignMaterial: the first colour given to a name is the one every visual of that name gets"),
    Quirk("texture without colour", lambda m: m.visual("l3", '<box size="0.1 0.1 0.1"/>', '<material name="wood"><texture filename="package://nowhere/wood.png"/></material>'), True,
          "parseMaterial: a texture filename is enough; the file is never opened"),
    Quirk("duplicate robot-level material", lambda m: m.materials.append('<material name="grey"><color rgba="0 0 0 1"/></material>'), False,
          "parseURDF: logError 'material ... is not unique.', the model is dropped"),
    Quirk("colour out of range", lambda m: m.visual("l1", '<box size="0.1 0.1 0.1"/>', '<material name="hot"><color rgba="2 0 0 1"/></material>'), False,
          "Color::init throws for a component outside [0, 1]; parseMaterial logs an error"),
    # --- inertia (link.cpp parseInertial reads numbers and checks nothing else) ---
    Quirk("moving link without inertial", lambda m: m.replace("l2", "<inertial", None), True,
          "parseLink: <inertial> is optional"),
    Quirk("zero mass and inertia", lambda m: m.replace("l1", "<inertial", '<inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>'), True,
          "parseInertial: any double"),
    Quirk("negative mass", lambda m: m.replace("l3", "<inertial", '<inertial><mass value="-1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>'), True,
          "parseInertial: any double"),
    Quirk("inertia not positive definite", lambda m: m.replace("l2", "<inertial", '<inertial><mass value="1"/><inertia ixx="-0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>'), True,
          "parseInertial: any doubles"),
    Quirk("inertia breaks the triangle inequality", lambda m: m.replace("l4", "<inertial", '<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.05"/></inertial>'), True,
          "parseInertial: any doubles"),
    # --- shapes (link.cpp parseBox/parseCylinder/parseSphere/parseMesh read numbers only) ---
    Quirk("box of size zero", lambda m: m.visual("l1", '<box size="0 0.1 0.1"/>'), True, "parseBox: Vector3::init"),
    Quirk("negative cylinder radius", lambda m: m.replace("l2", "<collision", '<collision><geometry><cylinder radius="-0.05" length="0.2"/></geometry></collision>'), True,
          "parseCylinder: strToDouble"),
    Quirk("mesh scaled by zero", _mesh("part.obj", "1 0 1"), True, "parseMesh: Vector3::init"),
    Quirk("STL mesh", _mesh("part.stl", "0.001 0.001 0.001"), True, "parseMesh: the file is never opened"),
    Quirk("unnamed visual and collision", lambda m: (m.replace("l3", "<visual", '<visual name=""><geometry><sphere radius="0.05"/></geometry></visual>'), m.replace("l3", "<collision", '<collision name=""><geometry><sphere radius="0.05"/></geometry></collision>')), True,
          "parseVisual/parseCollision: the name is optional"),
    # --- elements urdfdom never reads (model.cpp reads material, link and joint only) ---
    Quirk("unknown elements", lambda m: (m.links["l1"].append('<sensor_mount frame="x"/>'), m.after.append('<sensor name="cam" update_rate="30"><camera/></sensor>'), m.after.append('<drake_ignore_me/>')), True,
          "parseURDF iterates <material>, <link> and <joint> children only"),
    Quirk("gazebo blocks", lambda m: m.after.extend(['<gazebo reference="l1"><material>Gazebo/Orange</material><mu1>0.2</mu1></gazebo>', '<gazebo><plugin name="ros_control" filename="libgazebo_ros_control.so"><robotNamespace>/</robotNamespace></plugin></gazebo>']), True,
          "parseURDF never reads <gazebo>"),
    Quirk("transmissions", lambda m: m.after.extend([_transmission(f"t{j}", f'{SIMPLE}<joint name="{j}">{EFFORT}</joint><actuator name="m{j}">{EFFORT}<mechanicalReduction>50</mechanicalReduction></actuator>') for j in ("j1", "j2", "j5")]), True,
          "parseURDF never reads <transmission>"),
    Quirk("transmissions Drake cannot read", lambda m: m.after.extend([_transmission("t_empty_type", '<type/><joint name="j1"/><actuator name="a1"/>'), _transmission("t_ghost", f'{SIMPLE}<joint name="ghost">{EFFORT}</joint><actuator name="a2"/>'), _transmission("t_no_actuator", f'{SIMPLE}<joint name="j2"/>'), _transmission("t_dup1", f'{SIMPLE}<joint name="j3"/><actuator name="same"/>'), _transmission("t_dup2", f'{SIMPLE}<joint name="j4"/><actuator name="same"/>')]), True,
          "parseURDF never reads <transmission> (Drake refuses these, and crashes on <type/>)"),
    # --- joints (joint.cpp parseJoint and its parts) ---
    Quirk("safety controller and calibration", lambda m: m.joints["j1"].extend(['<safety_controller soft_lower_limit="-1.4" soft_upper_limit="1.4" k_position="100" k_velocity="10"/>', '<calibration rising="0.1" falling="0.2"/>']), True,
          "parseJointSafety needs k_velocity only; parseJointCalibration reads what is there"),
    Quirk("dynamics", lambda m: m.joints["j2"].append('<dynamics damping="0.7" friction="0.1"/>'), True, "parseJointDynamics"),
    Quirk("mimic joint", lambda m: m.joints["j2"].append('<mimic joint="j1" multiplier="-1" offset="0.1"/>'), True, "parseJointMimic needs the joint attribute"),
    Quirk("mimic of a missing joint", lambda m: m.joints["j2"].append('<mimic joint="nowhere"/>'), True, "parseJointMimic does not look the joint up"),
    Quirk("mimic of itself", lambda m: m.joints["j4"].append('<mimic joint="j4"/>'), True, "parseJointMimic does not look the joint up"),
    Quirk("fixed joint mimics a revolute one", lambda m: m.joints["j5"].append('<mimic joint="j1"/>'), True, "parseJointMimic does not look the joint up"),
    Quirk("reversed limits", lambda m: m.limit("j1", '<limit lower="1" upper="-1" effort="10" velocity="1"/>'), True, "parseJointLimits reads four doubles"),
    Quirk("negative velocity and effort", lambda m: m.limit("j4", '<limit lower="0" upper="0.2" effort="-10" velocity="-1"/>'), True, "parseJointLimits reads four doubles"),
    Quirk("continuous joint with reversed limits", lambda m: m.limit("j3", '<limit lower="3" upper="-3" effort="5" velocity="2"/>'), True,
          "parseJointLimits; a continuous joint's bounds are never used"),
    Quirk("floating and planar joints", lambda m: (m.kinds.__setitem__("j5", "floating"), m.kinds.__setitem__("j3", "planar")), True, "parseJoint: known types"),
    Quirk("mimic without joint", lambda m: m.joints["j2"].insert(0, '<mimic multiplier="2"/>'), False, "parseJointMimic: 'joint mimic: no mimic joint specified'"),
    Quirk("safety controller without k_velocity", lambda m: m.joints["j1"].insert(0, '<safety_controller k_position="1"/>'), False, "parseJointSafety: 'joint safety: no k_velocity'"),
    Quirk("dynamics without numbers", lambda m: m.joints["j2"].insert(0, "<dynamics/>"), False, "parseJointDynamics: 'no damping and no friction'"),
]
# fmt: on
ACCEPTED = [quirk for quirk in QUIRKS if quirk.ros_accepts]
REFUSED = [quirk for quirk in QUIRKS if not quirk.ros_accepts]


def variant(seed: int) -> tuple[str, list[Quirk]]:
    """A model with 2 to 5 quirks, one of urdfdom's refusals in about a fifth of them."""
    rng = np.random.default_rng(seed)
    count = int(rng.integers(2, 6))
    chosen = [ACCEPTED[int(i)] for i in rng.choice(len(ACCEPTED), size=count, replace=False)]
    if rng.random() < 0.2:
        chosen.append(REFUSED[int(rng.integers(len(REFUSED)))])
    model = Model.base()
    for quirk in chosen:
        quirk.apply(model)
    return model.text(), chosen


# --- running both sides ------------------------------------------------------------------


def _write_meshes(folder: Path) -> None:
    """A tetrahedron as OBJ and as ASCII STL, the formats real descriptions use."""
    corners = [(0, 0, 0), (0.05, 0, 0), (0, 0.05, 0), (0, 0, 0.05)]
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    obj = [f"v {x} {y} {z}" for x, y, z in corners] + [
        f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces
    ]
    (folder / "part.obj").write_text("\n".join(obj) + "\n")
    stl = ["solid part"]
    for face in faces:
        stl += ["facet normal 0 0 0", "outer loop"]
        stl += [f"vertex {x} {y} {z}" for x, y, z in (corners[i] for i in face)]
        stl += ["endloop", "endfacet"]
    (folder / "part.stl").write_text("\n".join(stl + ["endsolid part"]) + "\n")


def compare(tools: Tools, path: Path, tmp_path: Path) -> tuple[bool, dict]:
    """Run both; assert what must match; returns (check_urdf accepted, workbench's JSON report)."""
    env = {"PATH": str(tmp_path / "no-programs"), "LC_ALL": "C"}
    ros = subprocess.run(
        [tools.check_urdf, str(path)], capture_output=True, text=True, env=env, timeout=60
    )
    ros_stderr = [line for line in ros.stderr.splitlines() if not line.startswith("         at ")]
    ros_ok = ros.returncode == 0 and not any(line.startswith("Error:") for line in ros_stderr)
    status, stdout, stderr = run_cli("check", "--json", str(path))
    assert "Traceback" not in stdout + stderr
    report = json.loads(stdout)
    # The same tree and the same log lines as check_urdf (see test_urdfdom_differential.py).
    assert "\n".join(report["tree"]) == ros.stdout.removesuffix("\n")
    assert report["urdfdom"] == ros_stderr
    errors = [f for f in report["findings"] if f["severity"] == "error"]
    if ros_ok:
        assert status == 0 and not errors and report["loaded"], errors
        ros_gv = tmp_path / "ros"
        subprocess.run(
            [tools.urdf_to_graphviz, str(path), str(ros_gv)],
            capture_output=True,
            env=env,
            timeout=60,
        )
        graph_status, _, graph_error = run_cli("graph", str(path), "-o", str(tmp_path / "wb.gv"))
        assert graph_status == 0, graph_error
        assert (tmp_path / "wb.gv").read_text() == Path(f"{ros_gv}.gv").read_text()
    else:
        assert status == 1 and errors
    return ros_ok, report


@pytest.mark.parametrize("quirk", QUIRKS, ids=[quirk.name for quirk in QUIRKS])
def test_each_quirk_alone(ros_tools, tmp_path, quirk):
    _write_meshes(tmp_path)
    model = Model.base()
    quirk.apply(model)
    path = tmp_path / "quirky.urdf"
    path.write_text(model.text())
    ros_ok, _ = compare(ros_tools, path, tmp_path)
    assert ros_ok == quirk.ros_accepts, f"check_urdf no longer decides as cited: {quirk.source}"


@pytest.mark.parametrize("seed", range(SEEDS))
def test_random_variants(ros_tools, tmp_path, seed):
    _write_meshes(tmp_path)
    text, chosen = variant(seed)
    path = tmp_path / "quirky.urdf"
    path.write_text(text)
    ros_ok, _ = compare(ros_tools, path, tmp_path)
    assert ros_ok == all(quirk.ros_accepts for quirk in chosen), [q.name for q in chosen]


def test_the_variants_have_both_outcomes():
    outcomes = {all(q.ros_accepts for q in variant(seed)[1]) for seed in range(SEEDS)}
    assert outcomes == {True, False}


# --- what urdfdom reads but nothing after it in ROS can use ---------------------------

#: (name, change, why ROS cannot show it either, the element workbench's error is about)
BROKEN_DOWNSTREAM = [
    (
        "zero axis",
        lambda m: m.joints["j1"].__setitem__(3, '<axis xyz="0 0 0"/>'),
        "kdl_parser divides the axis by its norm: robot_state_publisher sends NaN poses",
        "joint 'j1'",
    ),
    (
        "link with two parents",
        lambda m: (
            m.joints.__setitem__("again", ['<parent link="base"/>', '<child link="l2"/>']),
            m.kinds.__setitem__("again", "fixed"),
        ),
        "KDL's tree takes a segment once: robot_state_publisher cannot build the tree",
        "joint 'again'",
    ),
    (
        "missing mesh file",
        lambda m: m.visual("l1", '<mesh filename="no_such_part.stl"/>'),
        "RViz cannot load the mesh and shows the link as an error",
        "link 'l1'",
    ),
]


@pytest.mark.parametrize(
    ("name", "change", "why", "element"),
    BROKEN_DOWNSTREAM,
    ids=[case[0] for case in BROKEN_DOWNSTREAM],
)
def test_accepted_by_urdfdom_but_broken_downstream(ros_tools, tmp_path, name, change, why, element):
    """The deliberate differences: check_urdf passes these, workbench gives one error."""
    model = Model.base()
    change(model)
    path = tmp_path / "quirky.urdf"
    path.write_text(model.text())
    ros = subprocess.run([ros_tools.check_urdf, str(path)], capture_output=True, timeout=60)
    assert ros.returncode == 0 and b"Error" not in ros.stderr, why
    status, stdout, _ = run_cli("check", "--json", str(path))
    errors = [f for f in json.loads(stdout)["findings"] if f["severity"] == "error"]
    assert status == 1 and [f["element"] for f in errors] == [element], errors


def test_drake_warnings_keep_the_files_lines(tmp_path):
    """Drake reads the rewritten robot; its lines must stay the file's (a removed
    multi-line material, a dropped transmission) and name the element there, also a
    tag whose attributes span two lines (lxml counts its last line, Drake its first)."""
    path = tmp_path / "lines.urdf"
    path.write_text(
        '<?xml version="1.0"?>\n<robot name="lines">\n'
        '  <material name="">\n    <color rgba="0.5 0.5 0.5 1"/>\n  </material>\n'
        '  <transmission name="t">\n    <type/>\n  </transmission>\n'
        f'  <link name="a">\n    {INERTIAL}\n  </link>\n'
        f'  <link name="b">\n    {INERTIAL}\n  </link>\n'
        '  <joint name="j" type="continuous">\n    <parent link="a"/><child link="b"/>\n'
        '    <dynamics damping="0.1"\n              friction="0.2"/>\n  </joint>\n</robot>\n'
    )
    status, stdout, _ = run_cli("check", "--json", str(path))
    report = json.loads(stdout)
    friction = [f for f in report["findings"] if "friction" in f["message"]]
    assert status == 0 and report["loaded"]
    assert [(f["element"], f["line"]) for f in friction] == [("joint 'j'", 17)]
