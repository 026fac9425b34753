"""Running nodes: ``workbench run`` (one node, in this process) and launch plans (many processes).

A node is either a declared entry point (:mod:`workbench.entry_points`) or
a Python script, found by its type name in the working directory, its
``scripts/`` folder, the launch file's package, or the checkout's
``examples/`` (where the lab's own scripts live).
"""

from __future__ import annotations

import contextlib
import os
import runpy
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from workbench.bus.launch import LaunchError, LaunchPlan, NodeSpec, find_package
from workbench.entry_points import call_node, find_node, unknown_node
from workbench.errors import BusError

if TYPE_CHECKING:
    from workbench.bus.bus import Bus
    from workbench.bus.core import Core


def find_script(pkg: str, node_type: str, near: Path | None = None) -> Path | None:
    """A script named ``node_type`` for package ``pkg``, or None."""
    from workbench.paths import project_root

    direct = Path(node_type)
    if direct.suffix == ".py" and direct.is_file():
        return direct.resolve()
    places: list[Path] = []
    for base in [near, Path.cwd()]:
        if base is not None:
            places += [base, base / "scripts", base / pkg / "scripts", base / pkg]
            places += [base.parent / "scripts", base.parent]
    try:
        package_dir = find_package(pkg, near)
        places += [package_dir / "scripts", package_dir, package_dir / "src"]
    except BusError:
        pass
    examples = project_root() / "examples"
    places.append(examples)
    if examples.is_dir():
        places += sorted(p for p in examples.iterdir() if p.is_dir())
    for place in places:
        for name in (node_type, f"{node_type}.py"):
            candidate = place / name
            if candidate.is_file() and candidate.suffix == ".py":
                return candidate.resolve()
    return None


def run_node(pkg: str, node_type: str, argv: list[str], near: Path | None = None) -> int:
    """Run one node in this process (``workbench run``); returns its exit status.

    A declared node (entry point) wins over a script of the same name.

    Raises:
        UnknownNodeError: Neither a declared node nor a script of that name exists.
    """
    target = find_node(pkg, node_type)
    if target is not None:
        return call_node(target, list(argv))
    return run_script_node(pkg, node_type, argv, near)


def run_script_node(pkg: str, node_type: str, argv: list[str], near: Path | None = None) -> int:
    """Run the script that plays node ``pkg/node_type`` (no entry point declares it).

    Raises:
        UnknownNodeError: No script of that name is found (the message lists the known nodes).
    """
    script = find_script(pkg, node_type, near)
    if script is None:
        raise unknown_node(pkg, node_type, scripts=True)
    return run_script(script, argv)


def run_script(script: Path, argv: list[str]) -> int:
    """Run a Python script as ``__main__`` with ``argv`` (like ``python script args``)."""
    saved_argv, saved_path = sys.argv, list(sys.path)
    sys.argv = [str(script), *argv]
    sys.path.insert(0, str(script.parent))
    try:
        runpy.run_path(str(script), run_name="__main__")
    except SystemExit as done:
        code = done.code
        return code if isinstance(code, int) else (0 if code is None else 1)
    finally:
        sys.argv, sys.path[:] = saved_argv, saved_path
    return 0


#: Set in the environment of every process a launch starts.
LAUNCHED_ENV = "WORKBENCH_LAUNCHED"


def launch_prefix(spec: NodeSpec) -> list[str]:
    """The words of a node's ``launch-prefix`` (``gdb -ex run --args``), put before its command.

    Raises:
        LaunchError: Words that cannot be split, or a program that is not installed.
    """
    if not spec.launch_prefix:
        return []
    try:
        words = shlex.split(spec.launch_prefix)
    except ValueError as error:
        raise LaunchError(
            f"node {spec.full_name}: launch-prefix {spec.launch_prefix!r} cannot be split "
            f"({error})",
            path=spec.source,
        ) from None
    if words and shutil.which(words[0]) is None:
        raise LaunchError(
            f"node {spec.full_name}: launch-prefix program '{words[0]}' is not installed",
            path=spec.source,
            hint="install it, or remove launch-prefix",
        )
    return words


def working_directory(spec: NodeSpec, near: Path | None) -> Path | None:
    """Where a node runs: ``cwd="ROS_HOME"`` in ``$ROS_HOME`` (``~/.ros``), ``cwd="node"``
    in its script's or package's folder, else where ``workbench launch`` runs."""
    if spec.cwd == "ROS_HOME":
        home = Path(os.environ.get("ROS_HOME") or Path.home() / ".ros")
        home.mkdir(parents=True, exist_ok=True)
        return home
    if spec.cwd == "node":
        script = find_script(spec.pkg, spec.type, near)
        if script is not None:
            return script.parent
        try:
            return find_package(spec.pkg, near)
        except BusError:
            return None
    return None


def _dump(bus: Bus, param: str, file: Path) -> None:
    """``<rosparam command="dump">``: the parameters under ``param`` into ``file`` as YAML."""
    import yaml

    if not bus.params.has(param):
        print(f"rosparam dump: no parameter {param}; {file} not written", flush=True)
        return
    try:
        file.write_text(yaml.safe_dump(bus.params.get(param), default_flow_style=False))
    except OSError as error:
        raise LaunchError(
            f"rosparam dump of {param}: cannot write {file}: {error.strerror or error}"
        ) from None


@dataclass
class _Process:
    spec: NodeSpec
    index: int
    popen: subprocess.Popen | None = None
    log: Path | None = None
    starts: int = 0

    @property
    def label(self) -> str:
        return f"{self.spec.name}-{self.index}"


