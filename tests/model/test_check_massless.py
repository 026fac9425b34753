"""A massless link welded to its parent (a tool frame, the Panda's panda_hand_tcp) is not an
error: ROS's tools and Drake accept it; on a movable joint of its own it is."""

from __future__ import annotations

from workbench.model import check_robot

ARM = """<robot name="massless">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="tool"><inertial><mass value="0"/>
    <inertia ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="swing" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="tip" type="{tip}"><parent link="arm"/><child link="tool"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"""


def _codes(tmp_path, tip: str) -> set[str]:
    path = tmp_path / f"{tip}.urdf"
    path.write_text(ARM.format(tip=tip))
    return {f.code for f in check_robot(path, load=False).findings}


def test_a_massless_link_on_a_fixed_joint_is_fine(tmp_path):
    assert not {"non-positive-mass", "zero-inertia"} & _codes(tmp_path, "fixed")


def test_a_massless_link_on_a_movable_joint_is_an_error(tmp_path):
    assert "non-positive-mass" in _codes(tmp_path, "revolute")
