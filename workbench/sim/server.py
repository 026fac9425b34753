"""The simulation server: one World stepped in a loop, Gazebo's ``gzserver``.

:class:`SimServer` owns a built :class:`~workbench.sim.World` and advances it,
paced to a real-time factor (or as fast as it can), pausable. Everything that
changes the world — spawning, deleting, moving models, applying wrenches, plugin
updates — runs on the loop's thread between physics steps: other threads hand
work over with :meth:`SimServer.call`. Hooks run after each advance (the Gazebo
ROS API publishes ``/clock`` and the model states from one; the live view
draws from another).

Example::

    world = World(**SERVER_PHYSICS)
    server = SimServer(world)
    server.spawn(load_sim_model("simple_box"), [0, 0, 1])
    server.run(until=2.0)
"""

from __future__ import annotations

import logging
import math
import queue
import threading
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures import Future
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from workbench.errors import SimulationError
from workbench.sim.model_spec import PluginSpec, SimModel
from workbench.sim.plugin_trust import PluginTrust
from workbench.sim.plugins import (
    Plugin,
    PluginSetupError,
    SdfElement,
    UnavailablePluginError,
    UpdateInfo,
    WorldPlugin,
    describe_failure,
    load_plugin_class,
)
from workbench.sim.request_limits import MAX_EFFORT, MAX_FORCE, MAX_TORQUE, out_of_bounds
from workbench.sim.scene import GROUND_NAME

_LOG = logging.getLogger("workbench.sim")

#: Physics of the server: Gazebo's 1 ms step (a world's ``<max_step_size>``
#: overrides it); point contact (Gazebo's kind; no hydroelastic properties to
#: write) with Drake's default "lagged" discrete solver (convex, stable at this
#: step; TAMSI is deprecated). Friction is 1.0 unless a model says otherwise
#: (Drake's parser default, and SDF's default ``<mu>``); the ground plane too.
#: Output ports are computed when asked, not sampled every step (10 % faster).
SERVER_PHYSICS: dict[str, Any] = {
    "time_step": 0.001,
    "physics": {
        "contact_model": "point",
        "discrete_contact_approximation": "lagged",
        "use_sampled_output_ports": False,
    },
}


#: How often the state is checked for NaN, simulated s (a blown-up state stays NaN).
_FINITE_CHECK_PERIOD = 0.05


@dataclass
class _PluginSlot:
    plugin: Plugin
    spec: PluginSpec
    model: str | None
    period: float
    next_update: float = 0.0
    last_update: float | None = None
    node: Any = None
    efforts: dict[tuple[str, str], float] = field(default_factory=dict)
    wrenches: list[tuple[Any, Any, Any]] = field(default_factory=list)


@dataclass
class _Job:
    """A wrench or effort the Gazebo API applies for a while (start and end in sim time)."""

    start: float
    end: float
    body: Any = None
    force: Any = None
    torque: Any = None
    joint: tuple[str, str] | None = None
    effort: float = 0.0


