"""``libgazebo_ros_bumper.so``: a ``contact`` sensor's contacts as ``gazebo_msgs/ContactsState``.

As gazebo_plugins' gazebo_ros_bumper.cpp (noetic-devel) and Gazebo 11's contact sensor::

    <gazebo reference="base_bellow_link">
      <sensor name="base_contact_sensor" type="contact">
        <update_rate>100.0</update_rate>
        <contact><collision>base_bellow_link_collision</collision></contact>
        <plugin name="base_gazebo_ros_bumper_controller" filename="libgazebo_ros_bumper.so">
          <bumperTopicName>base_bumper</bumperTopicName>   <!-- default bumper_states -->
          <frameName>world</frameName>                     <!-- header.frame_id, default world -->
        </plugin>
      </sensor>
    </gazebo>

At the sensor's ``<update_rate>``, while the topic has subscribers, the plugin publishes
one ``ContactState`` per pair of touching collisions (``collision1_name`` the sensor's,
``collision2_name`` the other one's, both ``model::link::collision``) with, per contact
point, the wrench on the sensor's link (force, and torque about the link's centre of
mass, both in the link's frame, as Gazebo's contact feedback is), the position and the
normal (in the world frame, pointing from the other collision into the sensor's), the
penetration depth, and their sum in ``total_wrench``, stamped with simulated time. The
contacts are those of the physics step at the update (Gazebo gathers every step's
since the last update). A ``<collision>`` name is a collision of the sensor's link by
its own name, or by Gazebo's names for a URDF link's collisions (``<link>_collision``,
``<link>_collision_N``, ``..._fixed_joint_lump__<link>_collision``); one that matches
nothing is one error line listing the link's collisions. Names are relative to
``<robotNamespace>`` (none: global).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.sim.plugins import PluginSetupError, SdfElement, UpdateInfo
from workbench.sim.sensors.base import RosSensorPlugin, parameter
from workbench.sim.sensors.messages import resolve_topic, tf_frame
from workbench.sim.sensors.spec import CONTACT_TYPES, ContactSpec

GROUND_COLLISION = "ground_plane::link::collision"


class GazeboRosBumper(RosSensorPlugin):
    """Publishes the contacts of a ``contact`` sensor's collisions."""

    sensor_types = CONTACT_TYPES
    label = "bumper"
    publisher: Any = None

    def setup(self, sdf: SdfElement) -> None:
        assert isinstance(self.spec, ContactSpec)
        namespace = parameter(sdf, "robotNamespace", "")
        self.topic = resolve_topic(namespace, parameter(sdf, "bumperTopicName", "bumper_states"))
        self.frame = tf_frame(parameter(sdf, "frameName", "world"))
        self.geometries = self._geometries(self.spec)
        #: The last ContactsState message, or None.
        self.latest_message: Any = None
        self.publisher = None
        if self.node is not None:
            self.publisher = self.node.create_publisher(
                self.topic, "gazebo_msgs/ContactsState", queue_size=1
            )

    def _geometries(self, spec: ContactSpec) -> dict[Any, str]:
        """Geometry id -> Gazebo's scoped collision name, for every ``<collision>`` listed."""
        world = self.world
        model, link = self.model.name, spec.link
        inspector = world.scene_graph.model_inspector()
        plant = world.plant
        from pydrake.geometry import Role

        by_link: dict[str, list[tuple[Any, str]]] = {}
        for geometry in inspector.GetAllGeometryIds(Role.kProximity):
            body = plant.GetBodyFromFrameId(inspector.GetFrameId(geometry))
            if body is None or plant.GetModelInstanceName(body.model_instance()) != model:
                continue
            local = inspector.GetName(geometry).removeprefix(f"{model}::")
            by_link.setdefault(body.name(), []).append((geometry, local))
        found: dict[Any, str] = {}
        for name in spec.collisions:
            owner = link
            if "_fixed_joint_lump__" in name:
                owner = name.split("_fixed_joint_lump__", 1)[1].rsplit("_collision", 1)[0]
            candidates = by_link.get(owner, [])
            exact = [(g, local) for g, local in candidates if local == name]
            urdf_style = name.startswith(f"{owner}_collision") or "_fixed_joint_lump__" in name
            matched = exact or (candidates if urdf_style else [])
            if not matched:
                names = ", ".join(local for _, local in by_link.get(link, [])) or "none"
                raise PluginSetupError(
                    f"model '{model}', link '{link}', sensor '{spec.name}': <contact><collision> "
                    f"'{name}' is not a collision of the link (its collisions: {names})"
                )
            for geometry, _ in matched:
                found[geometry] = f"{model}::{link}::{name}"
        return found

    def active(self) -> bool:
        return self.publisher is None or self.listeners(self.publisher) > 0

    def update(self, info: UpdateInfo) -> None:
        from workbench.msgs.gazebo_msgs import ContactsState

        message = ContactsState(states=self.contacts(info.sim_time))
        message.header.frame_id = self.frame
        from workbench.sim.gazebo_ros_plugins.ros_context import ros_stamp

        message.header.stamp = ros_stamp(info.sim_time)
        self.latest_message = message
        if self.publisher is not None:
            self.publisher.publish(message)

    def contacts(self, seconds: float) -> list[Any]:
        """The ContactState of each touching pair now (see the module docstring)."""
        from workbench.msgs.gazebo_msgs import ContactState
        from workbench.msgs.geometry_msgs import Vector3, Wrench

        world = self.world
        plant = world.plant
        context = plant.GetMyContextFromRoot(world.context)
        results = plant.get_contact_results_output_port().Eval(context)
        inspector = world.scene_graph.model_inspector()
        pairs: dict[tuple[str, str], list[tuple[Any, ...]]] = {}
        body = world.body(f"{self.model.name}::{self.spec.link}")
        X_WL = plant.EvalBodyPoseInWorld(context, body)
        R_LW = X_WL.rotation().inverse()
        p_WCm = X_WL.multiply(body.CalcCenterOfMassInBodyFrame(context))
        for i in range(results.num_point_pair_contacts()):
            contact = results.point_pair_contact_info(i)
            pair = contact.point_pair()
            for mine, other, sign in ((pair.id_A, pair.id_B, -1.0), (pair.id_B, pair.id_A, 1.0)):
                if mine not in self.geometries:
                    continue
                force = sign * np.asarray(contact.contact_force())  # on the sensor's body, W
                point = np.asarray(contact.contact_point())
                normal = -sign * np.asarray(pair.nhat_BA_W)  # from the other into the sensor's
                torque = np.cross(point - np.asarray(p_WCm), force)
                key = (self.geometries[mine], _scoped(world, inspector, other))
                pairs.setdefault(key, []).append(
                    (R_LW.multiply(force), R_LW.multiply(torque), point, normal, float(pair.depth))
                )
        states = []
        total_count = len(pairs)
        for index, ((mine, other), points) in enumerate(pairs.items()):
            state = ContactState(collision1_name=mine, collision2_name=other)
            state.info = (
                f"Debug:  i:({index}/{total_count})     my geom:{mine}   other geom:{other}"
                f"         time:{seconds:.9f}\n"
            )
            total = np.zeros(6)
            wrenches, positions, normals, depths = [], [], [], []
            for force, torque, point, normal, depth in points:
                wrenches.append(Wrench(force=Vector3(*force), torque=Vector3(*torque)))
                positions.append(Vector3(*point))
                normals.append(Vector3(*normal))
                depths.append(depth)
                total += np.concatenate([force, torque])
            state.wrenches, state.contact_positions = wrenches, positions
            state.contact_normals, state.depths = normals, depths
            state.total_wrench = Wrench(force=Vector3(*total[:3]), torque=Vector3(*total[3:]))
            states.append(state)
        return states

    def close(self) -> None:
        if self.publisher is not None:
            self.publisher.unregister()
            self.publisher = None


def _scoped(world: Any, inspector: Any, geometry: Any) -> str:
    """Gazebo's ``model::link::collision`` name of any geometry of the world."""
    plant = world.plant
    body = plant.GetBodyFromFrameId(inspector.GetFrameId(geometry))
    name = inspector.GetName(geometry)
    if body is None or body.index() == plant.world_body().index():
        return GROUND_COLLISION if name == "ground_plane" else f"{name}::link::collision"
    model = plant.GetModelInstanceName(body.model_instance())
    return f"{model}::{body.name()}::{name.removeprefix(model + '::')}"
