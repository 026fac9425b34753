"""Types of the sensor_msgs messages (generated: python -m workbench.msgs._stubgen)."""

# Generated from the message definitions; do not edit by hand.

from collections.abc import Iterable, Mapping
from typing import Any, ClassVar, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.msgs import builtin_interfaces, geometry_msgs, std_msgs
from workbench.msgs import sensor_msgs as msg
from workbench.msgs import sensor_msgs as srv
from workbench.msgs._classes import Message, ServiceType

__all__ = [
    "BatteryState",
    "CameraInfo",
    "ChannelFloat32",
    "CompressedImage",
    "FluidPressure",
    "Illuminance",
    "Image",
    "Imu",
    "JointState",
    "Joy",
    "JoyFeedback",
    "JoyFeedbackArray",
    "LaserEcho",
    "LaserScan",
    "MagneticField",
    "MultiDOFJointState",
    "MultiEchoLaserScan",
    "NavSatFix",
    "NavSatStatus",
    "PointCloud",
    "PointCloud2",
    "PointField",
    "Range",
    "RegionOfInterest",
    "RelativeHumidity",
    "SetCameraInfo",
    "SetCameraInfoRequest",
    "SetCameraInfoResponse",
    "Temperature",
    "TimeReference",
    "msg",
    "srv",
]

class BatteryState(Message):
    """``sensor_msgs/BatteryState``."""

    POWER_SUPPLY_STATUS_UNKNOWN: Final = 0
    POWER_SUPPLY_STATUS_CHARGING: Final = 1
    POWER_SUPPLY_STATUS_DISCHARGING: Final = 2
    POWER_SUPPLY_STATUS_NOT_CHARGING: Final = 3
    POWER_SUPPLY_STATUS_FULL: Final = 4
    POWER_SUPPLY_HEALTH_UNKNOWN: Final = 0
    POWER_SUPPLY_HEALTH_GOOD: Final = 1
    POWER_SUPPLY_HEALTH_OVERHEAT: Final = 2
    POWER_SUPPLY_HEALTH_DEAD: Final = 3
    POWER_SUPPLY_HEALTH_OVERVOLTAGE: Final = 4
    POWER_SUPPLY_HEALTH_UNSPEC_FAILURE: Final = 5
    POWER_SUPPLY_HEALTH_COLD: Final = 6
    POWER_SUPPLY_HEALTH_WATCHDOG_TIMER_EXPIRE: Final = 7
    POWER_SUPPLY_HEALTH_SAFETY_TIMER_EXPIRE: Final = 8
    POWER_SUPPLY_TECHNOLOGY_UNKNOWN: Final = 0
    POWER_SUPPLY_TECHNOLOGY_NIMH: Final = 1
    POWER_SUPPLY_TECHNOLOGY_LION: Final = 2
    POWER_SUPPLY_TECHNOLOGY_LIPO: Final = 3
    POWER_SUPPLY_TECHNOLOGY_LIFE: Final = 4
    POWER_SUPPLY_TECHNOLOGY_NICD: Final = 5
    POWER_SUPPLY_TECHNOLOGY_LIMN: Final = 6

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    voltage: float
    temperature: float
    current: float
    charge: float
    capacity: float
    design_capacity: float
    percentage: float
    power_supply_status: int
    power_supply_health: int
    power_supply_technology: int
    present: bool
    @property
    def cell_voltage(self) -> NDArray[np.float32]: ...
    @cell_voltage.setter
    def cell_voltage(self, value: ArrayLike) -> None: ...
    @property
    def cell_temperature(self) -> NDArray[np.float32]: ...
    @cell_temperature.setter
    def cell_temperature(self, value: ArrayLike) -> None: ...
    location: str
    serial_number: str
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        voltage: float = ...,
        temperature: float = ...,
        current: float = ...,
        charge: float = ...,
        capacity: float = ...,
        design_capacity: float = ...,
        percentage: float = ...,
        power_supply_status: int = ...,
        power_supply_health: int = ...,
        power_supply_technology: int = ...,
        present: bool = ...,
        cell_voltage: ArrayLike = ...,
        cell_temperature: ArrayLike = ...,
        location: str = ...,
        serial_number: str = ...,
    ) -> None: ...

