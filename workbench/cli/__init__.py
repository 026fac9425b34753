"""The ``workbench`` command line.

The top level knows only the command names and one-line helps, so
``workbench --help`` starts instantly. A command lives in its own module
``workbench.cli.<name>`` that defines::

    def configure(parser: argparse.ArgumentParser) -> None: ...
    def run(args: argparse.Namespace) -> int: ...

and imports anything heavy (pydrake, ompl, zenoh) inside ``run``. ``run`` only
unpacks the options and calls typed functions of the same module (``plan(robot,
goal, ...)``), which tests call directly and which check cheap things (syntax,
names, numbers, files) before loading anything heavy. Errors derived from
:class:`~workbench.errors.WorkbenchError` are printed as one line on stderr with
a non-zero exit status; ``workbench --debug COMMAND ...`` (or ``WORKBENCH_DEBUG=1``)
shows the traceback instead. Anything else a command raises is a bug, not bad input:
it is reported as one line naming the command and its arguments, asking to report
it, with exit status 70 (the traceback again only under ``--debug``).
SIGINT and SIGTERM unwind a command as Ctrl-C does (its ``finally`` blocks run),
also in a background job, and it exits with 130 or 143 (see
:mod:`workbench.cli.signals`).
"""

from __future__ import annotations

import argparse
import errno
import importlib
import importlib.util
import os
import re
import signal
import sys
from collections.abc import Sequence

from workbench import __version__
from workbench.errors import MissingDependencyError, WorkbenchError
from workbench.optional import EXTRA_OF_MODULE

#: command name -> one-line help, in the order ``--help`` lists them.
COMMANDS: dict[str, str] = {
    # models (Experiments 5, 7.2, 8)
    "check": "check a URDF/SDF/xacro robot description (check_urdf, and more)",
    "graph": "draw a robot's links and joints with graphviz (urdf_to_graphviz)",
    "show": "show a robot in the browser with joint sliders (urdf_tutorial display.launch)",
    # bus (Experiments 1, 2)
    "core": "run the parameter server and registry for several processes (roscore)",
    "launch": "start the nodes of a launch file (roslaunch)",
    "run": "run a registered workbench node (rosrun)",
    "node": "list, inspect, ping and kill nodes; draw the graph (rosnode, rqt_graph)",
    "topic": "list, echo, publish, measure and plot topics (rostopic, rqt_plot)",
    "service": "list, call and inspect services (rosservice)",
    "param": "get, set, dump and load parameters (rosparam)",
    "msg": "show message definitions and md5sums (rosmsg)",
    "srv": "show service definitions (rossrv)",
    "bag": "record, inspect and play ROS 1 bag files (rosbag)",
    "turtlesim": "run the turtlesim simulator (turtlesim_node)",
    "teleop": "drive a turtle or a robot from the keyboard",
    # simulation (Experiment 6, Additional Experiment 1)
    "sim": "run the physics simulation server with the Gazebo ROS API (gzserver)",
    "world": "build a world from a floor plan (Gazebo's building editor); list shipped worlds",
    # visualisation (Experiment 3, and every later lab)
    "rviz": "show markers, tf, robot models, scans and maps in the browser (rviz)",
    # frames (Experiment 4)
    "tf": "echo transforms and draw the frame tree (tf_echo, view_frames)",
    # planning (Experiments 9, 10)
    "setup": "write a planning configuration for a robot (MoveIt setup assistant)",
    "plan": "plan, time and execute a motion for a robot arm (MoveIt)",
    # mapping (Experiment 10)
    "slam": "build a 2D occupancy map from a laser log (gmapping)",
    "map": "show and convert saved maps (map_server)",
    # hardware (Experiment 11)
    "serial": "bridge an Arduino (rosserial) to the bus; run a virtual board (serial_node.py)",
}


def _module_name(command: str) -> str:
    return f"workbench.cli.{command}"


def available_commands() -> dict[str, str]:
    """The commands whose modules exist in this installation."""
    return {
        name: text
        for name, text in COMMANDS.items()
        if importlib.util.find_spec(_module_name(name)) is not None
    }


