"""``libgazebo_ros_control.so``: ros_control's controller manager on a simulated robot.

As gazebo_ros_control's ``GazeboRosControlPlugin`` (noetic)::

    <gazebo>
      <plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">
        <robotNamespace>/</robotNamespace>        <!-- default: the model's name -->
        <robotParam>robot_description</robotParam>
        <robotSimType>gazebo_ros_control/DefaultRobotHWSim</robotSimType>
        <controlPeriod>0.001</controlPeriod>      <!-- s; default: the physics step -->
        <eStopTopic>e_stop</eStopTopic>           <!-- optional std_msgs/Bool -->
      </plugin>
    </gazebo>

The robot description is read from the parameter ``robotParam`` searched upwards from
the robot namespace (as the plugin does); where that parameter is not set (a model
spawned from a file), workbench uses the model's own URDF instead of waiting for it.
Its ``<transmission>`` blocks give the joints and their hardware interfaces
(:mod:`.hardware`), and a :class:`~.manager.ControllerManager` serves
``<robot ns>/controller_manager/*``; the ``spawner`` node loads and starts controllers
(:mod:`.nodes`). Every control period the plugin reads the joints, updates the running
controllers and writes their commands, stamped with simulated time. Only the default
``robotSimType`` exists here; another one is refused in one line.
"""

from __future__ import annotations

import logging
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.gazebo_ros_plugins.ros_context import PluginRos
from workbench.sim.plugins import ModelPlugin, PluginSetupError, SdfElement, UpdateInfo
from workbench.sim.ros_control.hardware import RobotHWSim
from workbench.sim.ros_control.manager import ControllerManager
from workbench.sim.ros_control.params import ParamView
from workbench.sim.ros_control.urdf_info import read_robot_info

_LOG = logging.getLogger("workbench.sim.ros_control")
DEFAULT_SIM_TYPE = "gazebo_ros_control/DefaultRobotHWSim"


class GazeboRosControl(ModelPlugin):
    """ros_control for the model (see the module docstring)."""

    manager: ControllerManager | None = None

    def load(self, model: Any, sdf: SdfElement, node: Any) -> None:
        ros = PluginRos("gazebo_ros_control", sdf, model.name, node)
        self.model = model
        where = f"model '{model.name}', plugin '{sdf.name}'"
        sim_type = ros.string("robotSimType", DEFAULT_SIM_TYPE)
        if sim_type != DEFAULT_SIM_TYPE:
            raise PluginSetupError(
                f"{where}: robotSimType '{sim_type}' is not provided (workbench simulates "
                f"{DEFAULT_SIM_TYPE})"
            )
        step = float(model.time_step)
        self.control_period = step
        if ros.text("controlPeriod") is not None:
            self.control_period = ros.number("controlPeriod", step)
            if self.control_period < step:
                _LOG.error(
                    "%s: desired controller update period (%g s) is faster than the simulation "
                    "period (%g s)",
                    where,
                    self.control_period,
                    step,
                )
            elif self.control_period > step:
                _LOG.warning(
                    "%s: desired controller update period (%g s) is slower than the simulation "
                    "period (%g s)",
                    where,
                    self.control_period,
                    step,
                )
            self.update_rate = 1.0 / self.control_period if self.control_period > step else 0.0
        root = ParamView(node.bus.params if node is not None else None, ros.namespace)
        text, source = self._description(root, ros.string("robotParam", "robot_description"))
        try:
            info = read_robot_info(text, source)
        except SimulationError as error:
            raise PluginSetupError(f"{where}: {error.one_line()}") from None
        for problem in info.problems:
            _LOG.error("%s: %s", where, problem)
        if not info.transmissions:
            _LOG.warning("%s: %s has no usable <transmission>; nothing to control", where, source)
        try:
            self.hardware = RobotHWSim.from_robot(model, info, root, source)
        except SimulationError as error:
            raise PluginSetupError(f"{where}: {error.one_line()}") from None
        self.manager = ControllerManager(self.hardware, root, node, model.server.call)
        self.last: float | None = None
        self.stopped = False
        self.e_stop_subscription = None
        topic = ros.text("eStopTopic")
        if topic and node is not None:
            self.e_stop_subscription = node.create_subscription(
                ros.topic(topic), "std_msgs/Bool", self._on_e_stop, 1, inline=True
            )
        _LOG.info("%s: ros_control in namespace %s", where, ros.namespace)

    def _description(self, root: ParamView, parameter: str) -> tuple[str, str]:
        """The URDF text and where it came from."""
        found = root.search(parameter)
        if found is not None:
            value = root.params.get(found)
            if isinstance(value, str) and value.strip():
                return value, f"parameter {found}"
        placed = self.model.server.world.models.get(self.model.name)
        if placed is not None and placed.model.format == "urdf":
            _LOG.info(
                "model '%s': parameter '%s' is not set; ros_control reads the model's own URDF",
                self.model.name,
                parameter,
            )
            return placed.model.text, placed.model.source or f"model '{self.model.name}'"
        raise PluginSetupError(
            f"model '{self.model.name}': gazebo_ros_control needs the robot's URDF in parameter "
            f"'{parameter}' (it is not set, and the model is not a URDF)"
        )

    def _on_e_stop(self, message: Any) -> None:
        self.hardware.e_stop = bool(message.data)

    def update(self, info: UpdateInfo) -> None:
        assert self.manager is not None
        period = self.control_period if self.last is None else info.sim_time - self.last
        self.last = info.sim_time
        self.hardware.read()
        if self.stopped and not self.hardware.e_stop:  # released: controllers start afresh
            self.manager.reset(info.sim_time)
        self.stopped = self.hardware.e_stop
        self.manager.update(info.sim_time, period)
        self.hardware.write(period)

    def reset(self) -> None:
        self.last = None
        if self.manager is not None:
            self.hardware.read()
            self.manager.reset(self.model.sim_time)

    def close(self) -> None:
        if self.manager is not None:
            self.manager.close()
        if self.e_stop_subscription is not None:
            self.e_stop_subscription.unregister()
