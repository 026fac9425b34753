"""The ``gazebo_ros`` API of a :class:`SimServer` on the bus (the node ``/gazebo``).

Services (``gazebo_msgs``/``std_srvs`` types, ROS 1 Noetic md5sums):
``spawn_urdf_model``, ``spawn_sdf_model``, ``delete_model``, ``get_model_state``,
``set_model_state``, ``set_model_configuration``, ``get_world_properties``, ``get_model_properties``,
``apply_body_wrench``, ``apply_joint_effort``, ``clear_body_wrenches``,
``clear_joint_forces``, ``pause_physics``, ``unpause_physics``,
``reset_simulation``, ``reset_world``, all under ``/gazebo/``. Topics:
``/clock`` (100 Hz of simulated time, as gazebo_ros's ``pub_clock_frequency``),
``/gazebo/model_states`` and ``/gazebo/link_states`` (while somebody subscribes,
at ``state_rate`` Hz of simulated time; Gazebo sends them every physics step),
and ``/gazebo/set_model_state`` (subscribed). Status messages are Gazebo's own.
``/use_sim_time`` is set to true, as gazebo_ros does.
"""

from __future__ import annotations

import functools
import logging
import time
from typing import Any

import numpy as np

from workbench.errors import SimulationError, WorkbenchError
from workbench.sim.request_limits import (
    MAX_ANGULAR_SPEED,
    MAX_EFFORT,
    MAX_FORCE,
    MAX_JOINT_POSITION,
    MAX_LINEAR_SPEED,
    MAX_POSITION,
    MAX_QUATERNION,
    MAX_TORQUE,
    out_of_bounds,
    xyz,
)
from workbench.sim.server import SimServer

_LOG = logging.getLogger("workbench.sim")
_WORLD_FRAMES = ("", "world", "map", "/map")


