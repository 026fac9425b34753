"""libgazebo_ros_imu.so, libgazebo_ros_p3d.so, libgazebo_ros_ft_sensor.so and libgazebo_ros_bumper.so.

The model blocks are written in the shapes the real robots use them (turtlebot3's
``turtlebot3_burger.gazebo.xacro`` IMU block with its ``<imu><noise>``; PR2's p3d and
bumper blocks in ``base.gazebo.xacro``; prbt's ft_sensor blocks in ``prbt_macro.xacro``).
What is matched (gazebo_plugins noetic-devel): gazebo_ros_imu's frames (orientation
q_WL, rates and accelerations turned by ``q.RotateVector``) and its gravity convention
(the link's own acceleration: 0 at rest, -g in free fall), its topic and service under
the global namespace, ``frameName`` defaulting to ``bodyName``; p3d's world and link
reference frames, offsets and child frame; ft_sensor's wrench on the child link in the
child frame; the bumper's ContactState names, normals and wrench frame.
"""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest

from workbench.bus import Bus, Node
from workbench.paths import urdf_dir
from workbench.sim import World
from workbench.sim.gazebo_ros_plugins.robot_namespace import with_robot_namespace
from workbench.sim.loading import sim_model_from_xml
from workbench.sim.server import SERVER_PHYSICS, SimServer

IMU_BLOCK = """
  <gazebo>
    <plugin name="imu_plugin" filename="libgazebo_ros_imu.so">
      <alwaysOn>true</alwaysOn>
      <bodyName>imu_link</bodyName>
      <frameName>imu_link</frameName>
      <topicName>imu</topicName>
      <serviceName>imu_service</serviceName>
      <gaussianNoise>0.0</gaussianNoise>
      <updateRate>{rate}</updateRate>
      <imu>
        <noise>
          <type>gaussian</type>
          <rate><mean>0.0</mean><stddev>2e-4</stddev></rate>
          <accel><mean>0.0</mean><stddev>1.7e-2</stddev></accel>
        </noise>
      </imu>
    </plugin>
  </gazebo>
"""


def burger_with_model_imu(rate: float = 0) -> str:
    """The shipped Burger with ROBOTIS's IMU block (the model plugin) instead of the sensor."""
    text = (urdf_dir() / "turtlebot3_burger.urdf").read_text(encoding="utf-8")
    start = text.index('  <gazebo reference="imu_link">')
    end = text.index("</gazebo>", start) + len("</gazebo>")
    return text[:start] + IMU_BLOCK.format(rate=rate) + text[end:]


def probe(plugin: str, *, static: bool = False) -> str:
    """A 2 kg box ``base_link`` with a child ``imu_link`` rolled 90 degrees, and ``plugin``."""
    return f"""<robot name="probe">
  <link name="base_link">
    <inertial><mass value="2"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <joint name="imu_joint" type="fixed"><parent link="base_link"/><child link="imu_link"/>
    <origin xyz="0 0 0.05" rpy="1.5707963267948966 0 0"/></joint>
  <link name="imu_link"/>
  {"<gazebo><static>true</static></gazebo>" if static else ""}
  <gazebo>{plugin}</gazebo>
</robot>"""


class Rig:
    def __init__(self, urdf: str, pose=(0.0, 0.0, 0.1), *, gravity: float = 9.81, name="probe"):
        self.bus = Bus()
        self.world = World(**{**SERVER_PHYSICS, "gravity": gravity})
        self.server = SimServer(self.world, bus=self.bus, real_time_factor=0)
        model = with_robot_namespace(
            sim_model_from_xml(urdf, name=name, source=f"{name}.urdf"), "/"
        )
        self.server.spawn(model, list(pose))
        self.node = Node("tester", bus=self.bus)

    def record(self, topic: str, kind: str) -> list:
        log: list = []
        self.node.create_subscription(topic, kind, log.append, inline=True)
        return log

    def run(self, seconds: float) -> None:
        self.server.run(until=self.world.time + seconds)

    def close(self) -> None:
        self.server.stop()
        self.bus.shutdown()


def _vec(v) -> np.ndarray:
    return np.array([v.x, v.y, v.z])


# --- libgazebo_ros_imu.so ------------------------------------------------------------------


def test_turtlebot3_imu_block_publishes_imu_at_rest_without_gravity():
    rig = Rig(burger_with_model_imu(), pose=(0.0, 0.0, 0.0), name="turtlebot3_burger")
    try:
        messages = rig.record("/imu", "sensor_msgs/Imu")
        rig.run(0.5)
        assert messages and messages[-1].header.frame_id == "imu_link"
        last = messages[-1]
        assert np.abs(_vec(last.linear_acceleration)).max() < 0.05  # no gravity in it
        assert abs(last.orientation.w) == pytest.approx(1.0, abs=1e-3)
        stamps = [m.header.stamp.to_sec() for m in messages[-20:]]
        assert np.diff(stamps) == pytest.approx(0.001, abs=1e-9)  # updateRate 0: every step
        from workbench.msgs.std_srvs import Empty

        client = rig.node.create_client("/imu_service", Empty)
        client.wait_for_service(timeout=10)
        client.call(Empty.Request(), timeout=10)
    finally:
        rig.close()