class CameraInfo(Message):
    """``sensor_msgs/CameraInfo``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    height: int
    width: int
    distortion_model: str
    @property
    def D(self) -> NDArray[np.float64]: ...
    @D.setter
    def D(self, value: ArrayLike) -> None: ...
    @property
    def K(self) -> NDArray[np.float64]: ...
    @K.setter
    def K(self, value: ArrayLike) -> None: ...
    @property
    def R(self) -> NDArray[np.float64]: ...
    @R.setter
    def R(self, value: ArrayLike) -> None: ...
    @property
    def P(self) -> NDArray[np.float64]: ...
    @P.setter
    def P(self, value: ArrayLike) -> None: ...
    binning_x: int
    binning_y: int
    @property
    def roi(self) -> RegionOfInterest: ...
    @roi.setter
    def roi(self, value: RegionOfInterest | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        height: int = ...,
        width: int = ...,
        distortion_model: str = ...,
        D: ArrayLike = ...,
        K: ArrayLike = ...,
        R: ArrayLike = ...,
        P: ArrayLike = ...,
        binning_x: int = ...,
        binning_y: int = ...,
        roi: RegionOfInterest | Mapping[str, Any] = ...,
    ) -> None: ...

class ChannelFloat32(Message):
    """``sensor_msgs/ChannelFloat32``."""

    name: str
    @property
    def values(self) -> NDArray[np.float32]: ...
    @values.setter
    def values(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        name: str = ...,
        values: ArrayLike = ...,
    ) -> None: ...

class CompressedImage(Message):
    """``sensor_msgs/CompressedImage``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    format: str
    @property
    def data(self) -> NDArray[np.uint8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        format: str = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class FluidPressure(Message):
    """``sensor_msgs/FluidPressure``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    fluid_pressure: float
    variance: float
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        fluid_pressure: float = ...,
        variance: float = ...,
    ) -> None: ...

class Illuminance(Message):
    """``sensor_msgs/Illuminance``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    illuminance: float
    variance: float
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        illuminance: float = ...,
        variance: float = ...,
    ) -> None: ...