class GazeboRosApi:
    """Serve a SimServer's world on ``node`` the way gazebo_ros_api_plugin does.

    Args:
        server: The simulation server.
        node: A ``workbench.bus.Node``, normally named ``gazebo``.
        clock_rate: ``/clock`` messages per second of simulated time.
        state_rate: Model and link state messages per second of simulated time.
    """

    def __init__(
        self, server: SimServer, node: Any, *, clock_rate: float = 100.0, state_rate: float = 100.0
    ) -> None:
        from workbench.msgs import gazebo_msgs as gm
        from workbench.msgs import std_srvs
        from workbench.msgs.rosgraph_msgs import Clock

        self.server = server
        self.node = node
        self.clock_period = 1.0 / clock_rate
        self.state_period = 1.0 / state_rate
        self._next_clock = 0.0
        self._next_states = 0.0
        self._last_time = -1.0
        self._clock_message = Clock
        self.clock = node.create_publisher("/clock", Clock, queue_size=10)
        self.model_states = node.create_publisher("/gazebo/model_states", gm.ModelStates, 1)
        self.link_states = node.create_publisher("/gazebo/link_states", gm.LinkStates, 1)
        self._subscriber_counts = (0, 0)
        self._count_checked = -1e9
        services = {
            "spawn_urdf_model": (gm.SpawnModel, self._spawn_urdf),
            "spawn_sdf_model": (gm.SpawnModel, self._spawn_sdf),
            "delete_model": (gm.DeleteModel, self._delete),
            "get_model_state": (gm.GetModelState, self._get_model_state),
            "set_model_state": (gm.SetModelState, self._set_model_state),
            "get_world_properties": (gm.GetWorldProperties, self._get_world_properties),
            "get_model_properties": (gm.GetModelProperties, self._get_model_properties),
            "set_model_configuration": (gm.SetModelConfiguration, self._set_configuration),
            "apply_body_wrench": (gm.ApplyBodyWrench, self._apply_body_wrench),
            "apply_joint_effort": (gm.ApplyJointEffort, self._apply_joint_effort),
            "clear_body_wrenches": (gm.BodyRequest, self._clear_body_wrenches),
            "clear_joint_forces": (gm.JointRequest, self._clear_joint_forces),
            "pause_physics": (std_srvs.Empty, self._pause),
            "unpause_physics": (std_srvs.Empty, self._unpause),
            "reset_simulation": (std_srvs.Empty, self._reset_simulation),
            "reset_world": (std_srvs.Empty, self._reset_world),
        }
        self.services = [
            node.create_service(f"/gazebo/{name}", kind, handler)
            for name, (kind, handler) in services.items()
        ]
        self.set_state_topic = node.create_subscription(
            "/gazebo/set_model_state", gm.ModelState, self._on_set_model_state
        )
        node.set_param("/use_sim_time", True)
        server.hooks.append(self.publish)

    # --- publishing (on the loop thread) ---------------------------------------------

    def publish(self, server: SimServer) -> None:
        """Publish ``/clock`` and, for subscribers, the model and link states when due."""
        t = server.world.time
        if t < self._last_time:  # reset_simulation went back in time
            self._next_clock = self._next_states = t
        self._last_time = t
        if t + 1e-12 >= self._next_clock:
            self.clock.publish(self._clock_message(clock=_stamp(t)))
            self._next_clock = t + self.clock_period
        if t + 1e-12 < self._next_states:
            return
        self._next_states = t + self.state_period
        now = time.monotonic()
        if now - self._count_checked >= 0.2:  # who listens, looked up 5 times a wall second
            self._subscriber_counts = (
                self.model_states.get_num_connections(),
                self.link_states.get_num_connections(),
            )
            self._count_checked = now
        models, links = self._subscriber_counts
        if models:
            self.model_states.publish(self.model_states_message())
        if links:
            self.link_states.publish(self.link_states_message())

    def model_states_message(self) -> Any:
        """``gazebo_msgs/ModelStates`` of every model now (ground included, as Gazebo)."""
        from workbench.msgs import gazebo_msgs as gm

        world = self.server.world
        names, poses, twists = [], [], []
        for name in world.model_names():
            names.append(name)
            if name == "ground_plane":
                poses.append(_pose(None))
                twists.append(_twist(np.zeros(3), np.zeros(3)))
                continue
            poses.append(_pose(world.get_model_pose(name)))
            twists.append(_twist(*world.get_model_twist(name)))
        return gm.ModelStates._from_wire(names, poses, twists)

    def link_states_message(self) -> Any:
        """``gazebo_msgs/LinkStates``: every link as ``model::link``."""
        from workbench.msgs import gazebo_msgs as gm

        names, poses, twists = [], [], []
        for name, X, V in self.server.world.link_states():
            names.append(name)
            poses.append(_pose(X))
            twists.append(_twist(V.translational(), V.rotational()))
        return gm.LinkStates._from_wire(names, poses, twists)

    # --- services --------------------------------------------------------------------

    def _spawn_urdf(self, request: Any) -> Any:
        from workbench.sim.loading import xml_format

        if xml_format(request.model_xml) != "urdf":
            return _spawn_reply(False, "SpawnModel: Failure - model format is not URDF.")
        return self._spawn(request)

    def _spawn_sdf(self, request: Any) -> Any:
        return self._spawn(request)

    def _spawn(self, request: Any) -> Any:
        from workbench.sim.bounds import spawn_request_problem
        from workbench.sim.gazebo_ros_plugins.robot_namespace import with_robot_namespace
        from workbench.sim.loading import sim_model_from_xml

        name = request.model_name
        problem = spawn_request_problem(name, request.robot_namespace, request.model_xml)
        if problem is not None:
            _LOG.error("SpawnModel: Failure - %s", problem)
            return _spawn_reply(False, f"SpawnModel: Failure - {problem}")
        world = self.server.world
        if name in world.model_names():
            _LOG.error("SpawnModel: Failure - model name %s already exist.", name)
            return _spawn_reply(False, "SpawnModel: Failure - model already exists.")
        try:
            X_WM = _transform(request.initial_pose, "initial_pose")
            if request.reference_frame not in _WORLD_FRAMES:
                X_WM = self._link_pose(request.reference_frame).multiply(X_WM)
            model = sim_model_from_xml(
                request.model_xml, name=name or None, source=f"spawn request '{name}'"
            )
            model = with_robot_namespace(model, request.robot_namespace)
            self.server.spawn(model, X_WM, from_bus=True)
        except _NoFrame:
            return _spawn_reply(
                False,
                "SpawnModel: reference reference_frame not found, did you forget to scope "
                "the link by model name?",
            )
        except WorkbenchError as error:
            _LOG.error("SpawnModel: %s", error)
            return _spawn_reply(False, f"SpawnModel: Failure - {error}")
        return _spawn_reply(True, "SpawnModel: Successfully spawned entity")

    def _delete(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import DeleteModel

        if request.model_name not in self._deletable():
            _LOG.error("DeleteModel: model [%s] does not exist", request.model_name)
            return DeleteModel.Response(
                success=False, status_message="DeleteModel: model does not exist"
            )
        self.server.delete(request.model_name)
        return DeleteModel.Response(
            success=True, status_message="DeleteModel: successfully deleted model"
        )

    def _deletable(self) -> list[str]:
        return [n for n in self.server.world.model_names() if n != "ground_plane"]

    def _get_model_state(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import GetModelState

        def work() -> Any:
            world = self.server.world
            reply = GetModelState.Response()
            if request.model_name not in world.model_names():
                _LOG.error("GetModelState: model [%s] does not exist", request.model_name)
                reply.success = False
                reply.status_message = "GetModelState: model does not exist"
                return reply
            if request.model_name == "ground_plane":
                X, v, w = None, np.zeros(3), np.zeros(3)
            else:
                X = world.get_model_pose(request.model_name)
                v, w = world.get_model_twist(request.model_name)
            if request.relative_entity_name not in _WORLD_FRAMES:
                try:
                    X_WF = self._link_pose(request.relative_entity_name)
                except _NoFrame:
                    reply.success = False
                    reply.status_message = (
                        "GetModelState: reference relative_entity_name not found, did you "
                        "forget to scope the body by model name?"
                    )
                    return reply
                X = X_WF.inverse().multiply(X if X is not None else _identity())
                R_FW = X_WF.rotation().inverse()
                v, w = R_FW.multiply(v), R_FW.multiply(w)
            reply.header.stamp = _stamp(world.time)
            reply.header.frame_id = request.relative_entity_name
            reply.pose = _pose(X)
            reply.twist = _twist(v, w)
            reply.success = True
            reply.status_message = "GetModelState: got properties"
            return reply

        return self.server.call(work)

    def _set_model_state(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import SetModelState

        success, message = self._apply_model_state(request.model_state)
        return SetModelState.Response(success=success, status_message=message)

    def _on_set_model_state(self, message: Any) -> None:
        success, status = self._apply_model_state(message)
        if not success:
            _LOG.error("Updating ModelState: %s", status)

    def _apply_model_state(self, state: Any) -> tuple[bool, str]:
        world = self.server.world
        if state.model_name not in self._deletable():
            _LOG.error("Updating ModelState: model [%s] does not exist", state.model_name)
            return False, "SetModelState: model does not exist"
        reason = out_of_bounds(
            xyz("twist.linear", state.twist.linear), MAX_LINEAR_SPEED, "m/s"
        ) or out_of_bounds(xyz("twist.angular", state.twist.angular), MAX_ANGULAR_SPEED, "rad/s")
        if reason is not None:
            _LOG.error("Updating ModelState: model [%s]: %s", state.model_name, reason)
            return False, f"SetModelState: {reason}"
        try:
            X = _transform(state.pose, "pose")
            v = _vector(state.twist.linear)
            w = _vector(state.twist.angular)
            if state.reference_frame not in _WORLD_FRAMES:
                X_WF = self._link_pose(state.reference_frame)
                R = X_WF.rotation()
                X = _place_relative(world.get_model_pose(state.model_name), X_WF, X)
                v, w = R.multiply(v), R.multiply(w)
            self.server.call(lambda: world.set_model_state(state.model_name, X, v, w))
        except _NoFrame:
            return False, "SetModelState: specified reference frame entity does not exist"
        except WorkbenchError as error:
            return False, f"SetModelState: {error}"
        return True, "SetModelState: set model state done"

    def _set_configuration(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import SetModelConfiguration

        name = request.model_name
        if name not in self._deletable():
            _LOG.error("SetModelConfiguration: model [%s] does not exist", name)
            return SetModelConfiguration.Response(
                success=False, status_message="SetModelConfiguration: model does not exist"
            )
        if len(request.joint_names) != len(request.joint_positions):
            return SetModelConfiguration.Response(
                success=False,
                status_message="SetModelConfiguration: joint name and position list have "
                "different lengths",
            )
        reason = out_of_bounds(
            (
                (f"position of joint '{name}'", value)
                for name, value in zip(request.joint_names, request.joint_positions, strict=True)
            ),
            MAX_JOINT_POSITION,
            "rad or m",
        )
        if reason is not None:
            return SetModelConfiguration.Response(
                success=False, status_message=f"SetModelConfiguration: {reason}"
            )
        positions = dict(zip(request.joint_names, request.joint_positions, strict=True))
        try:
            self.server.call(lambda: self.server.world.set_joint_positions(name, positions))
        except WorkbenchError as error:
            return SetModelConfiguration.Response(
                success=False, status_message=f"SetModelConfiguration: {error}"
            )
        return SetModelConfiguration.Response(
            success=True, status_message="SetModelConfiguration: success"
        )

    def _get_world_properties(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import GetWorldProperties

        world = self.server.world
        return GetWorldProperties.Response(
            sim_time=world.time,
            model_names=world.model_names(),
            rendering_enabled=True,
            success=True,
            status_message="GetWorldProperties: got properties",
        )

    def _get_model_properties(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import GetModelProperties

        def work() -> Any:
            world = self.server.world
            name = request.model_name
            if name not in world.model_names():
                _LOG.error("GetModelProperties: model [%s] does not exist", name)
                return GetModelProperties.Response(
                    success=False, status_message="GetModelProperties: model does not exist"
                )
            if name == "ground_plane":
                return GetModelProperties.Response(
                    canonical_body_name="link",
                    body_names=["link"],
                    geom_names=["collision"],
                    is_static=True,
                    success=True,
                    status_message="GetModelProperties: got properties",
                )
            from workbench.model.sdf_names import shown_name
            from workbench.sim.scene import joint_names

            plant = world.plant
            instance = world.model_instance(name)
            bodies = [plant.get_body(i) for i in plant.GetBodyIndices(instance)]
            inspector = world.scene_graph.model_inspector()
            geoms = [
                inspector.GetName(g) for b in bodies for g in plant.GetCollisionGeometriesForBody(b)
            ]
            return GetModelProperties.Response(
                canonical_body_name=shown_name(world.root_body(name).name()),
                body_names=[shown_name(b.name()) for b in bodies],
                geom_names=geoms,
                joint_names=joint_names(plant, instance),
                is_static=not world.root_body(name).is_floating_base_body(),
                success=True,
                status_message="GetModelProperties: got properties",
            )

        return self.server.call(work)

    def _apply_body_wrench(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import ApplyBodyWrench

        if not self._has_body(request.body_name):
            _LOG.error("ApplyBodyWrench: body [%s] does not exist", request.body_name)
            return ApplyBodyWrench.Response(
                success=False, status_message="ApplyBodyWrench: body does not exist"
            )
        reason = (
            out_of_bounds(xyz("wrench.force", request.wrench.force), MAX_FORCE, "N")
            or out_of_bounds(xyz("wrench.torque", request.wrench.torque), MAX_TORQUE, "N m")
            or out_of_bounds(xyz("reference_point", request.reference_point), MAX_POSITION, "m")
        )
        if reason is not None:
            _LOG.error("ApplyBodyWrench: body [%s]: %s", request.body_name, reason)
            return ApplyBodyWrench.Response(
                success=False, status_message=f"ApplyBodyWrench: {reason}"
            )
        force, torque = _vector(request.wrench.force), _vector(request.wrench.torque)
        try:
            if request.reference_frame not in _WORLD_FRAMES:
                R = self._link_pose(request.reference_frame).rotation()
                force, torque = R.multiply(force), R.multiply(torque)
            point = _vector(request.reference_point)
            if np.any(point):
                torque = torque + np.cross(self._body_rotation(request.body_name, point), force)
            self.server.apply_body_wrench(
                request.body_name,
                force,
                torque,
                _seconds(request.start_time),
                _seconds(request.duration),
            )
        except _NoFrame:
            return ApplyBodyWrench.Response(
                success=False,
                status_message="ApplyBodyWrench: reference_frame is not a valid entity name",
            )
        except WorkbenchError:
            return ApplyBodyWrench.Response(
                success=False,
                status_message="ApplyBodyWrench: body does not exist",
            )
        return ApplyBodyWrench.Response(success=True, status_message="")

    def _has_body(self, body_name: str) -> bool:
        def work() -> bool:
            try:
                self.server.world.body(body_name)
            except SimulationError:
                return False
            return True

        return bool(self.server.call(work))

    def _body_rotation(self, body_name: str, point: np.ndarray) -> np.ndarray:
        def work() -> np.ndarray:
            world = self.server.world
            body = world.body(body_name)
            context = world.plant.GetMyContextFromRoot(world.context)
            return world.plant.EvalBodyPoseInWorld(context, body).rotation().multiply(point)

        return self.server.call(work)

    def _apply_joint_effort(self, request: Any) -> Any:
        from workbench.msgs.gazebo_msgs import ApplyJointEffort

        reason = out_of_bounds([("effort", request.effort)], MAX_EFFORT, "N m or N")
        try:
            if reason is not None:
                self.server.call(lambda: self.server.joint_owner(request.joint_name))
                _LOG.error("ApplyJointEffort: joint [%s]: %s", request.joint_name, reason)
                return ApplyJointEffort.Response(
                    success=False, status_message=f"ApplyJointEffort: {reason}"
                )
            self.server.apply_joint_effort(
                request.joint_name,
                request.effort,
                _seconds(request.start_time),
                _seconds(request.duration),
            )
        except WorkbenchError:
            return ApplyJointEffort.Response(
                success=False, status_message="ApplyJointEffort: joint not found"
            )
        return ApplyJointEffort.Response(
            success=True, status_message="ApplyJointEffort: effort set"
        )

    def _clear_body_wrenches(self, request: Any) -> Any:
        self.server.clear_jobs(body=request.body_name)
        return {}

    def _clear_joint_forces(self, request: Any) -> Any:
        self.server.clear_jobs(joint=request.joint_name)
        return {}

    def _pause(self, request: Any) -> Any:
        self.server.paused = True
        return {}

    def _unpause(self, request: Any) -> Any:
        self.server.paused = False
        self.server.wake()
        return {}

    def _reset_simulation(self, request: Any) -> Any:
        self.server.reset(time_too=True)
        return {}

    def _reset_world(self, request: Any) -> Any:
        self.server.reset(time_too=False)
        return {}

    def _link_pose(self, scoped: str) -> Any:
        def work() -> Any:
            world = self.server.world
            try:
                body = world.body(scoped)
            except SimulationError:
                if scoped in world.model_names() and scoped != "ground_plane":
                    return world.get_model_pose(scoped)
                raise _NoFrame(scoped) from None
            context = world.plant.GetMyContextFromRoot(world.context)
            return world.plant.EvalBodyPoseInWorld(context, body)

        return self.server.call(work)

    def close(self) -> None:
        """Stop serving (the node is the caller's to shut down)."""
        if self.publish in self.server.hooks:
            self.server.hooks.remove(self.publish)
        for service in self.services:
            service.shutdown()
        self.set_state_topic.unregister()


class _NoFrame(Exception):
    pass


def _spawn_reply(success: bool, message: str) -> Any:
    from workbench.msgs.gazebo_msgs import SpawnModel

    return SpawnModel.Response(success=success, status_message=message)


def _identity() -> Any:
    from pydrake.math import RigidTransform

    return RigidTransform()


def _vector(v: Any) -> np.ndarray:
    return np.array([v.x, v.y, v.z], dtype=float)


def _transform(pose: Any, what: str) -> Any:
    from pydrake.common.eigen_geometry import Quaternion
    from pydrake.math import RigidTransform, RotationMatrix

    o = pose.orientation
    reason = out_of_bounds(xyz(f"{what}.position", pose.position), MAX_POSITION, "m") or (
        out_of_bounds(
            [(f"{what}.orientation.{k}", getattr(o, k)) for k in ("x", "y", "z", "w")],
            MAX_QUATERNION,
            "",
        )
    )
    if reason is not None:
        raise SimulationError(reason)
    p = _vector(pose.position)
    q = np.array([o.w, o.x, o.y, o.z], float)
    norm = float(np.linalg.norm(q))
    if norm < 1e-6:  # Gazebo normalises; a zero-length quaternion means no rotation
        q, norm = np.array([1.0, 0.0, 0.0, 0.0]), 1.0
    # pydrake's stubs give numpy arrays a float64 shape; these vectors are right
    return RigidTransform(RotationMatrix(Quaternion(q / norm)), p)  # type: ignore[arg-type]


def _place_relative(X_WM_now: Any, X_WF: Any, X_FM: Any) -> Any:
    """gazebo_ros's rule: position = model position + R_WF p, rotation = R_WF R."""
    from pydrake.math import RigidTransform

    R = X_WF.rotation()
    return RigidTransform(
        R.multiply(X_FM.rotation()), X_WM_now.translation() + R.multiply(X_FM.translation())
    )


# Messages the server publishes at 100 Hz are built with the classes' trusted
# constructor (``_from_wire``, the deserializer's): the values are floats computed
# here, and the checked constructors cost 4x as much per message.


@functools.lru_cache(maxsize=1)
def _geometry() -> Any:
    """The geometry_msgs classes, looked up once (a lookup per message costs 2 us each)."""
    from workbench.msgs import geometry_msgs

    return geometry_msgs


def _pose(X: Any) -> Any:
    g = _geometry()
    Point, Pose, Quaternion = g.Point, g.Pose, g.Quaternion  # noqa: N806 - class names
    if X is None:
        return Pose._from_wire(
            Point._from_wire(0.0, 0.0, 0.0), Quaternion._from_wire(0.0, 0.0, 0.0, 1.0)
        )
    x, y, z = (float(c) for c in X.translation())
    q = X.rotation().ToQuaternion()
    return Pose._from_wire(
        Point._from_wire(x, y, z),
        Quaternion._from_wire(float(q.x()), float(q.y()), float(q.z()), float(q.w())),
    )


def _twist(v: Any, w: Any) -> Any:
    Twist, Vector3 = _geometry().Twist, _geometry().Vector3  # noqa: N806 - class names
    return Twist._from_wire(
        Vector3._from_wire(float(v[0]), float(v[1]), float(v[2])),
        Vector3._from_wire(float(w[0]), float(w[1]), float(w[2])),
    )


def _stamp(t: float) -> Any:
    from workbench.msgs import Time

    nanos = int(round(t * 1e9))
    return Time(nanos // 1_000_000_000, nanos % 1_000_000_000)


def _seconds(value: Any) -> float:
    if hasattr(value, "sec"):
        return float(value.sec) + float(value.nanosec) * 1e-9
    if hasattr(value, "secs"):
        return float(value.secs) + float(value.nsecs) * 1e-9
    return float(value)
