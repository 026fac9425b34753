"""What reading a launch file produces: the nodes, tests, parameters and rosparam commands."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from workbench.bus.names import join


@dataclass
class NodeSpec:
    """One node to start (``<node>``).

    Attributes:
        env: ``<env>`` settings in effect for the node (launch, group, include, node level).
        launch_prefix: Words put before the node's command (``gdb -ex run --args``), or None.
        cwd: ``"node"`` (the node's package folder), ``"ROS_HOME"`` or None (the launching
            process's folder).
        machine: The ``<machine>`` it names (every machine workbench accepts is this one).
    """

    pkg: str
    type: str
    name: str
    namespace: str = "/"
    args: list[str] = field(default_factory=list)
    remaps: dict[str, str] = field(default_factory=dict)
    output: str = "log"
    respawn: bool = False
    respawn_delay: float = 0.0
    required: bool = False
    source: str = ""
    env: dict[str, str] = field(default_factory=dict)
    launch_prefix: str | None = None
    cwd: str | None = None
    machine: str | None = None

    @property
    def full_name(self) -> str:
        return join(self.namespace, self.name)


@dataclass
class TestSpec(NodeSpec):
    """A ``<test>`` (rostest's): listed in the plan, never started by ``workbench launch``.

    Attributes:
        test_name: Its ``test-name``.
        time_limit: Seconds rostest gives it (``time-limit``, 60 by default).
        retry: How often rostest retries it.
    """

    test_name: str = ""
    time_limit: float = 60.0
    retry: int = 0


@dataclass(frozen=True)
class RosparamCommand:
    """A ``<rosparam command="delete|dump">``: runs before the parameters are set, in order.

    Attributes:
        command: ``"delete"`` or ``"dump"``.
        param: The parameter (or namespace) it acts on.
        file: Where ``dump`` writes (None for ``delete``).
    """

    command: str
    param: str
    file: str | None = None


@dataclass(frozen=True)
class Deferred:
    """A value a dry run does not compute: a command's output or a file's contents."""

    kind: str  # "output of command", "contents of file"
    source: str

    def __repr__(self) -> str:
        return f"<{self.kind} {self.source!r}, not read in a dry run>"


@dataclass
class LaunchArg:
    """An ``<arg>`` of the top-level file, for ``--ros-args``.

    Attributes:
        default: Its ``default`` (None: it must be given, or it has a fixed ``value``).
        fixed: It has a ``value`` (not settable from the command line).
    """

    name: str
    doc: str | None = None
    default: str | None = None
    fixed: bool = False


@dataclass
class LaunchPlan:
    """Parameters to set, then nodes to start.

    Attributes:
        params: Global name -> value (a :class:`Deferred` in a dry run for ``command=``
            and ``textfile=``).
        nodes: In file order.
        tests: ``<test>`` elements, in file order (listed, not run).
        clear_params: Namespaces emptied before the parameters are set (``clear_params``).
        rosparam_commands: ``<rosparam command="delete|dump">``, in file order.
        rosparam_files: ``(namespace, file)`` of each ``<rosparam file=...>`` a dry run
            did not read.
        machines: ``<machine>`` name -> address (all of them this computer).
        args: The top-level file's ``<arg>`` declarations.
        warnings: What roslaunch would warn about (an unknown element ...), one line each.
    """

    params: dict[str, Any] = field(default_factory=dict)
    nodes: list[NodeSpec] = field(default_factory=list)
    tests: list[TestSpec] = field(default_factory=list)
    clear_params: list[str] = field(default_factory=list)
    rosparam_commands: list[RosparamCommand] = field(default_factory=list)
    rosparam_files: list[tuple[str, str]] = field(default_factory=list)
    machines: dict[str, str] = field(default_factory=dict)
    args: list[LaunchArg] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)

    @property
    def deletes(self) -> list[str]:
        """The parameters ``<rosparam command="delete">`` removes."""
        return [c.param for c in self.rosparam_commands if c.command == "delete"]