class Launcher:
    """Starts a core (if none is reachable) and the nodes of a plan as child processes.

    Args:
        plan: What to start.
        uri: The core's address (default ``WORKBENCH_MASTER_URI``).
        near: The launch file's folder (scripts are looked for near it).
        log_dir: Where nodes without ``output="screen"`` write (default: a temp folder).
    """

    def __init__(
        self,
        plan: LaunchPlan,
        uri: str | None = None,
        near: Path | None = None,
        log_dir: Path | None = None,
    ) -> None:
        from workbench.bus.bus import master_uri

        self.plan = plan
        self.uri = uri or master_uri()
        self.near = near
        self.log_dir = log_dir or Path(tempfile.mkdtemp(prefix="workbench-launch-"))
        self.core: Core | None = None
        self.bus: Bus | None = None
        self.processes = [_Process(spec, i + 1) for i, spec in enumerate(plan.nodes)]
        self._stopping = False

    def start(self) -> None:
        """Start (or find) the core, run the rosparam commands, clear and set the parameters,
        start every node.

        Raises:
            LaunchError: A node's launch-prefix names a program that is not installed.
        """
        for spec in self.plan.nodes:
            launch_prefix(spec)
        from workbench.bus.bus import Bus
        from workbench.bus.core import Core
        from workbench.bus.zconfig import parse_uri, port_open

        _proto, host, port = parse_uri(self.uri)
        if port_open(host, port):
            print(f"using the core at {self.uri}", flush=True)
        else:
            self.core = Core(self.uri)
            print(f"started core service [{self.uri}]", flush=True)
        self.bus = bus = Bus.connect(self.uri)
        for command in self.plan.rosparam_commands:  # roslaunch runs these first
            if command.command == "delete":
                if bus.params.has(command.param):
                    bus.params.delete(command.param)
            elif command.file is not None:
                _dump(bus, command.param, Path(command.file))
        for namespace in self.plan.clear_params:
            if bus.params.has(namespace):
                bus.params.delete(namespace)
        for name, value in self.plan.params.items():
            bus.params.set(name, value)
        if self.plan.params:
            print("PARAMETERS", flush=True)
            for name in sorted(self.plan.params):
                print(f" * {name}", flush=True)
        print("NODES", flush=True)
        for process in self.processes:
            print(
                f"    {process.spec.full_name} ({process.spec.pkg}/{process.spec.type})", flush=True
            )
        for test in self.plan.tests:
            print(f"test {test.full_name} is not run (rostest runs tests)", flush=True)
        for process in self.processes:
            self._spawn(process)

    def _command(self, spec: NodeSpec) -> list[str]:
        command = launch_prefix(spec) + [sys.executable, "-m", "workbench", "run"]
        if self.near is not None:
            command += ["--near", str(self.near)]
        command += [spec.pkg, spec.type, *spec.args, f"__name:={spec.name}"]
        if spec.namespace != "/":
            command.append(f"__ns:={spec.namespace}")
        command += [f"{src}:={dst}" for src, dst in spec.remaps.items()]
        return command

    def _spawn(self, process: _Process) -> None:
        spec = process.spec
        env = dict(os.environ, **spec.env)
        env.update(WORKBENCH_MASTER_URI=self.uri, PYTHONUNBUFFERED="1")
        env[LAUNCHED_ENV] = "1"  # Ctrl-C reaches it twice (terminal and launcher): expected
        if spec.output == "screen":
            stdout = stderr = None
        else:
            process.log = self.log_dir / f"{process.label}.log"
            stdout = stderr = open(process.log, "ab")  # noqa: SIM115 - handed to the child
        process.popen = subprocess.Popen(
            self._command(spec),
            env=env,
            stdout=stdout,
            stderr=stderr,
            cwd=working_directory(spec, self.near),
        )
        process.starts += 1
        where = "" if process.log is None else f" (log: {process.log})"
        print(
            f"process[{process.label}]: started with pid [{process.popen.pid}]{where}", flush=True
        )

    def poll(self) -> bool:
        """Check the children once: respawn, or stop all if a required one ended.

        Returns:
            Whether anything is still running.
        """
        alive = False
        for process in self.processes:
            popen = process.popen
            if popen is None:
                continue
            code = popen.poll()
            if code is None:
                alive = True
                continue
            process.popen = None
            if self._stopping:
                continue
            if code == 0:
                print(f"[{process.label}] process has finished cleanly", flush=True)
            else:
                print(
                    f"[{process.label}] process has died [pid {popen.pid}, exit code {code}]",
                    flush=True,
                )
            if process.spec.required:
                print(f"[{process.label}] required node ended; shutting down", flush=True)
                self.shutdown()
                return False
            if process.spec.respawn:
                time.sleep(process.spec.respawn_delay)
                self._spawn(process)
                alive = True
        return alive

    def wait(self) -> None:
        """Block until every node has ended (Ctrl-C: shut them all down)."""
        try:
            while self.poll():
                time.sleep(0.1)
        except KeyboardInterrupt:
            pass
        finally:
            self.shutdown()

    def shutdown(self, grace: float = 5.0) -> None:
        """Stop every node (SIGINT, then SIGTERM, then SIGKILL) and the core if we started it."""
        self._stopping = True
        running = [
            p.popen for p in self.processes if p.popen is not None and p.popen.poll() is None
        ]
        for popen in running:
            with contextlib.suppress(OSError):
                popen.send_signal(signal.SIGINT)
        deadline = time.monotonic() + grace
        for popen in running:
            try:
                popen.wait(max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                popen.terminate()
                try:
                    popen.wait(2.0)
                except subprocess.TimeoutExpired:
                    popen.kill()
                    popen.wait()
        for process in self.processes:
            process.popen = None
        if self.bus is not None:
            self.bus.shutdown()
            self.bus = None
        if self.core is not None:
            self.core.close()
            self.core = None
            print("shutting down core service", flush=True)