def test_in_free_fall_it_reads_minus_g_and_rates_are_turned_by_the_orientation():
    plugin = """<plugin name="imu_plugin" filename="libgazebo_ros_imu.so">
        <bodyName>imu_link</bodyName><topicName>imu</topicName><updateRate>100</updateRate></plugin>"""
    rig = Rig(probe(plugin), pose=(0.0, 0.0, 20.0))
    try:
        messages = rig.record("/imu", "sensor_msgs/Imu")
        rig.run(0.3)
        assert messages[-1].header.frame_id == "imu_link"  # frameName defaults to bodyName
        # turned by q (roll 90 degrees): world -z reads as +y
        assert _vec(messages[-1].linear_acceleration) == pytest.approx([0, 9.81, 0], abs=0.05)
        stamps = [m.header.stamp.to_sec() for m in messages]
        assert np.diff(stamps)[-5:] == pytest.approx(0.01, abs=1e-9)
    finally:
        rig.close()
    spinner = Rig(probe(plugin), pose=(0.0, 0.0, 1.0), gravity=0.0)
    try:
        messages = spinner.record("/imu", "sensor_msgs/Imu")
        spinner.world.set_model_state("probe", [0, 0, 1], [0, 0, 0], [0, 0, 2.0])
        spinner.run(0.05)
        last = messages[-1]
        q = last.orientation
        from scipy.spatial.transform import Rotation

        R = Rotation.from_quat([q.x, q.y, q.z, q.w]).as_matrix()
        # gazebo_ros_imu turns the world rate by q, not by q^-1 (about (0, -2, 0) here)
        assert _vec(last.angular_velocity) == pytest.approx(R @ [0, 0, 2.0], abs=1e-3)
        assert _vec(last.angular_velocity) != pytest.approx(R.T @ [0, 0, 2.0], abs=0.5)
    finally:
        spinner.close()


def test_nobody_listening_means_no_work_and_bad_blocks_are_one_line(caplog):
    rig = Rig(burger_with_model_imu(), pose=(0.0, 0.0, 0.0), name="turtlebot3_burger")
    try:
        rig.run(0.05)
        imu = next(p for p in rig.server.plugins if type(p).__name__ == "GazeboRosImu")
        assert imu.latest_message is None
    finally:
        rig.close()
    for plugin, expected in (
        (
            '<plugin name="imu" filename="libgazebo_ros_imu.so"><topicName>imu</topicName></plugin>',
            "needs <bodyName>",
        ),
        (
            '<plugin name="imu" filename="libgazebo_ros_imu.so"><bodyName>nose</bodyName></plugin>',
            "'nose' is not a link",
        ),
    ):
        caplog.clear()
        with caplog.at_level(logging.ERROR, logger="workbench.sim"):
            Rig(probe(plugin)).close()
        lines = [r.getMessage() for r in caplog.records if expected in r.getMessage()]
        assert len(lines) == 1 and "model 'probe'" in lines[0]


# --- libgazebo_ros_p3d.so -------------------------------------------------------------------


def test_p3d_reports_the_true_pose_and_velocity_in_the_world_and_relative_to_a_link(caplog):
    plugin = """<plugin name="p3d_base_controller" filename="libgazebo_ros_p3d.so">
        <alwaysOn>true</alwaysOn><updateRate>100.0</updateRate><bodyName>base_link</bodyName>
        <topicName>base_pose_ground_truth</topicName><gaussianNoise>0.01</gaussianNoise>
        <frameName>map</frameName><xyzOffsets>0 0 0</xyzOffsets><rpyOffsets>0 0 0</rpyOffsets>
      </plugin>
      <plugin name="p3d_imu" filename="libgazebo_ros_p3d.so">
        <bodyName>imu_link</bodyName><topicName>imu_in_base</topicName><frameName>base_link</frameName>
        <xyzOffset>1 0 0</xyzOffset>
      </plugin>"""
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        rig = Rig(probe(plugin), pose=(1.0, 2.0, 1.0), gravity=0.0)
    try:
        assert "<xyzOffsets> is not read by gazebo_ros_p3d" in caplog.text
        truth = rig.record("/base_pose_ground_truth", "nav_msgs/Odometry")
        relative = rig.record("/imu_in_base", "nav_msgs/Odometry")
        rig.world.set_model_state("probe", [1, 2, 1], [0.5, 0, 0], [0, 0, 0])
        rig.run(0.2)
        last = truth[-1]
        assert (last.header.frame_id, last.child_frame_id) == ("map", "base_link")
        position = last.pose.pose.position
        moved = 0.5 * last.header.stamp.to_sec()  # at 0.5 m/s since t = 0, no gravity
        # within one 1 ms step of motion
        assert [position.x, position.y, position.z] == pytest.approx([1 + moved, 2, 1], abs=1e-3)
        assert last.twist.twist.linear.x == pytest.approx(0.5, abs=0.05)  # noise 0.01
        assert last.twist.covariance[0] == pytest.approx(1e-4)
        inside = relative[-1]
        assert inside.header.frame_id == "base_link"
        p = inside.pose.pose.position
        assert [p.x, p.y, p.z] == pytest.approx([1.0, 0.0, 0.05], abs=1e-9)  # + xyzOffset
        q = inside.pose.pose.orientation
        assert abs(q.x) == pytest.approx(math.sin(math.pi / 4), abs=1e-9)
    finally:
        rig.close()


