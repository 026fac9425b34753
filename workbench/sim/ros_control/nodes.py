"""``controller_manager``'s nodes: ``spawner`` and the ``controller_manager`` command.

``workbench run controller_manager spawner [--stopped] [--namespace NS] [--timeout T]
[--no-timeout] [--wait-for TOPIC] NAME_OR_YAML...`` does what controller_manager's
spawner script does: it waits for ``<NS>/controller_manager/{load,switch,unload}_controller``
(30 s by default, longer while a simulation that has not started its clock is coming
up), loads each controller (a YAML file's contents are put on the parameter server
first and its top-level keys are the names), starts them all together (STRICT) unless
``--stopped``, and stays until it is shut down, when it stops and unloads what it loaded.

``workbench run controller_manager controller_manager COMMAND [NAME...]`` is the
command-line tool: ``load``, ``unload``, ``start``, ``stop``, ``spawn`` (load + start),
``kill`` (stop + unload), ``list`` (``lc``), ``list-types`` (``lt``) and
``reload-libraries``, with the tool's messages.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from collections.abc import Sequence
from typing import Any

from workbench.errors import WorkbenchError

USAGE = """Commands:
    load <name>          - Load the controller named <name>
    unload <name>        - Unload the controller named <name>
    start <name>         - Start the controller named <name>
    stop <name>          - Stop the controller named <name>
    spawn <name>         - Load and start the controller named <name>
    kill <name>          - Stop and unload the controller named <name>
    list                 - List active controllers
    list-types           - List controller Types
    reload-libraries     - Reloads all plugin controller libraries"""


def _spawner_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="spawner", description="Controller spawner")
    parser.add_argument("--stopped", action="store_true", help="load, but do not start")
    parser.add_argument("--wait-for", metavar="topic", help="wait for True (std_msgs/Bool) on it")
    parser.add_argument("--namespace", metavar="ns", help="namespace of the controller_manager")
    parser.add_argument("--timeout", metavar="T", type=float, default=30.0)
    parser.add_argument("--no-timeout", action="store_true")
    parser.add_argument("--shutdown-timeout", help="no effect (deprecated in ros_control too)")
    parser.add_argument("controllers", metavar="controller", nargs="+")
    return parser


def spawner(argv: Sequence[str] | None = None) -> int:
    """The ``spawner`` node (see the module docstring); 0, or 1 for bad arguments."""
    from workbench.bus import Node

    raw = list(sys.argv[1:] if argv is None else argv)
    node = Node("spawner", argv=raw, anonymous=True)
    try:
        try:
            args = _spawner_parser().parse_args(node.argv)
        except SystemExit as exit_:
            return int(exit_.code or 0)
        Spawner(node, args).run()
        return 0
    except WorkbenchError as error:
        print(f"[ERROR] spawner: {error}", file=sys.stderr)
        return 1
    finally:
        node.bus.shutdown("spawner done")


class Spawner:
    """What one ``spawner`` does on ``node``."""

    def __init__(self, node: Any, args: argparse.Namespace) -> None:
        self.node = node
        self.args = args
        prefix = args.namespace or ""
        if prefix and not prefix.endswith("/"):
            prefix += "/"
        self.prefix = prefix
        self.loaded: list[str] = []
        self.clients: dict[str, Any] = {}

    def _client(self, service: str, kind: Any) -> Any:
        return self.node.create_client(f"{self.prefix}controller_manager/{service}", kind)

    def run(self, spin: bool = True) -> None:
        """Wait, load, start; then (``spin``) stay until the bus shuts down."""
        from workbench.msgs import controller_manager_msgs as cm

        timeout = None if self.args.no_timeout or self.args.timeout <= 0 else self.args.timeout
        clients = {
            name: self._client(name, kind)
            for name, kind in (
                ("load_controller", cm.LoadController),
                ("switch_controller", cm.SwitchController),
                ("unload_controller", cm.UnloadController),
            )
        }
        if not self._wait(clients, timeout):
            return
        if self.args.wait_for and not self._wait_for_topic(self.args.wait_for, timeout):
            return
        self.clients = clients
        self.node.on_shutdown(lambda *_: self.take_down())
        for name in self._names():
            self._log(f"Loading controller: {name}")
            if clients["load_controller"].call(cm.LoadController.Request(name=name)).ok:
                self.loaded.append(name)
            else:
                self._log(f"Failed to load {name}", error=True)
        self._log("Controller Spawner: Loaded controllers: " + ", ".join(self.loaded))
        if not self.args.stopped:
            request = cm.SwitchController.Request(
                start_controllers=list(self.loaded), strictness=cm.SwitchController.Request.STRICT
            )
            if clients["switch_controller"].call(request).ok:
                self._log("Started controllers: " + ", ".join(self.loaded))
            else:
                self._log("Failed to start controllers: " + ", ".join(self.loaded), error=True)
        if spin:
            self.node.bus.spin()

    def _wait(self, clients: dict[str, Any], timeout: float | None) -> bool:
        from workbench.bus.errors import ServiceTimeout

        while True:
            try:
                for client in clients.values():
                    self._log(f"Controller Spawner: Waiting for service {client.name}")
                    client.wait_for_service(timeout=timeout)
                return True
            except ServiceTimeout:
                sim_time = self.node.get_param("/use_sim_time", False) is True
                if sim_time and self.node.now().to_nsec() == 0:
                    self._log("Waiting for /clock to be available...")
                    continue
                self._log(
                    "Controller Spawner couldn't find the expected controller_manager ROS "
                    "interface.",
                    error=True,
                )
                return False

    def _wait_for_topic(self, topic: str, timeout: float | None) -> bool:
        heard: list[Any] = []
        self.node.create_subscription(topic, "std_msgs/Bool", heard.append, 1, inline=True)
        start = time.monotonic()
        warned = False
        while not (heard and heard[-1].data):
            if self.node.bus.is_shutdown:
                return False
            if not warned and not heard and timeout and time.monotonic() - start > timeout:
                warned = True
                self._log(
                    f'Controller Spawner hasn\'t heard anything from its "wait for" topic ({topic})',
                    error=True,
                )
            time.sleep(0.01)
        return True

    def _names(self) -> list[str]:
        names: list[str] = []
        for name in self.args.controllers:
            if os.path.exists(name):
                from workbench.limits import load_yaml_file

                values = load_yaml_file(name, "controller configuration")
                if isinstance(values, dict):
                    for key, value in values.items():
                        self.node.set_param(str(key), value)
                        names.append(str(key))
            else:
                names.append(name)
        return names

    def take_down(self) -> None:
        """Stop and unload the controllers this spawner loaded (its shutdown)."""
        from workbench.msgs import controller_manager_msgs as cm

        clients = self.clients
        if not self.loaded:
            return
        self._log("Shutting down spawner. Stopping and unloading controllers...")
        try:
            clients["switch_controller"].call(
                cm.SwitchController.Request(
                    stop_controllers=list(self.loaded),
                    strictness=cm.SwitchController.Request.STRICT,
                ),
                timeout=2.0,
            )
            for name in reversed(self.loaded):
                clients["unload_controller"].call(
                    cm.UnloadController.Request(name=name), timeout=2.0
                )
        except WorkbenchError as error:
            self._log(
                f"Controller Spawner error while taking down controllers: {error}", error=True
            )

    def _log(self, text: str, error: bool = False) -> None:
        print(
            f"[{'WARN' if error else 'INFO'}] {text}",
            file=sys.stderr if error else sys.stdout,
            flush=True,
        )


def controller_manager(argv: Sequence[str] | None = None) -> int:
    """The ``controller_manager`` command (see the module docstring)."""
    from workbench.bus import Node

    raw = list(sys.argv[1:] if argv is None else argv)
    node = Node("controller_manager", argv=raw, anonymous=True)
    try:
        args = node.argv
        if not args:
            print(USAGE)
            return 0
        return _command(node, args[0], args[1:])
    except WorkbenchError as error:
        print(f"[ERROR] controller_manager: {error}", file=sys.stderr)
        return 1
    finally:
        node.bus.shutdown("controller_manager done")


def _command(node: Any, command: str, names: list[str]) -> int:
    from workbench.msgs import controller_manager_msgs as cm

    def call(service: str, kind: Any, request: Any) -> Any:
        client = node.create_client(f"controller_manager/{service}", kind)
        client.wait_for_service()
        return client.call(request)

    def switch(start: list[str], stop: list[str]) -> bool:
        ok = call(
            "switch_controller",
            cm.SwitchController,
            cm.SwitchController.Request(
                start_controllers=start,
                stop_controllers=stop,
                strictness=cm.SwitchController.Request.STRICT,
            ),
        ).ok
        if ok:
            if start:
                print(f"Started {start} successfully")
            if stop:
                print(f"Stopped {stop} successfully")
        else:
            print(f"Error when starting {start} and stopping {stop}")
        return bool(ok)

    def load(name: str) -> bool:
        ok = call("load_controller", cm.LoadController, cm.LoadController.Request(name=name)).ok
        print(f"Loaded '{name}'" if ok else f"Error when loading '{name}'")
        return bool(ok)

    def unload(name: str) -> bool:
        ok = call(
            "unload_controller", cm.UnloadController, cm.UnloadController.Request(name=name)
        ).ok
        print(f"Unloaded '{name}' successfully" if ok else f"Error when unloading '{name}'")
        return bool(ok)

    results: list[bool] = []
    if command in ("lt", "list-types"):
        for kind in call(
            "list_controller_types", cm.ListControllerTypes, cm.ListControllerTypes.Request()
        ).types:
            print(kind)
    elif command in ("lc", "list"):
        states = call(
            "list_controllers", cm.ListControllers, cm.ListControllers.Request()
        ).controller
        if not states:
            print("No controllers are loaded in mechanism control")
        for state in states:
            interfaces = sorted({r.hardware_interface for r in state.claimed_resources})
            print(f"'{state.name}' - '{'+'.join(interfaces)}' ( {state.state} )")
    elif command == "reload-libraries":
        ok = call(
            "reload_controller_libraries",
            cm.ReloadControllerLibraries,
            cm.ReloadControllerLibraries.Request(force_kill=True),
        ).ok
        print(
            "Successfully reloaded libraries"
            if ok
            else "Failed to reload libraries. Do you still have controllers loaded?"
        )
        results.append(bool(ok))
    elif command == "load":
        results = [load(n) for n in names]
    elif command == "unload":
        results = [unload(n) for n in names]
    elif command == "start":
        results = [switch([n], []) for n in names]
    elif command == "stop":
        results = [switch([], [n]) for n in names]
    elif command in ("sp", "spawn"):
        results = [load(n) for n in names] + [switch([n], []) for n in names]
    elif command in ("kl", "kill"):
        results = [switch([], [n]) for n in names] + [unload(n) for n in names]
    else:
        print(USAGE)
        return 1
    return 0 if all(results) else 1