class Image(Message):
    """``sensor_msgs/Image``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    height: int
    width: int
    encoding: str
    is_bigendian: int
    step: int
    @property
    def data(self) -> NDArray[np.uint8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        height: int = ...,
        width: int = ...,
        encoding: str = ...,
        is_bigendian: int = ...,
        step: int = ...,
        data: ArrayLike = ...,
    ) -> None: ...

class Imu(Message):
    """``sensor_msgs/Imu``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def orientation(self) -> geometry_msgs.Quaternion: ...
    @orientation.setter
    def orientation(self, value: geometry_msgs.Quaternion | Mapping[str, Any]) -> None: ...
    @property
    def orientation_covariance(self) -> NDArray[np.float64]: ...
    @orientation_covariance.setter
    def orientation_covariance(self, value: ArrayLike) -> None: ...
    @property
    def angular_velocity(self) -> geometry_msgs.Vector3: ...
    @angular_velocity.setter
    def angular_velocity(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def angular_velocity_covariance(self) -> NDArray[np.float64]: ...
    @angular_velocity_covariance.setter
    def angular_velocity_covariance(self, value: ArrayLike) -> None: ...
    @property
    def linear_acceleration(self) -> geometry_msgs.Vector3: ...
    @linear_acceleration.setter
    def linear_acceleration(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def linear_acceleration_covariance(self) -> NDArray[np.float64]: ...
    @linear_acceleration_covariance.setter
    def linear_acceleration_covariance(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        orientation: geometry_msgs.Quaternion | Mapping[str, Any] = ...,
        orientation_covariance: ArrayLike = ...,
        angular_velocity: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        angular_velocity_covariance: ArrayLike = ...,
        linear_acceleration: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        linear_acceleration_covariance: ArrayLike = ...,
    ) -> None: ...

class JointState(Message):
    """``sensor_msgs/JointState``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def name(self) -> list[str]: ...
    @name.setter
    def name(self, value: Iterable[str]) -> None: ...
    @property
    def position(self) -> NDArray[np.float64]: ...
    @position.setter
    def position(self, value: ArrayLike) -> None: ...
    @property
    def velocity(self) -> NDArray[np.float64]: ...
    @velocity.setter
    def velocity(self, value: ArrayLike) -> None: ...
    @property
    def effort(self) -> NDArray[np.float64]: ...
    @effort.setter
    def effort(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        name: Iterable[str] = ...,
        position: ArrayLike = ...,
        velocity: ArrayLike = ...,
        effort: ArrayLike = ...,
    ) -> None: ...

class Joy(Message):
    """``sensor_msgs/Joy``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def axes(self) -> NDArray[np.float32]: ...
    @axes.setter
    def axes(self, value: ArrayLike) -> None: ...
    @property
    def buttons(self) -> NDArray[np.int32]: ...
    @buttons.setter
    def buttons(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        axes: ArrayLike = ...,
        buttons: ArrayLike = ...,
    ) -> None: ...

class JoyFeedback(Message):
    """``sensor_msgs/JoyFeedback``."""

    TYPE_LED: Final = 0
    TYPE_RUMBLE: Final = 1
    TYPE_BUZZER: Final = 2

    type: int
    id: int
    intensity: float
    def __init__(
        self,
        type: int = ...,
        id: int = ...,
        intensity: float = ...,
    ) -> None: ...

class JoyFeedbackArray(Message):
    """``sensor_msgs/JoyFeedbackArray``."""

    @property
    def array(self) -> list[JoyFeedback]: ...
    @array.setter
    def array(self, value: Iterable[JoyFeedback | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        array: Iterable[JoyFeedback | Mapping[str, Any]] = ...,
    ) -> None: ...

class LaserEcho(Message):
    """``sensor_msgs/LaserEcho``."""

    @property
    def echoes(self) -> NDArray[np.float32]: ...
    @echoes.setter
    def echoes(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        echoes: ArrayLike = ...,
    ) -> None: ...

class LaserScan(Message):
    """``sensor_msgs/LaserScan``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    angle_min: float
    angle_max: float
    angle_increment: float
    time_increment: float
    scan_time: float
    range_min: float
    range_max: float
    @property
    def ranges(self) -> NDArray[np.float32]: ...
    @ranges.setter
    def ranges(self, value: ArrayLike) -> None: ...
    @property
    def intensities(self) -> NDArray[np.float32]: ...
    @intensities.setter
    def intensities(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        angle_min: float = ...,
        angle_max: float = ...,
        angle_increment: float = ...,
        time_increment: float = ...,
        scan_time: float = ...,
        range_min: float = ...,
        range_max: float = ...,
        ranges: ArrayLike = ...,
        intensities: ArrayLike = ...,
    ) -> None: ...

class MagneticField(Message):
    """``sensor_msgs/MagneticField``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def magnetic_field(self) -> geometry_msgs.Vector3: ...
    @magnetic_field.setter
    def magnetic_field(self, value: geometry_msgs.Vector3 | Mapping[str, Any]) -> None: ...
    @property
    def magnetic_field_covariance(self) -> NDArray[np.float64]: ...
    @magnetic_field_covariance.setter
    def magnetic_field_covariance(self, value: ArrayLike) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        magnetic_field: geometry_msgs.Vector3 | Mapping[str, Any] = ...,
        magnetic_field_covariance: ArrayLike = ...,
    ) -> None: ...

class MultiDOFJointState(Message):
    """``sensor_msgs/MultiDOFJointState``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def joint_names(self) -> list[str]: ...
    @joint_names.setter
    def joint_names(self, value: Iterable[str]) -> None: ...
    @property
    def transforms(self) -> list[geometry_msgs.Transform]: ...
    @transforms.setter
    def transforms(self, value: Iterable[geometry_msgs.Transform | Mapping[str, Any]]) -> None: ...
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
        joint_names: Iterable[str] = ...,
        transforms: Iterable[geometry_msgs.Transform | Mapping[str, Any]] = ...,
        twist: Iterable[geometry_msgs.Twist | Mapping[str, Any]] = ...,
        wrench: Iterable[geometry_msgs.Wrench | Mapping[str, Any]] = ...,
    ) -> None: ...

class MultiEchoLaserScan(Message):
    """``sensor_msgs/MultiEchoLaserScan``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    angle_min: float
    angle_max: float
    angle_increment: float
    time_increment: float
    scan_time: float
    range_min: float
    range_max: float
    @property
    def ranges(self) -> list[LaserEcho]: ...
    @ranges.setter
    def ranges(self, value: Iterable[LaserEcho | Mapping[str, Any]]) -> None: ...
    @property
    def intensities(self) -> list[LaserEcho]: ...
    @intensities.setter
    def intensities(self, value: Iterable[LaserEcho | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        angle_min: float = ...,
        angle_max: float = ...,
        angle_increment: float = ...,
        time_increment: float = ...,
        scan_time: float = ...,
        range_min: float = ...,
        range_max: float = ...,
        ranges: Iterable[LaserEcho | Mapping[str, Any]] = ...,
        intensities: Iterable[LaserEcho | Mapping[str, Any]] = ...,
    ) -> None: ...

class NavSatFix(Message):
    """``sensor_msgs/NavSatFix``."""

    COVARIANCE_TYPE_UNKNOWN: Final = 0
    COVARIANCE_TYPE_APPROXIMATED: Final = 1
    COVARIANCE_TYPE_DIAGONAL_KNOWN: Final = 2
    COVARIANCE_TYPE_KNOWN: Final = 3

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def status(self) -> NavSatStatus: ...
    @status.setter
    def status(self, value: NavSatStatus | Mapping[str, Any]) -> None: ...
    latitude: float
    longitude: float
    altitude: float
    @property
    def position_covariance(self) -> NDArray[np.float64]: ...
    @position_covariance.setter
    def position_covariance(self, value: ArrayLike) -> None: ...
    position_covariance_type: int
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        status: NavSatStatus | Mapping[str, Any] = ...,
        latitude: float = ...,
        longitude: float = ...,
        altitude: float = ...,
        position_covariance: ArrayLike = ...,
        position_covariance_type: int = ...,
    ) -> None: ...

class NavSatStatus(Message):
    """``sensor_msgs/NavSatStatus``."""

    STATUS_NO_FIX: Final = -1
    STATUS_FIX: Final = 0
    STATUS_SBAS_FIX: Final = 1
    STATUS_GBAS_FIX: Final = 2
    SERVICE_GPS: Final = 1
    SERVICE_GLONASS: Final = 2
    SERVICE_COMPASS: Final = 4
    SERVICE_GALILEO: Final = 8

    status: int
    service: int
    def __init__(
        self,
        status: int = ...,
        service: int = ...,
    ) -> None: ...

class PointCloud(Message):
    """``sensor_msgs/PointCloud``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def points(self) -> list[geometry_msgs.Point32]: ...
    @points.setter
    def points(self, value: Iterable[geometry_msgs.Point32 | Mapping[str, Any]]) -> None: ...
    @property
    def channels(self) -> list[ChannelFloat32]: ...
    @channels.setter
    def channels(self, value: Iterable[ChannelFloat32 | Mapping[str, Any]]) -> None: ...
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        points: Iterable[geometry_msgs.Point32 | Mapping[str, Any]] = ...,
        channels: Iterable[ChannelFloat32 | Mapping[str, Any]] = ...,
    ) -> None: ...

class PointCloud2(Message):
    """``sensor_msgs/PointCloud2``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    height: int
    width: int
    @property
    def fields(self) -> list[PointField]: ...
    @fields.setter
    def fields(self, value: Iterable[PointField | Mapping[str, Any]]) -> None: ...
    is_bigendian: bool
    point_step: int
    row_step: int
    @property
    def data(self) -> NDArray[np.uint8]: ...
    @data.setter
    def data(self, value: ArrayLike) -> None: ...
    is_dense: bool
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        height: int = ...,
        width: int = ...,
        fields: Iterable[PointField | Mapping[str, Any]] = ...,
        is_bigendian: bool = ...,
        point_step: int = ...,
        row_step: int = ...,
        data: ArrayLike = ...,
        is_dense: bool = ...,
    ) -> None: ...

class PointField(Message):
    """``sensor_msgs/PointField``."""

    INT8: Final = 1
    UINT8: Final = 2
    INT16: Final = 3
    UINT16: Final = 4
    INT32: Final = 5
    UINT32: Final = 6
    FLOAT32: Final = 7
    FLOAT64: Final = 8

    name: str
    offset: int
    datatype: int
    count: int
    def __init__(
        self,
        name: str = ...,
        offset: int = ...,
        datatype: int = ...,
        count: int = ...,
    ) -> None: ...

class Range(Message):
    """``sensor_msgs/Range``."""

    ULTRASOUND: Final = 0
    INFRARED: Final = 1

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    radiation_type: int
    field_of_view: float
    min_range: float
    max_range: float
    range: float
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        radiation_type: int = ...,
        field_of_view: float = ...,
        min_range: float = ...,
        max_range: float = ...,
        range: float = ...,
    ) -> None: ...