# --- libgazebo_ros_ft_sensor.so ---------------------------------------------------------------

CANTILEVER = """<robot name="post">
  <link name="base_link"><inertial><mass value="5"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="joint_1" type="fixed"><parent link="base_link"/><child link="link_1"/><origin xyz="0 0 1"/></joint>
  <link name="link_1"><inertial><origin xyz="0.3 0 0"/><mass value="2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <gazebo><static>true</static></gazebo>
  <gazebo reference="joint_1"><provideFeedback>true</provideFeedback></gazebo>
  <gazebo>
    <plugin name="ft_sensor" filename="libgazebo_ros_ft_sensor.so">
      <updateRate>100.0</updateRate>
      <topicName>prbt/ft_sensor/joint_1</topicName>
      <jointName>joint_1</jointName>
    </plugin>
  </gazebo>
</robot>"""


def test_ft_sensor_gives_the_joints_wrench_on_its_child_in_the_child_frame():
    rig = Rig(CANTILEVER, pose=(0.0, 0.0, 0.0), name="post")
    try:
        messages = rig.record("/prbt/ft_sensor/joint_1", "geometry_msgs/WrenchStamped")
        rig.run(0.1)
        last = messages[-1]
        assert last.header.frame_id == "link_1"
        # holds up 2 kg whose centre of mass is 0.3 m out along x
        assert _vec(last.wrench.force) == pytest.approx([0, 0, 2 * 9.81], abs=1e-6)
        assert _vec(last.wrench.torque) == pytest.approx([0, -0.3 * 2 * 9.81, 0], abs=1e-6)
        stamps = [m.header.stamp.to_sec() for m in messages]
        assert np.diff(stamps)[-3:] == pytest.approx(0.01, abs=1e-9)
    finally:
        rig.close()


# --- libgazebo_ros_bumper.so ------------------------------------------------------------------

CRATE = """<robot name="crate">
  <link name="base_bellow_link">
    <inertial><mass value="3"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <gazebo reference="base_bellow_link">
    <sensor type="contact" name="base_contact_sensor">
      <always_on>true</always_on>
      <update_rate>100.0</update_rate>
      <contact>
        <collision>{collision}</collision>
      </contact>
      <plugin name="base_gazebo_ros_bumper_controller" filename="libgazebo_ros_bumper.so">
        <alwaysOn>true</alwaysOn>
        <updateRate>100.0</updateRate>
        <bumperTopicName>base_bumper</bumperTopicName>
        <frameName>world</frameName>
      </plugin>
    </sensor>
  </gazebo>
</robot>"""


def test_bumper_reports_the_ground_contact_with_gazebos_names_and_frames():
    rig = Rig(CRATE.format(collision="base_bellow_link_collision"), name="crate")
    try:
        messages = rig.record("/base_bumper", "gazebo_msgs/ContactsState")
        rig.run(0.5)
        last = messages[-1]
        assert last.header.frame_id == "world"
        [state] = last.states
        assert state.collision1_name == "crate::base_bellow_link::base_bellow_link_collision"
        assert state.collision2_name == "ground_plane::link::collision"
        assert _vec(state.total_wrench.force) == pytest.approx([0, 0, 3 * 9.81], abs=0.05)
        assert all(_vec(n) == pytest.approx([0, 0, 1]) for n in state.contact_normals)
        assert len(state.depths) == len(state.wrenches) == len(state.contact_positions) > 0
    finally:
        rig.close()


def test_a_bumper_collision_that_is_not_on_the_link_is_one_line(caplog):
    with caplog.at_level(logging.ERROR, logger="workbench.sim"):
        Rig(CRATE.format(collision="front_bumper_collision"), name="crate").close()
    lines = [r.getMessage() for r in caplog.records if "front_bumper_collision" in r.getMessage()]
    assert len(lines) == 1 and "sensor 'base_contact_sensor'" in lines[0]


def test_plugins_not_provided_are_one_warning_naming_plugin_and_model(caplog):
    plugin = (
        '<plugin name="f3d" filename="libgazebo_ros_f3d.so"><bodyName>base_link</bodyName></plugin>'
    )
    with caplog.at_level(logging.WARNING, logger="workbench.sim"):
        Rig(probe(plugin)).close()
    lines = [r.getMessage() for r in caplog.records if "libgazebo_ros_f3d.so" in r.getMessage()]
    assert len(lines) == 1 and "model 'probe'" in lines[0] and "not provided" in lines[0]
