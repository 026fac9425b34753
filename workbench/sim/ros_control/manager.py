"""controller_manager's ``ControllerManager`` (ros_control noetic) for one simulated robot.

Services under ``<robot ns>/controller_manager/``: ``list_controllers``,
``list_controller_types``, ``load_controller``, ``unload_controller``,
``switch_controller`` and ``reload_controller_libraries`` (controller_manager_msgs).
Loading reads ``<robot ns>/<name>/type`` (loaded there by ``<rosparam command="load">``);
switching is STRICT (every name must exist, no double start or stop) or BEST_EFFORT
(what cannot be done is skipped), refuses two running controllers claiming one joint,
and happens in the next control update (``starting``/``stopping`` are called there),
as the real manager does. A controller's state is ``initialized`` after loading,
then ``running`` or ``stopped``. Refusals are logged with controller_manager's words.
"""

from __future__ import annotations

import logging
import threading
from typing import Any

from workbench.errors import SimulationError
from workbench.sim.ros_control.controllers import Controller, ControllerError, controller_types
from workbench.sim.ros_control.hardware import RobotHWSim
from workbench.sim.ros_control.params import ParamView

_LOG = logging.getLogger("workbench.sim.ros_control")
BEST_EFFORT, STRICT = 1, 2


class ControllerManager:
    """Loads, switches and updates controllers of one :class:`RobotHWSim`.

    Args:
        hardware: The robot's joints.
        root: The robot namespace's parameters.
        node: The bus node for services and the controllers' topics, or None.
        run: ``run(fn)`` runs ``fn`` where the control loop runs (the simulation thread).
    """

    def __init__(self, hardware: RobotHWSim, root: ParamView, node: Any, run: Any) -> None:
        self.hardware = hardware
        self.root = root
        self.node = node
        self.run = run
        self.controllers: dict[str, Controller] = {}
        self.lock = threading.RLock()
        self._switch: tuple[list[Controller], list[Controller]] | None = None
        self.services: list[Any] = []
        if node is not None:
            from workbench.msgs import controller_manager_msgs as cm

            handlers = {
                "list_controllers": (cm.ListControllers, self._list),
                "list_controller_types": (cm.ListControllerTypes, self._types),
                "load_controller": (cm.LoadController, self._load),
                "unload_controller": (cm.UnloadController, self._unload),
                "switch_controller": (cm.SwitchController, self._switch_srv),
                "reload_controller_libraries": (cm.ReloadControllerLibraries, self._reload),
            }
            self.services = [
                node.create_service(root.name(f"controller_manager/{name}"), kind, handler)
                for name, (kind, handler) in handlers.items()
            ]

    # --- operations (also the Python API) ---------------------------------------------

    def load(self, name: str) -> bool:
        """Load controller ``name`` from its parameters; False (logged) when it cannot be."""
        with self.lock:
            if name in self.controllers:
                _LOG.error(
                    "A controller named '%s' was already loaded inside the controller manager", name
                )
                return False
            params = self.root.child(name)
            kind = params.get("type", None)
            if not isinstance(kind, str) or not kind:
                _LOG.error(
                    "Could not load controller '%s' because the type was not specified. Did you "
                    "load the controller configuration on the parameter server (namespace: '%s')?",
                    name,
                    params.namespace,
                )
                return False
            cls = controller_types().get(kind)
            if cls is None:
                _LOG.error(
                    "Could not load controller '%s' because controller type '%s' does not exist "
                    "in workbench (it has: %s)",
                    name,
                    kind,
                    ", ".join(controller_types()),
                )
                return False
            controller = cls()
            try:
                controller.setup(name, kind, self.hardware, self.root, self.node)
            except (ControllerError, SimulationError) as error:
                _LOG.error("Initializing controller '%s' failed: %s", name, error.one_line())
                controller.shutdown()
                return False
            self.controllers[name] = controller
            return True

    def unload(self, name: str) -> bool:
        with self.lock:
            controller = self.controllers.get(name)
            if controller is None:
                _LOG.error(
                    "Could not unload controller with name '%s' because no controller with "
                    "this name exists",
                    name,
                )
                return False
            if controller.state == "running":
                _LOG.error(
                    "Could not unload controller with name '%s' because it is still running", name
                )
                return False
            controller.shutdown()
            del self.controllers[name]
            return True

    def switch(self, start: list[str], stop: list[str], strictness: int = STRICT) -> bool:
        """Start and stop controllers in the next update; False when refused (logged)."""
        if strictness == 0:
            _LOG.warning(
                "Controller Manager: To switch controllers you need to specify a strictness "
                "level of STRICT (2) or BEST_EFFORT (1). Defaulting to BEST_EFFORT."
            )
            strictness = BEST_EFFORT
        with self.lock:
            plan = self._plan(start, stop, strictness)
            if plan is None:
                return False
            self._switch = plan
        self.run(self._apply_switch_now)
        return True

    def _plan(
        self, start: list[str], stop: list[str], strictness: int
    ) -> tuple[list[Controller], list[Controller]] | None:
        for names, verb in ((stop, "stop"), (start, "start")):
            for name in names:
                if name not in self.controllers and strictness == STRICT:
                    _LOG.error(
                        "Could not %s controller with name '%s' because no controller with this "
                        "name exists",
                        verb,
                        name,
                    )
                    return None
        to_start, to_stop, after = [], [], []
        for name, controller in self.controllers.items():
            in_stop, in_start = name in stop, name in start
            running = controller.state == "running"
            if not running and in_stop:
                if strictness == STRICT:
                    _LOG.error("Could not stop controller '%s' since it is not running", name)
                    return None
                in_stop = False
            if running and not in_stop and in_start:
                if strictness == STRICT:
                    _LOG.error("Controller '%s' is already running", name)
                    return None
                in_start = False
            if in_stop and in_start:
                _LOG.error(
                    "Could no start or stop controller '%s' because of conflicting switching "
                    "command",
                    name,
                )
                return None
            if running and in_stop and not in_start:
                to_stop.append(controller)
            elif not running and not in_stop and in_start:
                to_start.append(controller)
            if (running and not in_stop) or in_start:
                after.append(controller)
        claims: dict[str, list[str]] = {}
        for controller in after:
            for joint in controller.claimed():
                claims.setdefault(joint, []).append(controller.name)
        conflicts = {joint: names for joint, names in claims.items() if len(names) > 1}
        if conflicts:
            for joint, names in conflicts.items():
                _LOG.warning(
                    "Resource conflict on [%s].  Controllers = [%s]", joint, ", ".join(names)
                )
            _LOG.error("Could not switch controllers, due to resource conflict")
            return None
        return to_start, to_stop

    def _apply_switch_now(self) -> None:
        """Run a pending switch at once (also done at the start of the next update)."""
        if self._switch is not None:
            self.hardware.read()
        self._do_switch(self.hardware.model.sim_time)

    def _do_switch(self, time: float) -> None:
        with self.lock:
            plan, self._switch = self._switch, None
        if plan is None:
            return
        to_start, to_stop = plan
        for controller in to_stop:
            controller.stopping(time)
            controller.state = "stopped"
        for controller in to_start:
            controller.starting(time)
            controller.state = "running"

    def update(self, time: float, period: float) -> None:
        """One control step: a pending switch, then every running controller's update."""
        self._do_switch(time)
        with self.lock:
            running = [c for c in self.controllers.values() if c.state == "running"]
        for controller in running:
            controller.update(time, period)

    def reset(self, time: float) -> None:
        """After a world reset: running controllers start again from the joints' new state."""
        with self.lock:
            running = [c for c in self.controllers.values() if c.state == "running"]
        for controller in running:
            controller.stopping(time)
            controller.starting(time)

    def close(self) -> None:
        with self.lock:
            for controller in self.controllers.values():
                controller.shutdown()
            self.controllers.clear()
        for service in self.services:
            service.shutdown()
        self.services.clear()

    # --- service handlers ---------------------------------------------------------------

    def _list(self, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        states = []
        with self.lock:
            for name, controller in self.controllers.items():
                resources = []
                if controller.claimed() or controller.interface:
                    resources.append(
                        cm.HardwareInterfaceResources(
                            hardware_interface=controller.interface,
                            resources=sorted(set(controller.claimed())),
                        )
                    )
                states.append(
                    cm.ControllerState(
                        name=name,
                        state=controller.state,
                        type=controller.type,
                        claimed_resources=resources,
                    )
                )
        return cm.ListControllers.Response(controller=states)

    def _types(self, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        types = list(controller_types())
        return cm.ListControllerTypes.Response(
            types=types, base_classes=["controller_interface::ControllerBase"] * len(types)
        )

    def _load(self, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        return cm.LoadController.Response(ok=self.run(lambda: self.load(request.name)))

    def _unload(self, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        return cm.UnloadController.Response(ok=self.run(lambda: self.unload(request.name)))

    def _switch_srv(self, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        ok = self.switch(
            list(request.start_controllers), list(request.stop_controllers), request.strictness
        )
        return cm.SwitchController.Response(ok=ok)

    def _reload(self, request: Any) -> Any:
        from workbench.msgs import controller_manager_msgs as cm

        with self.lock:
            loaded = list(self.controllers)
        if loaded and not request.force_kill:
            _LOG.error(
                "Controller manager: Cannot reload controller libraries because there are still "
                "%d controllers running",
                len(loaded),
            )
            return cm.ReloadControllerLibraries.Response(ok=False)
        self.switch([], loaded, BEST_EFFORT)
        ok = all(self.run(lambda name=name: self.unload(name)) for name in loaded)
        return cm.ReloadControllerLibraries.Response(ok=ok)