def _top_parser(commands: dict[str, str]) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="workbench",
        description="A ROS-free robotics lab workbench. "
        "Run 'workbench COMMAND --help' for a command's options.",
    )
    parser.add_argument("--version", action="version", version=f"workbench {__version__}")
    parser.add_argument(
        "--debug", action="store_true", help="show the Python traceback behind an error"
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, text in commands.items():
        sub.add_parser(name, help=text, add_help=False)
    return parser


#: Longest run of characters without a space an error line shows whole; a longer one (a
#: 5,000-character name echoed back, a 300-digit number) is cut to its start and length.
_LONGEST_WORD = 300


def _cut_long_words(line: str) -> str:
    return re.sub(
        rf"\S{{{_LONGEST_WORD + 1},}}",
        lambda word: f"{word[0][:80]}...({len(word[0]):,} characters)",
        line,
    )


def _report(command: str, error: WorkbenchError) -> int:
    print(f"workbench {command}: error: {_cut_long_words(error.one_line())}", file=sys.stderr)
    return error.exit_code


#: Exit status of a command that failed on a bug (sysexits' EX_SOFTWARE).
INTERNAL_ERROR_STATUS = 70


def _shorten(text: str, length: int) -> str:
    text = " ".join(text.split())
    return text if len(text) <= length else text[: length - 3] + "..."


def _internal_error(args: Sequence[str], error: BaseException) -> int:
    """The top-level guard's line: what failed, on which input, and that it is a bug."""
    import shlex

    command = args[0] if args else ""
    reason = _shorten(str(error), 200)
    what = type(error).__name__ + (f": {reason}" if reason else "")
    invocation = _shorten(shlex.join(["workbench", *args]), 200)
    print(
        f"workbench {command}: internal error: {what} (while running: {invocation}; "
        "please report this, with the input; 'workbench --debug ...' shows the traceback)",
        file=sys.stderr,
    )
    return INTERNAL_ERROR_STATUS


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the process exit status.

    SIGINT and SIGTERM stop a command cleanly even in a background job (see
    :mod:`workbench.cli.signals`); it then exits with 130 or 143.
    """
    from workbench.cli.signals import Terminated, ignore_stop_signals, stop_on_signals

    if argv is None:
        _log_warnings_plainly()
    args = list(sys.argv[1:] if argv is None else argv)
    debug = bool(os.environ.get("WORKBENCH_DEBUG"))
    while args and args[0] == "--debug":  # a top-level option, before the command
        debug = True
        args = args[1:]
    with stop_on_signals() as stop:
        try:
            status = _dispatch(args, debug)
        except Terminated:
            status = 128 + signal.SIGTERM
        except KeyboardInterrupt:
            status = 128 + signal.SIGINT
        except BrokenPipeError:  # `workbench ... | head`: the reader left; finish quietly
            from workbench.cli.signals import silence_stdout

            silence_stdout()
            status = 0
        except Exception as error:  # the guard: a bug, not bad input (that is a WorkbenchError)
            if debug:
                raise
            status = _internal_error(args, error)
    if stop.exit_status is not None and argv is None:
        # Stopping: a second signal (a launcher forwards the terminal's Ctrl-C) must not
        # break into the interpreter's exit with a KeyboardInterrupt traceback.
        ignore_stop_signals()
    if stop.exit_status is not None and status == 0:
        # The command caught the interrupt and finalised: report how it was stopped.
        return stop.exit_status
    return status


def _log_warnings_plainly() -> None:
    """Log records of WARNING and up print as their message alone, for the whole process.

    That is how Python prints them before logging is configured; without a handler of our
    own, the first library to call ``logging.basicConfig`` (Drake does when it first logs)
    would switch the rest of the run to ``ERROR:name:message``.
    """
    import logging

    root = logging.getLogger()
    if root.handlers:
        return
    handler = logging.StreamHandler()
    handler.setFormatter(logging.Formatter("%(message)s"))
    handler.setLevel(logging.WARNING)
    root.addHandler(handler)


def _dispatch(args: list[str], debug: bool = False) -> int:
    commands = available_commands()
    if not args or args[0] not in commands:
        # --help, --version, no command, or an unknown one: argparse says it.
        _top_parser(commands).parse_args(args or ["--help"])
        return 2
    command = args[0]
    module = importlib.import_module(_module_name(command))
    parser = argparse.ArgumentParser(prog=f"workbench {command}", description=COMMANDS[command])
    module.configure(parser)
    options = parser.parse_args(args[1:])
    try:
        return int(module.run(options) or 0)
    except WorkbenchError as error:
        if isinstance(error, KeyboardInterrupt) or debug:
            raise  # rospy's ROSInterruptException: a stop, not an error (main exits 130)
        return _report(command, error)
    except ModuleNotFoundError as error:
        # An optional package of an extra that is not installed: say which extra.
        extra = EXTRA_OF_MODULE.get((error.name or "").split(".")[0])
        if extra is None or debug:
            raise
        missing = MissingDependencyError(
            f"the optional package '{error.name}' is not installed",
            hint=f"pip install 'workbench[{extra}]'",
        )
        return _report(command, missing)
    except BrokenPipeError:
        # `workbench topic echo ... | head` closes stdout early: not an error.
        sys.stderr.close()
        return 0
    except OSError as error:
        # A name the file system refuses outright (a 5,000-character argument looked up as
        # a file): bad input wherever it is first touched, not a bug.
        if error.errno != errno.ENAMETOOLONG or debug:
            raise
        return _report(command, _name_too_long(error))


def _name_too_long(error: OSError) -> WorkbenchError:
    name = os.fsdecode(error.filename) if error.filename is not None else ""
    shown = name if len(name) <= 60 else name[:57] + "..."
    return WorkbenchError(
        f"the file name '{shown}' ({len(name):,} characters) is too long for the file system",
        hint="a file name has at most 255 characters per folder and 4,096 in all",
    )