class SimServer:
    """Step a World in a loop and serialise every change to it.

    Args:
        world: The world; built here if it is not (with ``meshcat`` if given).
        bus: A ``workbench.bus.Bus`` for plugins' nodes (None: plugins get no node).
        paused: Start paused (Gazebo's ``-u``).
        real_time_factor: Target sim/wall speed ratio; ``0`` or ``inf``: as fast as possible.
        chunk: Simulated time advanced between hooks when nothing needs finer steps, s.
        allow_spawn_plugins: Let models spawned over the bus load any plugin file or
            declared class, not only those the world loaded (:mod:`workbench.sim.plugin_trust`).
    """

    def __init__(
        self,
        world: Any,
        *,
        bus: Any = None,
        paused: bool = False,
        real_time_factor: float = 1.0,
        chunk: float = 0.01,
        meshcat: Any = None,
        allow_spawn_plugins: bool = False,
    ) -> None:
        if not (real_time_factor >= 0):
            raise SimulationError(f"real_time_factor must be >= 0, got {real_time_factor}")
        self.world = world
        self.bus = bus
        world.build(meshcat)
        self.paused = paused
        self.real_time_factor = float(real_time_factor)
        self.chunk = float(chunk)
        self.hooks: list[Callable[[SimServer], None]] = []
        self.measured_rtf = 0.0
        self.error: str | None = None
        self._jobs: queue.SimpleQueue[tuple[Callable[[], Any], Future[Any]]] = queue.SimpleQueue()
        self._wake = threading.Event()
        self._stop = threading.Event()
        self._loop_thread: threading.Thread | None = None
        self._running_in: int | None = None
        self._plugins: list[_PluginSlot] = []
        self.plugin_trust = PluginTrust(allow_spawn_plugins=allow_spawn_plugins)
        self._api_jobs: list[_Job] = []
        self._pace_reset = True
        self._step_request = 0.0
        self._next_finite_check = 0.0
        self._failure_pause = False

    # --- threading -------------------------------------------------------------------

    def call(self, fn: Callable[[], Any], timeout: float | None = 60.0) -> Any:
        """Run ``fn()`` on the loop's thread between steps and return its result.

        Called from the loop's own thread, or when no loop runs, ``fn`` runs at once.
        """
        if self._running_in is None or self._running_in == threading.get_ident():
            return fn()
        future: Future[Any] = Future()
        self._jobs.put((fn, future))
        self._wake.set()
        return future.result(timeout=timeout)

    def start(self, until: float | None = None) -> None:
        """Run the loop in a background thread (see :meth:`run`).

        Raises:
            SimulationError: The world draws in a Meshcat: Drake's Meshcat may only be
                called from the thread that created it, so use :meth:`run` there.
        """
        if self._loop_thread is not None:
            return
        if self.world.meshcat is not None:
            raise SimulationError(
                "a server that draws in Meshcat must run in the thread that created the Meshcat",
                hint="call server.run() from that thread",
            )
        ready = threading.Event()

        def target() -> None:
            ready.set()
            self.run(until=until)

        self._loop_thread = threading.Thread(target=target, name="sim-loop", daemon=True)
        self._loop_thread.start()
        ready.wait()
        while self._running_in is None and self._loop_thread.is_alive():
            time.sleep(0.001)

    def stop(self) -> None:
        """Stop the loop (and wait for a background one); plugins are closed."""
        self._stop.set()
        self._wake.set()
        if self._loop_thread is not None and self._loop_thread is not threading.current_thread():
            self._loop_thread.join(timeout=30)
            self._loop_thread = None
        for slot in list(self._plugins):
            self._close_plugin(slot)
        self._plugins.clear()

    @property
    def running(self) -> bool:
        return self._running_in is not None

    def run(self, until: float | None = None, stop: threading.Event | None = None) -> None:
        """Step the world until ``until`` (sim s), :meth:`stop`, ``stop`` is set, or Ctrl-C."""
        self._running_in = threading.get_ident()
        self._stop.clear()
        try:
            while not self._stop.is_set() and not (stop is not None and stop.is_set()):
                self._run_jobs()
                if until is not None and self.world.time >= until - 1e-9:
                    break
                if until is not None and self.error is not None:
                    break  # the physics failed: a run to a time ends (error says why)
                if self.paused and self._step_request <= 0:
                    self._wake.wait(0.05)
                    self._wake.clear()
                    self._pace_reset = True
                    for hook in self.hooks:
                        hook(self)
                    continue
                self.step_once(until)
        finally:
            self._run_jobs()
            self._running_in = None

    # --- stepping --------------------------------------------------------------------

    def step_once(self, until: float | None = None) -> None:
        """Advance by one chunk: plugins, physics, timed wrenches, hooks, pacing."""
        world = self.world
        t = world.time
        self._update_plugins(t)
        self._apply_jobs(t)
        target = t + self._next_chunk(t)
        if until is not None:
            target = min(target, until)
        if self._step_request > 0:
            target = min(target, t + self._step_request)
        try:
            world.advance_to(target)
        except SimulationError as error:
            self._blow_up(_first_sentence(str(error.message)), until)
            return
        if not t < world.time < self._next_finite_check:  # due, or time went back
            if not world.state_is_finite():
                self._blow_up(f"the state became NaN or infinite at t={world.time:.4f} s", until)
                return
            self._next_finite_check = world.time + _FINITE_CHECK_PERIOD
        if self._step_request > 0:
            self._step_request = max(0.0, self._step_request - (world.time - t))
        for hook in self.hooks:
            hook(self)
        self._pace(world.time - t)

    def request_step(self, seconds: float) -> None:
        """Advance ``seconds`` of simulated time while paused (the view's Step button)."""
        self._step_request += max(0.0, float(seconds))
        self._wake.set()

    def _next_chunk(self, t: float) -> float:
        chunk = self.chunk
        step = self.world.time_step
        for slot in self._plugins:
            if not slot.plugin.active():
                continue
            due = step if slot.period <= 0 else max(slot.next_update - t, 0.5 * step)
            chunk = min(chunk, due)
        for job in self._api_jobs:
            for edge in (job.start, job.end):
                if edge > t + 1e-9:
                    chunk = min(chunk, edge - t)
        return max(chunk, self.world.time_step)

    def _pace(self, advanced: float) -> None:
        now = time.perf_counter()
        if self._pace_reset:
            self._wall0, self._sim0 = now, self.world.time - advanced
            self._rtf_wall, self._rtf_sim = now, self.world.time
            self._pace_reset = False
        if now - self._rtf_wall >= 1.0:
            self.measured_rtf = (self.world.time - self._rtf_sim) / (now - self._rtf_wall)
            self._rtf_wall, self._rtf_sim = now, self.world.time
        rtf = self.real_time_factor
        if rtf <= 0 or math.isinf(rtf):
            return
        ahead = (self.world.time - self._sim0) / rtf - (now - self._wall0)
        if ahead > 0:
            self._wake.wait(min(ahead, 0.1))
            self._wake.clear()
        elif ahead < -0.5:  # far behind: do not try to catch up in a burst
            self._pace_reset = True

    def _blow_up(self, why: str, until: float | None = None) -> None:
        model = _failed_model(self.world, why)
        self.error = f"{f'model {model!r}: ' if model else ''}{why}"
        self.paused = True
        self._failure_pause = True
        if until is None:  # a run to a time ends instead, and its caller reports the error
            _LOG.error(
                "simulation stopped: %s; paused (reset with /gazebo/reset_world or delete "
                "the model)",
                self.error,
            )

    def _run_jobs(self) -> None:
        while True:
            try:
                fn, future = self._jobs.get_nowait()
            except queue.Empty:
                return
            if not future.set_running_or_notify_cancel():
                continue
            try:
                future.set_result(fn())
            except BaseException as error:  # noqa: BLE001 - handed back to the caller
                future.set_exception(error)

    # --- models ----------------------------------------------------------------------

    def spawn(
        self,
        model: SimModel,
        X_WM: Any = None,
        *,
        joint_positions: Mapping[str, float] | None = None,
        from_bus: bool = False,
    ) -> None:
        """Add ``model`` (with its plugins) at ``X_WM``; the running world keeps going.

        Args:
            model: The model.
            X_WM: Where it goes (a RigidTransform, ``[x, y, z]`` or ``{"xyz", "rpy"}``).
            joint_positions: Initial joint positions, by joint name.
            from_bus: The model came in a spawn request: it may only use the plugins the
                world allowed (:mod:`workbench.sim.plugin_trust`).

        Raises:
            PluginRefusedError: ``from_bus`` and a plugin the world did not allow; nothing
                was added and nothing of the plugin was read.
        """
        if from_bus:
            for spec in model.plugins:
                refusal = self.plugin_trust.refusal(spec)
                if refusal is not None:
                    raise refusal

        def work() -> None:
            self.world.add_model(model, X_WM, joint_positions=joint_positions)
            if not model.static:
                self.world.lift_out_of_ground(model.name)
            for warning in model.warnings:
                _LOG.warning("%s", warning)
            self._after_rebuild()
            from workbench.sim.sensors.check import check_sensors

            bad = check_sensors(model)
            for spec in model.plugins:
                if spec.sensor and spec.sensor in bad:
                    continue  # the sensor's own error was logged; the model runs without it
                self.load_plugin(spec, model.name, spawned=from_bus)

        self.call(work)

    def delete(self, name: str) -> None:
        """Remove a model and its plugins."""

        def work() -> None:
            self.world.remove_model(name)
            for slot in [s for s in self._plugins if s.model == name]:
                self._close_plugin(slot)
                self._plugins.remove(slot)
            self._api_jobs = [j for j in self._api_jobs if not _belongs(j, name)]
            self._after_rebuild()

        self.call(work)

    def reset(self, *, time_too: bool) -> None:
        """Models back to their spawn poses (``time_too``: the clock back to 0 too)."""

        def work() -> None:
            self.world.reset(time=time_too)
            self._api_jobs.clear()
            self.error = None
            if self._failure_pause:  # paused by a failure, not by a user: run again
                self.paused = self._failure_pause = False
                self._wake.set()
            for slot in self._plugins:
                slot.next_update = self.world.time
                slot.last_update = None
                try:
                    slot.plugin.reset()
                except (Exception, SystemExit) as error:  # noqa: BLE001 - a plugin's failure
                    self._disable(slot, error, "reset")
            self._after_rebuild()

        self.call(work)

    def rebuilt(self) -> None:
        """Called after something rebuilt the world's diagram: plugins' forces go back on."""
        self._after_rebuild()

    def _after_rebuild(self) -> None:
        self._pace_reset = True
        self._push_forces()

    # --- plugins ---------------------------------------------------------------------

    def load_plugin(
        self, spec: PluginSpec, model: str | None = None, *, spawned: bool = False
    ) -> Plugin | None:
        """Load and start a plugin; failures are logged (file and line) and the plugin skipped.

        A plugin of the world (``spawned`` False) is allowed for spawned models from now on;
        one of a model spawned over the bus must be allowed already
        (:mod:`workbench.sim.plugin_trust`).
        """
        trust = self.plugin_trust
        try:
            source = trust.admit_spawned(spec) if spawned else trust.admit(spec)
            cls = load_plugin_class(spec, source)
        except SystemExit:  # a plugin file that exits at import must not end the server
            _LOG.error(
                "plugin '%s' (%s) called sys.exit while loading: not loaded",
                spec.name,
                spec.filename,
            )
            return None
        except UnavailablePluginError as error:
            owner = f"model '{model}': " if model else ""
            _LOG.warning("%s%s", owner, error.one_line())
            return None
        except SimulationError as error:
            _LOG.error("%s", error)
            return None
        try:
            plugin = cls()
        except (Exception, SystemExit) as error:  # noqa: BLE001 - a plugin's failure
            reason = f"{type(error).__name__}: {error}"
            _LOG.error(
                "plugin '%s' (%s) failed while starting: %s", spec.name, spec.filename, reason
            )
            return None
        sdf = SdfElement(spec.element, spec.sensor, spec.reference)
        rate = sdf.get("update_rate", float(getattr(plugin, "update_rate", 0.0) or 0.0))
        period = 1.0 / rate if rate and rate > 0 else 0.0
        slot = _PluginSlot(plugin, spec, model, period, next_update=self.world.time)
        if self.bus is not None:
            from workbench.bus import Node

            slot.node = Node(
                f"gazebo_plugin_{spec.name or cls.__name__}", bus=self.bus, anonymous=True
            )
        from workbench.sim.handles import ModelHandle, WorldHandle

        try:
            if isinstance(plugin, WorldPlugin):
                plugin.load(WorldHandle(self, slot), sdf, slot.node)
            else:
                if model is None:
                    raise SimulationError(
                        f"plugin '{spec.name}' is a model plugin but was given no model",
                        hint="attach it in a <model> or URDF <gazebo> block, or --plugin MODEL=FILE",
                    )
                plugin.load(ModelHandle(self, model, slot), sdf, slot.node)  # type: ignore[attr-defined]
        except PluginSetupError as error:  # a plugin's own one-line refusal
            owner = f"model '{model}': " if model else ""
            _LOG.error("%splugin '%s' not loaded: %s", owner, spec.name, error.one_line())
            self._close_plugin(slot)
            return None
        except (Exception, SystemExit) as error:  # noqa: BLE001 - a plugin's failure
            self._disable(slot, error, "load")
            return None
        own_rate = float(getattr(plugin, "update_rate", 0.0) or 0.0)
        if not sdf.has("update_rate") and own_rate > 0:  # set by the plugin in load()
            slot.period = 1.0 / own_rate
        self._plugins.append(slot)
        _LOG.info("loaded plugin '%s' (%s)", spec.name, spec.filename)
        return plugin

    @property
    def plugins(self) -> list[Plugin]:
        """The running plugins."""
        return [slot.plugin for slot in self._plugins]

    def plugin_labels(self) -> list[str]:
        """``name (filename)`` of each running plugin, with its model."""
        return [
            f"{slot.spec.name} ({slot.spec.filename}{', model ' + slot.model if slot.model else ''})"
            for slot in self._plugins
        ]

    def set_plugin_effort(self, owner: Any, key: tuple[str, str], effort: float) -> None:
        """Set a joint effort ``{(model, joint): effort}`` until ``owner``'s next update."""
        _check_plugin_numbers([(f"effort on joint '{key[1]}'", effort)], MAX_EFFORT, "N m or N")
        owner.efforts[key] = effort
        self._push_forces()

    def set_plugin_efforts(self, owner: Any, efforts: Mapping[tuple[str, str], float]) -> None:
        """Set several joint efforts ``{(model, joint): effort}`` until ``owner``'s next update."""
        _check_plugin_numbers(
            [(f"effort on joint '{joint}'", value) for (_, joint), value in efforts.items()],
            MAX_EFFORT,
            "N m or N",
        )
        owner.efforts.update(efforts)
        self._push_forces()

    def set_plugin_wrench(self, owner: Any, body: str, force: Any, torque: Any) -> None:
        """Add a wrench on ``body`` (scoped ``model::link``) until ``owner``'s next update."""
        force, torque = np.asarray(force, float).reshape(3), np.asarray(torque, float).reshape(3)
        what = f"wrench on '{body}':"
        _check_plugin_numbers(_named("force", force), MAX_FORCE, "N", what)
        _check_plugin_numbers(_named("torque", torque), MAX_TORQUE, "N m", what)
        owner.wrenches.append((body, force, torque))
        self._push_forces()

    def _update_plugins(self, t: float) -> None:
        half_step = 0.5 * self.world.time_step
        for slot in list(self._plugins):
            if t < slot.next_update - half_step:
                continue
            if not slot.plugin.active():
                self._schedule(slot, t)
                continue
            dt = 0.0 if slot.last_update is None else t - slot.last_update
            slot.efforts.clear()
            slot.wrenches.clear()
            try:
                slot.plugin.update(UpdateInfo(t, dt))
            except (Exception, SystemExit) as error:  # noqa: BLE001 - a plugin's failure
                self._disable(slot, error, "update")
                continue
            slot.last_update = t
            self._schedule(slot, t)

    def _schedule(self, slot: _PluginSlot, t: float) -> None:
        """The next update on the plugin's own grid of periods (so that with steps coarser
        than its period it still updates at its rate on average); from ``t`` after a gap."""
        if slot.period <= 0:
            slot.next_update = t + self.world.time_step
            return
        due = slot.next_update + slot.period
        slot.next_update = due if due > t else t + slot.period

    def _disable(self, slot: _PluginSlot, error: BaseException, during: str) -> None:
        where = describe_failure(error, slot.plugin)
        _LOG.error("plugin '%s' failed in %s and is disabled: %s", slot.spec.name, during, where)
        if slot in self._plugins:
            self._plugins.remove(slot)
        self._close_plugin(slot)
        self._push_forces()

    def _close_plugin(self, slot: _PluginSlot) -> None:
        try:
            slot.plugin.close()
        except (Exception, SystemExit) as error:  # noqa: BLE001 - a plugin's failure
            _LOG.warning("plugin '%s' failed while closing: %s", slot.spec.name, error)
        if slot.node is not None:
            slot.node.shutdown()
            slot.node = None

    # --- forces from the API and plugins ---------------------------------------------

    def apply_body_wrench(
        self,
        body_name: str,
        force: Sequence[float] | np.ndarray,
        torque: Sequence[float] | np.ndarray,
        start: float,
        duration: float,
    ) -> None:
        """Apply a wrench (W, at the link origin) from ``start`` for ``duration`` s (< 0: forever)."""

        def work() -> None:
            body = self._scoped(body_name)
            begin = max(start, self.world.time)
            # Gazebo applies it in every update with time <= start + duration (both ends).
            end = math.inf if duration < 0 else begin + duration + 0.5 * self.world.time_step
            self._api_jobs.append(
                _Job(
                    begin,
                    end,
                    body=body,
                    force=np.asarray(force, float),
                    torque=np.asarray(torque, float),
                )
            )
            self._push_forces()

        self.call(work)

    def apply_joint_effort(
        self, joint_name: str, effort: float, start: float, duration: float
    ) -> None:
        """Apply ``effort`` on the joint named so in any model from ``start`` for ``duration`` s."""

        def work() -> None:
            owner = self.joint_owner(joint_name)
            joint = joint_name.rpartition("::")[2]
            if self.world.joint(owner, joint).num_velocities() != 1:  # a free body's own joint
                raise SimulationError(f"joint '{joint_name}' is not a 1-dof joint")
            begin = max(start, self.world.time)
            # Gazebo applies it in every update with time <= start + duration (both ends).
            end = math.inf if duration < 0 else begin + duration + 0.5 * self.world.time_step
            self._api_jobs.append(_Job(begin, end, joint=(owner, joint), effort=float(effort)))
            self._push_forces()

        self.call(work)

    def clear_jobs(self, *, body: str | None = None, joint: str | None = None) -> None:
        """Drop the API's wrenches on ``body`` or efforts on ``joint`` (Gazebo's clear_* services)."""

        def work() -> None:
            def keep(job: _Job) -> bool:
                if body is not None and job.body is not None:
                    return job.body != body and job.body.rpartition("::")[2] != body
                if joint is not None and job.joint is not None:
                    return job.joint[1] != joint.rpartition("::")[2]
                return True

            self._api_jobs = [j for j in self._api_jobs if keep(j)]
            self._push_forces()

        self.call(work)

    def wake(self) -> None:
        """Make a waiting loop look at its state now (after unpausing)."""
        self._pace_reset = True
        self._wake.set()

    def _scoped(self, body_name: str) -> str:
        body = self.world.body(body_name)
        instance_name = self.world.plant.GetModelInstanceName(body.model_instance())
        from workbench.model.sdf_names import scoped

        return scoped(instance_name, body.name())

    def joint_owner(self, joint_name: str) -> str:
        """The model that has the joint ``joint_name`` (``model::joint`` or a bare name).

        Raises:
            SimulationError: No model has it.
        """
        plant = self.world.plant
        model, _, joint = joint_name.rpartition("::")
        names = [model] if model else [n for n in self.world.model_names() if n != "ground_plane"]
        for name in names:
            from workbench.model.sdf_names import drake_joint

            if drake_joint(plant, joint or joint_name, self.world.model_instance(name)):
                return name
        raise SimulationError(f"joint '{joint_name}' not found")

    def _apply_jobs(self, t: float) -> None:
        before = len(self._api_jobs)
        self._api_jobs = [j for j in self._api_jobs if j.end > t + 1e-12]
        if len(self._api_jobs) != before or any(abs(j.start - t) < 1e-9 for j in self._api_jobs):
            self._push_forces()

    def _push_forces(self) -> None:
        t = self.world.time
        wrenches: list[tuple[Any, Any, Any]] = []
        efforts: dict[tuple[str, str], float] = {}
        for job in self._api_jobs:
            if not (job.start <= t + 1e-9 < job.end):
                continue
            if job.body is not None:
                wrenches.append((job.body, job.force, job.torque))
            elif job.joint is not None:
                efforts[job.joint] = efforts.get(job.joint, 0.0) + job.effort
        for slot in self._plugins:
            wrenches += slot.wrenches
            for key, value in slot.efforts.items():
                efforts[key] = efforts.get(key, 0.0) + value
        names = set(self.world.model_names())
        resolved = []
        for scoped, force, torque in wrenches:
            if scoped.rpartition("::")[0] in names:
                resolved.append((self.world.body(scoped), force, torque))
        self.world.set_body_wrenches(resolved)
        self.world.set_joint_efforts({k: v for k, v in efforts.items() if k[0] in names})


