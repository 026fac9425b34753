"""Types of the gazebo_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import builtin_interfaces, geometry_msgs, std_msgs, trajectory_msgs
from workbench.msgs import gazebo_msgs as msg
from workbench.msgs import gazebo_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "ApplyBodyWrench",
    "ApplyBodyWrenchRequest",
    "ApplyBodyWrenchResponse",
    "ApplyJointEffort",
    "ApplyJointEffortRequest",
    "ApplyJointEffortResponse",
    "BodyRequest",
    "BodyRequestRequest",
    "BodyRequestResponse",
    "ContactState",
    "ContactsState",
    "DeleteLight",
    "DeleteLightRequest",
    "DeleteLightResponse",
    "DeleteModel",
    "DeleteModelRequest",
    "DeleteModelResponse",
    "GetJointProperties",
    "GetJointPropertiesRequest",
    "GetJointPropertiesResponse",
    "GetLightProperties",
    "GetLightPropertiesRequest",
    "GetLightPropertiesResponse",
    "GetLinkProperties",
    "GetLinkPropertiesRequest",
    "GetLinkPropertiesResponse",
    "GetLinkState",
    "GetLinkStateRequest",
    "GetLinkStateResponse",
    "GetModelProperties",
    "GetModelPropertiesRequest",
    "GetModelPropertiesResponse",
    "GetModelState",
    "GetModelStateRequest",
    "GetModelStateResponse",
    "GetPhysicsProperties",
    "GetPhysicsPropertiesRequest",
    "GetPhysicsPropertiesResponse",
    "GetWorldProperties",
    "GetWorldPropertiesRequest",
    "GetWorldPropertiesResponse",
    "JointRequest",
    "JointRequestRequest",
    "JointRequestResponse",
    "LinkState",
    "LinkStates",
    "ModelState",
    "ModelStates",
    "ODEJointProperties",
    "ODEPhysics",
    "PerformanceMetrics",
    "SensorPerformanceMetric",
    "SetJointProperties",
    "SetJointPropertiesRequest",
    "SetJointPropertiesResponse",
    "SetJointTrajectory",
    "SetJointTrajectoryRequest",
    "SetJointTrajectoryResponse",
    "SetLightProperties",
    "SetLightPropertiesRequest",
    "SetLightPropertiesResponse",
    "SetLinkProperties",
    "SetLinkPropertiesRequest",
    "SetLinkPropertiesResponse",
    "SetLinkState",
    "SetLinkStateRequest",
    "SetLinkStateResponse",
    "SetModelConfiguration",
    "SetModelConfigurationRequest",
    "SetModelConfigurationResponse",
    "SetModelState",
    "SetModelStateRequest",
    "SetModelStateResponse",
    "SetPhysicsProperties",
    "SetPhysicsPropertiesRequest",
    "SetPhysicsPropertiesResponse",
    "SpawnModel",
    "SpawnModelRequest",
    "SpawnModelResponse",
    "WorldState",
    "msg",
    "srv",
]

class ApplyBodyWrenchRequest(Message):
    """``gazebo_msgs/ApplyBodyWrenchRequest``."""

    body_name: str
    reference_frame: str
    @property
    def reference_point(self) -> geometry_msgs.Point: ...
    @reference_point.setter
    def reference_point(self, value: geometry_msgs.Point | Mapping[str, Any]) -> None: ...
    @property
    def wrench(self) -> geometry_msgs.Wrench: ...
    @wrench.setter
    def wrench(self, value: geometry_msgs.Wrench | Mapping[str, Any]) -> None: ...
    @property
    def start_time(self) -> builtin_interfaces.Time: ...
    @start_time.setter
    def start_time(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    @property
    def duration(self) -> builtin_interfaces.Duration: ...
    @duration.setter
    def duration(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        body_name: str = ...,
        reference_frame: str = ...,
        reference_point: geometry_msgs.Point | Mapping[str, Any] = ...,
        wrench: geometry_msgs.Wrench | Mapping[str, Any] = ...,
        start_time: builtin_interfaces.Time | Mapping[str, Any] = ...,
        duration: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...

class ApplyBodyWrenchResponse(Message):
    """``gazebo_msgs/ApplyBodyWrenchResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class ApplyJointEffortRequest(Message):
    """``gazebo_msgs/ApplyJointEffortRequest``."""

    joint_name: str
    effort: float
    @property
    def start_time(self) -> builtin_interfaces.Time: ...
    @start_time.setter
    def start_time(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    @property
    def duration(self) -> builtin_interfaces.Duration: ...
    @duration.setter
    def duration(self, value: builtin_interfaces.Duration | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        joint_name: str = ...,
        effort: float = ...,
        start_time: builtin_interfaces.Time | Mapping[str, Any] = ...,
        duration: builtin_interfaces.Duration | Mapping[str, Any] = ...,
    ) -> None: ...

class ApplyJointEffortResponse(Message):
    """``gazebo_msgs/ApplyJointEffortResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class BodyRequestRequest(Message):
    """``gazebo_msgs/BodyRequestRequest``."""

    body_name: str
    def __init__(
        self,
        body_name: str = ...,
    ) -> None: ...

class BodyRequestResponse(Message):
    """``gazebo_msgs/BodyRequestResponse``."""

    def __init__(self) -> None: ...

class ContactState(Message):
    """``gazebo_msgs/ContactState``."""

    info: str
    collision1_name: str
    collision2_name: str
    @property
    def wrenches(self) -> list[geometry_msgs.Wrench]: ...
    @wrenches.setter
    def wrenches(self, value: Iterable[geometry_msgs.Wrench | Mapping[str, Any]]) -> None: ...
    @property
    def total_wrench(self) -> geometry_msgs.Wrench: ...
    @total_wrench.setter
    def total_wrench(self, value: geometry_msgs.Wrench | Mapping[str, Any]) -> None: ...
    @property
    def contact_positions(self) -> list[geometry_msgs.Vector3]: ...
    @contact_positions.setter
    def contact_positions(
        self, value: Iterable[geometry_msgs.Vector3 | Mapping[str, Any]]
    ) -> None: ...
    @property
    def contact_normals(self) -> list[geometry_msgs.Vector3]: ...
    @contact_normals.setter
    def contact_normals(
        self, value: Iterable[geometry_msgs.Vector3 | Mapping[str, Any]]
    ) -> None: ...
    @property
    def depths(self) -> NDArray[np.float64]: ...
    @depths.setter
    def depths(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        info: str = ...,
        collision1_name: str = ...,
        collision2_name: str = ...,
        wrenches: Iterable[geometry_msgs.Wrench | Mapping[str, Any]] = ...,
        total_wrench: geometry_msgs.Wrench | Mapping[str, Any] = ...,
        contact_positions: Iterable[geometry_msgs.Vector3 | Mapping[str, Any]] = ...,
        contact_normals: Iterable[geometry_msgs.Vector3 | Mapping[str, Any]] = ...,
        depths: ArrayLike = ...,
    ) -> None: ...

class ContactsState(Message):
    """``gazebo_msgs/ContactsState``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def states(self) -> list[ContactState]: ...
    @states.setter
    def states(self, value: Iterable[ContactState | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        states: Iterable[ContactState | Mapping[str, Any]] = ...,
    ) -> None: ...

class DeleteLightRequest(Message):
    """``gazebo_msgs/DeleteLightRequest``."""

    light_name: str
    def __init__(
        self,
        light_name: str = ...,
    ) -> None: ...

class DeleteLightResponse(Message):
    """``gazebo_msgs/DeleteLightResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class DeleteModelRequest(Message):
    """``gazebo_msgs/DeleteModelRequest``."""

    model_name: str
    def __init__(
        self,
        model_name: str = ...,
    ) -> None: ...

class DeleteModelResponse(Message):
    """``gazebo_msgs/DeleteModelResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetJointPropertiesRequest(Message):
    """``gazebo_msgs/GetJointPropertiesRequest``."""

    joint_name: str
    def __init__(
        self,
        joint_name: str = ...,
    ) -> None: ...

class GetJointPropertiesResponse(Message):
    """``gazebo_msgs/GetJointPropertiesResponse``."""

    REVOLUTE: Final = 0
    CONTINUOUS: Final = 1
    PRISMATIC: Final = 2
    FIXED: Final = 3
    BALL: Final = 4
    UNIVERSAL: Final = 5

    type: int
    @property
    def damping(self) -> NDArray[np.float64]: ...
    @damping.setter
    def damping(self, value: ArrayLike) -> None: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @position.setter
    def position(self, value: ArrayLike) -> None: ...
    @property
    def rate(self) -> NDArray[np.float64]: ...
    @rate.setter
    def rate(self, value: ArrayLike) -> None: ...
    success: bool
    status_message: str
    def __init__(
        self,
        type: int = ...,
        damping: ArrayLike = ...,
        position: ArrayLike = ...,
        rate: ArrayLike = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetLightPropertiesRequest(Message):
    """``gazebo_msgs/GetLightPropertiesRequest``."""

    light_name: str
    def __init__(
        self,
        light_name: str = ...,
    ) -> None: ...

class GetLightPropertiesResponse(Message):
    """``gazebo_msgs/GetLightPropertiesResponse``."""

    @property
    def diffuse(self) -> std_msgs.ColorRGBA: ...
    @diffuse.setter
    def diffuse(self, value: std_msgs.ColorRGBA | Mapping[str, Any]) -> None: ...
    attenuation_constant: float
    attenuation_linear: float
    attenuation_quadratic: float
    success: bool
    status_message: str
    def __init__(
        self,
        diffuse: std_msgs.ColorRGBA | Mapping[str, Any] = ...,
        attenuation_constant: float = ...,
        attenuation_linear: float = ...,
        attenuation_quadratic: float = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetLinkPropertiesRequest(Message):
    """``gazebo_msgs/GetLinkPropertiesRequest``."""

    link_name: str
    def __init__(
        self,
        link_name: str = ...,
    ) -> None: ...

class GetLinkPropertiesResponse(Message):
    """``gazebo_msgs/GetLinkPropertiesResponse``."""

    @property
    def com(self) -> geometry_msgs.Pose: ...
    @com.setter
    def com(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    gravity_mode: bool
    mass: float
    ixx: float
    ixy: float
    ixz: float
    iyy: float
    iyz: float
    izz: float
    success: bool
    status_message: str
    def __init__(
        self,
        com: geometry_msgs.Pose | Mapping[str, Any] = ...,
        gravity_mode: bool = ...,
        mass: float = ...,
        ixx: float = ...,
        ixy: float = ...,
        ixz: float = ...,
        iyy: float = ...,
        iyz: float = ...,
        izz: float = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetLinkStateRequest(Message):
    """``gazebo_msgs/GetLinkStateRequest``."""

    link_name: str
    reference_frame: str
    def __init__(
        self,
        link_name: str = ...,
        reference_frame: str = ...,
    ) -> None: ...

class GetLinkStateResponse(Message):
    """``gazebo_msgs/GetLinkStateResponse``."""

    @property
    def link_state(self) -> LinkState: ...
    @link_state.setter
    def link_state(self, value: LinkState | Mapping[str, Any]) -> None: ...
    success: bool
    status_message: str
    def __init__(
        self,
        link_state: LinkState | Mapping[str, Any] = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetModelPropertiesRequest(Message):
    """``gazebo_msgs/GetModelPropertiesRequest``."""

    model_name: str
    def __init__(
        self,
        model_name: str = ...,
    ) -> None: ...

class GetModelPropertiesResponse(Message):
    """``gazebo_msgs/GetModelPropertiesResponse``."""

    parent_model_name: str
    canonical_body_name: str
    @property
    def body_names(self) -> list[str]: ...
    @body_names.setter
    def body_names(self, value: Iterable[str]) -> None: ...
    @property
    def geom_names(self) -> list[str]: ...
    @geom_names.setter
    def geom_names(self, value: Iterable[str]) -> None: ...
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def child_model_names(self) -> list[str]: ...
    @child_model_names.setter
    def child_model_names(self, value: Iterable[str]) -> None: ...
    is_static: bool
    success: bool
    status_message: str
    def __init__(
        self,
        parent_model_name: str = ...,
        canonical_body_name: str = ...,
        body_names: Iterable[str] = ...,
        geom_names: Iterable[str] = ...,
        joint_names: Iterable[str] = ...,
        child_model_names: Iterable[str] = ...,
        is_static: bool = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetModelStateRequest(Message):
    """``gazebo_msgs/GetModelStateRequest``."""

    model_name: str
    relative_entity_name: str
    def __init__(
        self,
        model_name: str = ...,
        relative_entity_name: str = ...,
    ) -> None: ...

class GetModelStateResponse(Message):
    """``gazebo_msgs/GetModelStateResponse``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    @property
    def twist(self) -> geometry_msgs.Twist: ...
    @twist.setter
    def twist(self, value: geometry_msgs.Twist | Mapping[str, Any]) -> None: ...
    success: bool
    status_message: str
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        twist: geometry_msgs.Twist | Mapping[str, Any] = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetPhysicsPropertiesRequest(Message):
    """``gazebo_msgs/GetPhysicsPropertiesRequest``."""

    def __init__(self) -> None: ...

class GetPhysicsPropertiesResponse(Message):
    """``gazebo_msgs/GetPhysicsPropertiesResponse``."""

    time_step: float
    pause: bool
    max_update_rate: float
    @property
    def gravity(self) -> geometry_msgs.Vector3: ...
    @gravity.setter
    def gravity(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def ode_config(self) -> ODEPhysics: ...
    @ode_config.setter
    def ode_config(self, value: ODEPhysics | Mapping[str, Any]) -> None: ...
    success: bool
    status_message: str
    def __init__(
        self,
        time_step: float = ...,
        pause: bool = ...,
        max_update_rate: float = ...,
        gravity: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        ode_config: ODEPhysics | Mapping[str, Any] = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class GetWorldPropertiesRequest(Message):
    """``gazebo_msgs/GetWorldPropertiesRequest``."""

    def __init__(self) -> None: ...

class GetWorldPropertiesResponse(Message):
    """``gazebo_msgs/GetWorldPropertiesResponse``."""

    sim_time: float
    @property
    def model_names(self) -> list[str]: ...
    @model_names.setter
    def model_names(self, value: Iterable[str]) -> None: ...
    rendering_enabled: bool
    success: bool
    status_message: str
    def __init__(
        self,
        sim_time: float = ...,
        model_names: Iterable[str] = ...,
        rendering_enabled: bool = ...,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class JointRequestRequest(Message):
    """``gazebo_msgs/JointRequestRequest``."""

    joint_name: str
    def __init__(
        self,
        joint_name: str = ...,
    ) -> None: ...

class JointRequestResponse(Message):
    """``gazebo_msgs/JointRequestResponse``."""

    def __init__(self) -> None: ...

class LinkState(Message):
    """``gazebo_msgs/LinkState``."""

    link_name: str
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    @property
    def twist(self) -> geometry_msgs.Twist: ...
    @twist.setter
    def twist(self, value: geometry_msgs.Twist | Mapping[str, Any]) -> None: ...
    reference_frame: str
    def __init__(
        self,
        link_name: str = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        twist: geometry_msgs.Twist | Mapping[str, Any] = ...,
        reference_frame: str = ...,
    ) -> None: ...

class LinkStates(Message):
    """``gazebo_msgs/LinkStates``."""

    @property
    def name(self) -> list[str]: ...
    @name.setter
    def name(self, value: Iterable[str]) -> None: ...
    @property
    def pose(self) -> list[geometry_msgs.Pose]: ...
    @pose.setter
    def pose(self, value: Iterable[geometry_msgs.Pose | Mapping[str, Any]]) -> None: ...
    @property
    def twist(self) -> list[geometry_msgs.Twist]: ...
    @twist.setter
    def twist(self, value: Iterable[geometry_msgs.Twist | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        name: Iterable[str] = ...,
        pose: Iterable[geometry_msgs.Pose | Mapping[str, Any]] = ...,
        twist: Iterable[geometry_msgs.Twist | Mapping[str, Any]] = ...,
    ) -> None: ...

class ModelState(Message):
    """``gazebo_msgs/ModelState``."""

    model_name: str
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    @property
    def twist(self) -> geometry_msgs.Twist: ...
    @twist.setter
    def twist(self, value: geometry_msgs.Twist | Mapping[str, Any]) -> None: ...
    reference_frame: str
    def __init__(
        self,
        model_name: str = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        twist: geometry_msgs.Twist | Mapping[str, Any] = ...,
        reference_frame: str = ...,
    ) -> None: ...

class ModelStates(Message):
    """``gazebo_msgs/ModelStates``."""

    @property
    def name(self) -> list[str]: ...
    @name.setter
    def name(self, value: Iterable[str]) -> None: ...
    @property
    def pose(self) -> list[geometry_msgs.Pose]: ...
    @pose.setter
    def pose(self, value: Iterable[geometry_msgs.Pose | Mapping[str, Any]]) -> None: ...
    @property
    def twist(self) -> list[geometry_msgs.Twist]: ...
    @twist.setter
    def twist(self, value: Iterable[geometry_msgs.Twist | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        name: Iterable[str] = ...,
        pose: Iterable[geometry_msgs.Pose | Mapping[str, Any]] = ...,
        twist: Iterable[geometry_msgs.Twist | Mapping[str, Any]] = ...,
    ) -> None: ...

class ODEJointProperties(Message):
    """``gazebo_msgs/ODEJointProperties``."""

    @property
    def damping(self) -> NDArray[np.float64]: ...
    @damping.setter
    def damping(self, value: ArrayLike) -> None: ...
    @property
    def hiStop(self) -> NDArray[np.float64]: ...
    @hiStop.setter
    def hiStop(self, value: ArrayLike) -> None: ...
    @property
    def loStop(self) -> NDArray[np.float64]: ...
    @loStop.setter
    def loStop(self, value: ArrayLike) -> None: ...
    @property
    def erp(self) -> NDArray[np.float64]: ...
    @erp.setter
    def erp(self, value: ArrayLike) -> None: ...
    @property
    def cfm(self) -> NDArray[np.float64]: ...
    @cfm.setter
    def cfm(self, value: ArrayLike) -> None: ...
    @property
    def stop_erp(self) -> NDArray[np.float64]: ...
    @stop_erp.setter
    def stop_erp(self, value: ArrayLike) -> None: ...
    @property
    def stop_cfm(self) -> NDArray[np.float64]: ...
    @stop_cfm.setter
    def stop_cfm(self, value: ArrayLike) -> None: ...
    @property
    def fudge_factor(self) -> NDArray[np.float64]: ...
    @fudge_factor.setter
    def fudge_factor(self, value: ArrayLike) -> None: ...
    @property
    def fmax(self) -> NDArray[np.float64]: ...
    @fmax.setter
    def fmax(self, value: ArrayLike) -> None: ...
    @property
    def vel(self) -> NDArray[np.float64]: ...
    @vel.setter
    def vel(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        damping: ArrayLike = ...,
        hiStop: ArrayLike = ...,
        loStop: ArrayLike = ...,
        erp: ArrayLike = ...,
        cfm: ArrayLike = ...,
        stop_erp: ArrayLike = ...,
        stop_cfm: ArrayLike = ...,
        fudge_factor: ArrayLike = ...,
        fmax: ArrayLike = ...,
        vel: ArrayLike = ...,
    ) -> None: ...

class ODEPhysics(Message):
    """``gazebo_msgs/ODEPhysics``."""

    auto_disable_bodies: bool
    sor_pgs_precon_iters: int
    sor_pgs_iters: int
    sor_pgs_w: float
    sor_pgs_rms_error_tol: float
    contact_surface_layer: float
    contact_max_correcting_vel: float
    cfm: float
    erp: float
    max_contacts: int
    def __init__(
        self,
        auto_disable_bodies: bool = ...,
        sor_pgs_precon_iters: int = ...,
        sor_pgs_iters: int = ...,
        sor_pgs_w: float = ...,
        sor_pgs_rms_error_tol: float = ...,
        contact_surface_layer: float = ...,
        contact_max_correcting_vel: float = ...,
        cfm: float = ...,
        erp: float = ...,
        max_contacts: int = ...,
    ) -> None: ...

class PerformanceMetrics(Message):
    """``gazebo_msgs/PerformanceMetrics``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    real_time_factor: float
    @property
    def sensors(self) -> list[SensorPerformanceMetric]: ...
    @sensors.setter
    def sensors(self, value: Iterable[SensorPerformanceMetric | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        real_time_factor: float = ...,
        sensors: Iterable[SensorPerformanceMetric | Mapping[str, Any]] = ...,
    ) -> None: ...

class SensorPerformanceMetric(Message):
    """``gazebo_msgs/SensorPerformanceMetric``."""

    name: str
    sim_update_rate: float
    real_update_rate: float
    fps: float
    def __init__(
        self,
        name: str = ...,
        sim_update_rate: float = ...,
        real_update_rate: float = ...,
        fps: float = ...,
    ) -> None: ...

class SetJointPropertiesRequest(Message):
    """``gazebo_msgs/SetJointPropertiesRequest``."""

    joint_name: str
    @property
    def ode_joint_config(self) -> ODEJointProperties: ...
    @ode_joint_config.setter
    def ode_joint_config(self, value: ODEJointProperties | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        joint_name: str = ...,
        ode_joint_config: ODEJointProperties | Mapping[str, Any] = ...,
    ) -> None: ...

class SetJointPropertiesResponse(Message):
    """``gazebo_msgs/SetJointPropertiesResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetJointTrajectoryRequest(Message):
    """``gazebo_msgs/SetJointTrajectoryRequest``."""

    model_name: str
    @property
    def joint_trajectory(self) -> trajectory_msgs.JointTrajectory: ...
    @joint_trajectory.setter
    def joint_trajectory(
        self, value: trajectory_msgs.JointTrajectory | Mapping[str, Any]
    ) -> None: ...
    @property
    def model_pose(self) -> geometry_msgs.Pose: ...
    @model_pose.setter
    def model_pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    set_model_pose: bool
    disable_physics_updates: bool
    def __init__(
        self,
        model_name: str = ...,
        joint_trajectory: trajectory_msgs.JointTrajectory | Mapping[str, Any] = ...,
        model_pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        set_model_pose: bool = ...,
        disable_physics_updates: bool = ...,
    ) -> None: ...

class SetJointTrajectoryResponse(Message):
    """``gazebo_msgs/SetJointTrajectoryResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetLightPropertiesRequest(Message):
    """``gazebo_msgs/SetLightPropertiesRequest``."""

    light_name: str
    cast_shadows: bool
    @property
    def diffuse(self) -> std_msgs.ColorRGBA: ...
    @diffuse.setter
    def diffuse(self, value: std_msgs.ColorRGBA | Mapping[str, Any]) -> None: ...
    @property
    def specular(self) -> std_msgs.ColorRGBA: ...
    @specular.setter
    def specular(self, value: std_msgs.ColorRGBA | Mapping[str, Any]) -> None: ...
    attenuation_constant: float
    attenuation_linear: float
    attenuation_quadratic: float
    @property
    def direction(self) -> geometry_msgs.Vector3: ...
    @direction.setter
    def direction(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def pose(self) -> geometry_msgs.Pose: ...
    @pose.setter
    def pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        light_name: str = ...,
        cast_shadows: bool = ...,
        diffuse: std_msgs.ColorRGBA | Mapping[str, Any] = ...,
        specular: std_msgs.ColorRGBA | Mapping[str, Any] = ...,
        attenuation_constant: float = ...,
        attenuation_linear: float = ...,
        attenuation_quadratic: float = ...,
        direction: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
    ) -> None: ...

class SetLightPropertiesResponse(Message):
    """``gazebo_msgs/SetLightPropertiesResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetLinkPropertiesRequest(Message):
    """``gazebo_msgs/SetLinkPropertiesRequest``."""

    link_name: str
    @property
    def com(self) -> geometry_msgs.Pose: ...
    @com.setter
    def com(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    gravity_mode: bool
    mass: float
    ixx: float
    ixy: float
    ixz: float
    iyy: float
    iyz: float
    izz: float
    def __init__(
        self,
        link_name: str = ...,
        com: geometry_msgs.Pose | Mapping[str, Any] = ...,
        gravity_mode: bool = ...,
        mass: float = ...,
        ixx: float = ...,
        ixy: float = ...,
        ixz: float = ...,
        iyy: float = ...,
        iyz: float = ...,
        izz: float = ...,
    ) -> None: ...

class SetLinkPropertiesResponse(Message):
    """``gazebo_msgs/SetLinkPropertiesResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetLinkStateRequest(Message):
    """``gazebo_msgs/SetLinkStateRequest``."""

    @property
    def link_state(self) -> LinkState: ...
    @link_state.setter
    def link_state(self, value: LinkState | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        link_state: LinkState | Mapping[str, Any] = ...,
    ) -> None: ...

class SetLinkStateResponse(Message):
    """``gazebo_msgs/SetLinkStateResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetModelConfigurationRequest(Message):
    """``gazebo_msgs/SetModelConfigurationRequest``."""

    model_name: str
    urdf_param_name: str
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def joint_positions(self) -> NDArray[np.float64]: ...
    @joint_positions.setter
    def joint_positions(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        model_name: str = ...,
        urdf_param_name: str = ...,
        joint_names: Iterable[str] = ...,
        joint_positions: ArrayLike = ...,
    ) -> None: ...

class SetModelConfigurationResponse(Message):
    """``gazebo_msgs/SetModelConfigurationResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetModelStateRequest(Message):
    """``gazebo_msgs/SetModelStateRequest``."""

    @property
    def model_state(self) -> ModelState: ...
    @model_state.setter
    def model_state(self, value: ModelState | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        model_state: ModelState | Mapping[str, Any] = ...,
    ) -> None: ...

class SetModelStateResponse(Message):
    """``gazebo_msgs/SetModelStateResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SetPhysicsPropertiesRequest(Message):
    """``gazebo_msgs/SetPhysicsPropertiesRequest``."""

    time_step: float
    max_update_rate: float
    @property
    def gravity(self) -> geometry_msgs.Vector3: ...
    @gravity.setter
    def gravity(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def ode_config(self) -> ODEPhysics: ...
    @ode_config.setter
    def ode_config(self, value: ODEPhysics | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        time_step: float = ...,
        max_update_rate: float = ...,
        gravity: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        ode_config: ODEPhysics | Mapping[str, Any] = ...,
    ) -> None: ...

class SetPhysicsPropertiesResponse(Message):
    """``gazebo_msgs/SetPhysicsPropertiesResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class SpawnModelRequest(Message):
    """``gazebo_msgs/SpawnModelRequest``."""

    model_name: str
    model_xml: str
    robot_namespace: str
    @property
    def initial_pose(self) -> geometry_msgs.Pose: ...
    @initial_pose.setter
    def initial_pose(self, value: geometry_msgs.Pose | Mapping[str, Any]) -> None: ...
    reference_frame: str
    def __init__(
        self,
        model_name: str = ...,
        model_xml: str = ...,
        robot_namespace: str = ...,
        initial_pose: geometry_msgs.Pose | Mapping[str, Any] = ...,
        reference_frame: str = ...,
    ) -> None: ...

class SpawnModelResponse(Message):
    """``gazebo_msgs/SpawnModelResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class WorldState(Message):
    """``gazebo_msgs/WorldState``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def name(self) -> list[str]: ...
    @name.setter
    def name(self, value: Iterable[str]) -> None: ...
    @property
    def pose(self) -> list[geometry_msgs.Pose]: ...
    @pose.setter
    def pose(self, value: Iterable[geometry_msgs.Pose | Mapping[str, Any]]) -> None: ...
    @property
    def twist(self) -> list[geometry_msgs.Twist]: ...
    @twist.setter
    def twist(self, value: Iterable[geometry_msgs.Twist | Mapping[str, Any]]) -> None: ...
    @property
    def wrench(self) -> list[geometry_msgs.Wrench]: ...
    @wrench.setter
    def wrench(self, value: Iterable[geometry_msgs.Wrench | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        name: Iterable[str] = ...,
        pose: Iterable[geometry_msgs.Pose | Mapping[str, Any]] = ...,
        twist: Iterable[geometry_msgs.Twist | Mapping[str, Any]] = ...,
        wrench: Iterable[geometry_msgs.Wrench | Mapping[str, Any]] = ...,
    ) -> None: ...

class ApplyBodyWrench(ServiceType):
    """``gazebo_msgs/ApplyBodyWrench``: ``ApplyBodyWrench.Request(...)``, ``ApplyBodyWrench.Response(...)``."""

    Request: ClassVar[type[ApplyBodyWrenchRequest]]
    Response: ClassVar[type[ApplyBodyWrenchResponse]]

class ApplyJointEffort(ServiceType):
    """``gazebo_msgs/ApplyJointEffort``: ``ApplyJointEffort.Request(...)``, ``ApplyJointEffort.Response(...)``."""

    Request: ClassVar[type[ApplyJointEffortRequest]]
    Response: ClassVar[type[ApplyJointEffortResponse]]

class BodyRequest(ServiceType):
    """``gazebo_msgs/BodyRequest``: ``BodyRequest.Request(...)``, ``BodyRequest.Response(...)``."""

    Request: ClassVar[type[BodyRequestRequest]]
    Response: ClassVar[type[BodyRequestResponse]]

class DeleteLight(ServiceType):
    """``gazebo_msgs/DeleteLight``: ``DeleteLight.Request(...)``, ``DeleteLight.Response(...)``."""

    Request: ClassVar[type[DeleteLightRequest]]
    Response: ClassVar[type[DeleteLightResponse]]

class DeleteModel(ServiceType):
    """``gazebo_msgs/DeleteModel``: ``DeleteModel.Request(...)``, ``DeleteModel.Response(...)``."""

    Request: ClassVar[type[DeleteModelRequest]]
    Response: ClassVar[type[DeleteModelResponse]]

class GetJointProperties(ServiceType):
    """``gazebo_msgs/GetJointProperties``: ``GetJointProperties.Request(...)``, ``GetJointProperties.Response(...)``."""

    Request: ClassVar[type[GetJointPropertiesRequest]]
    Response: ClassVar[type[GetJointPropertiesResponse]]

class GetLightProperties(ServiceType):
    """``gazebo_msgs/GetLightProperties``: ``GetLightProperties.Request(...)``, ``GetLightProperties.Response(...)``."""

    Request: ClassVar[type[GetLightPropertiesRequest]]
    Response: ClassVar[type[GetLightPropertiesResponse]]

class GetLinkProperties(ServiceType):
    """``gazebo_msgs/GetLinkProperties``: ``GetLinkProperties.Request(...)``, ``GetLinkProperties.Response(...)``."""

    Request: ClassVar[type[GetLinkPropertiesRequest]]
    Response: ClassVar[type[GetLinkPropertiesResponse]]

class GetLinkState(ServiceType):
    """``gazebo_msgs/GetLinkState``: ``GetLinkState.Request(...)``, ``GetLinkState.Response(...)``."""

    Request: ClassVar[type[GetLinkStateRequest]]
    Response: ClassVar[type[GetLinkStateResponse]]

class GetModelProperties(ServiceType):
    """``gazebo_msgs/GetModelProperties``: ``GetModelProperties.Request(...)``, ``GetModelProperties.Response(...)``."""

    Request: ClassVar[type[GetModelPropertiesRequest]]
    Response: ClassVar[type[GetModelPropertiesResponse]]

class GetModelState(ServiceType):
    """``gazebo_msgs/GetModelState``: ``GetModelState.Request(...)``, ``GetModelState.Response(...)``."""

    Request: ClassVar[type[GetModelStateRequest]]
    Response: ClassVar[type[GetModelStateResponse]]

class GetPhysicsProperties(ServiceType):
    """``gazebo_msgs/GetPhysicsProperties``: ``GetPhysicsProperties.Request(...)``, ``GetPhysicsProperties.Response(...)``."""

    Request: ClassVar[type[GetPhysicsPropertiesRequest]]
    Response: ClassVar[type[GetPhysicsPropertiesResponse]]

class GetWorldProperties(ServiceType):
    """``gazebo_msgs/GetWorldProperties``: ``GetWorldProperties.Request(...)``, ``GetWorldProperties.Response(...)``."""

    Request: ClassVar[type[GetWorldPropertiesRequest]]
    Response: ClassVar[type[GetWorldPropertiesResponse]]

class JointRequest(ServiceType):
    """``gazebo_msgs/JointRequest``: ``JointRequest.Request(...)``, ``JointRequest.Response(...)``."""

    Request: ClassVar[type[JointRequestRequest]]
    Response: ClassVar[type[JointRequestResponse]]

class SetJointProperties(ServiceType):
    """``gazebo_msgs/SetJointProperties``: ``SetJointProperties.Request(...)``, ``SetJointProperties.Response(...)``."""

    Request: ClassVar[type[SetJointPropertiesRequest]]
    Response: ClassVar[type[SetJointPropertiesResponse]]

class SetJointTrajectory(ServiceType):
    """``gazebo_msgs/SetJointTrajectory``: ``SetJointTrajectory.Request(...)``, ``SetJointTrajectory.Response(...)``."""

    Request: ClassVar[type[SetJointTrajectoryRequest]]
    Response: ClassVar[type[SetJointTrajectoryResponse]]

class SetLightProperties(ServiceType):
    """``gazebo_msgs/SetLightProperties``: ``SetLightProperties.Request(...)``, ``SetLightProperties.Response(...)``."""

    Request: ClassVar[type[SetLightPropertiesRequest]]
    Response: ClassVar[type[SetLightPropertiesResponse]]

class SetLinkProperties(ServiceType):
    """``gazebo_msgs/SetLinkProperties``: ``SetLinkProperties.Request(...)``, ``SetLinkProperties.Response(...)``."""

    Request: ClassVar[type[SetLinkPropertiesRequest]]
    Response: ClassVar[type[SetLinkPropertiesResponse]]

class SetLinkState(ServiceType):
    """``gazebo_msgs/SetLinkState``: ``SetLinkState.Request(...)``, ``SetLinkState.Response(...)``."""

    Request: ClassVar[type[SetLinkStateRequest]]
    Response: ClassVar[type[SetLinkStateResponse]]

class SetModelConfiguration(ServiceType):
    """``gazebo_msgs/SetModelConfiguration``: ``SetModelConfiguration.Request(...)``, ``SetModelConfiguration.Response(...)``."""

    Request: ClassVar[type[SetModelConfigurationRequest]]
    Response: ClassVar[type[SetModelConfigurationResponse]]

class SetModelState(ServiceType):
    """``gazebo_msgs/SetModelState``: ``SetModelState.Request(...)``, ``SetModelState.Response(...)``."""

    Request: ClassVar[type[SetModelStateRequest]]
    Response: ClassVar[type[SetModelStateResponse]]

class SetPhysicsProperties(ServiceType):
    """``gazebo_msgs/SetPhysicsProperties``: ``SetPhysicsProperties.Request(...)``, ``SetPhysicsProperties.Response(...)``."""

    Request: ClassVar[type[SetPhysicsPropertiesRequest]]
    Response: ClassVar[type[SetPhysicsPropertiesResponse]]

class SpawnModel(ServiceType):
    """``gazebo_msgs/SpawnModel``: ``SpawnModel.Request(...)``, ``SpawnModel.Response(...)``."""

    Request: ClassVar[type[SpawnModelRequest]]
    Response: ClassVar[type[SpawnModelResponse]]