class RegionOfInterest(Message):
    """``sensor_msgs/RegionOfInterest``."""

    x_offset: int
    y_offset: int
    height: int
    width: int
    do_rectify: bool
    def __init__(
        self,
        x_offset: int = ...,
        y_offset: int = ...,
        height: int = ...,
        width: int = ...,
        do_rectify: bool = ...,
    ) -> None: ...

class RelativeHumidity(Message):
    """``sensor_msgs/RelativeHumidity``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    relative_humidity: float
    variance: float
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        relative_humidity: float = ...,
        variance: float = ...,
    ) -> None: ...

class SetCameraInfoRequest(Message):
    """``sensor_msgs/SetCameraInfoRequest``."""

    @property
    def camera_info(self) -> CameraInfo: ...
    @camera_info.setter
    def camera_info(self, value: CameraInfo | Mapping[str, Any]) -> None: ...
    def __init__(
        self,
        camera_info: CameraInfo | Mapping[str, Any] = ...,
    ) -> None: ...

class SetCameraInfoResponse(Message):
    """``sensor_msgs/SetCameraInfoResponse``."""

    success: bool
    status_message: str
    def __init__(
        self,
        success: bool = ...,
        status_message: str = ...,
    ) -> None: ...

class Temperature(Message):
    """``sensor_msgs/Temperature``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    temperature: float
    variance: float
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        temperature: float = ...,
        variance: float = ...,
    ) -> None: ...

class TimeReference(Message):
    """``sensor_msgs/TimeReference``."""

    @property
    def header(self) -> std_msgs.Header: ...
    @header.setter
    def header(self, value: std_msgs.Header | Mapping[str, Any]) -> None: ...
    @property
    def time_ref(self) -> builtin_interfaces.Time: ...
    @time_ref.setter
    def time_ref(self, value: builtin_interfaces.Time | Mapping[str, Any]) -> None: ...
    source: str
    def __init__(
        self,
        header: std_msgs.Header | Mapping[str, Any] = ...,
        time_ref: builtin_interfaces.Time | Mapping[str, Any] = ...,
        source: str = ...,
    ) -> None: ...

class SetCameraInfo(ServiceType):
    """``sensor_msgs/SetCameraInfo``: ``SetCameraInfo.Request(...)``, ``SetCameraInfo.Response(...)``."""

    Request: ClassVar[type[SetCameraInfoRequest]]
    Response: ClassVar[type[SetCameraInfoResponse]]