def _named(name: str, vector: np.ndarray) -> list[tuple[str, float]]:
    return [(f"{name}.{axis}", float(v)) for axis, v in zip("xyz", vector, strict=True)]


def _check_plugin_numbers(
    values: Iterable[tuple[str, float]], limit: float, unit: str, what: str = ""
) -> None:
    """Raise (into the plugin, which is then disabled) for a NaN, infinite or huge value."""
    reason = out_of_bounds(values, limit, unit)
    if reason is not None:
        raise SimulationError(f"{what + ' ' if what else ''}{reason}")


def _first_sentence(text: str) -> str:
    """Drake's failure messages go on with advice for C++ users: their first sentence, one line."""
    line = " ".join(text.split())
    head, dot, _ = line.partition(". ")
    return head + dot.strip()


def _failed_model(world: Any, why: str) -> str | None:
    """The model that failed: the first with a NaN or infinite state, else one whose body
    Drake's message names, else the one whose position or speed is the largest (a solver
    that did not converge names nothing; the model pushed or thrown furthest is the one a
    request or plugin drove there). None: no model moves."""
    try:
        plant = world.plant
        context = plant.GetMyContextFromRoot(world.context)
        names = [n for n in world.model_names() if n != GROUND_NAME]
        states = {
            name: plant.GetPositionsAndVelocities(context, world.model_instance(name))
            for name in names
        }
        for name, state in states.items():
            if not np.all(np.isfinite(state)):
                return str(name)
        for name in names:
            for index in plant.GetBodyIndices(world.model_instance(name)):
                if f"body {plant.get_body(index).name()} " in why + " ":
                    return str(name)
        largest = {name: float(np.max(np.abs(s))) for name, s in states.items() if s.size}
        if largest:
            return str(max(largest, key=lambda name: largest[name]))
    except (RuntimeError, SimulationError):  # a world Drake could not even evaluate
        return None
    return None


def _belongs(job: _Job, model: str) -> bool:
    if job.joint is not None:
        return job.joint[0] == model
    return str(job.body).rpartition("::")[0] == model
