"""ROS's own tools as oracles for benchmarks/corpus.py, and the probes that read both sides.

* launch files: Debian's ``python3-roslaunch`` (its XML loader, no master) run
  by :data:`ROSLAUNCH_PROBE` under the system Python, against workbench's
  loader run by :data:`WORKBENCH_LAUNCH_PROBE`; both print the resolved nodes
  and parameters as JSON and :func:`compare_launch` says how they differ;
* robot descriptions: urdfdom's ``check_urdf`` and ``urdf_to_graphviz`` on the
  URDF (a xacro expanded by workbench's xacro, :data:`XACRO_PROBE`);
* worlds and models: libsdformat, through the small checker
  :data:`SDF_CHECK_SOURCE` compiled here with g++;
* bags: Debian's ``python3-rosbag`` (:data:`ROSBAG_PROBE`).

Both launch probes set ``<param command=...>`` to one placeholder instead of
running the command (only the names are compared for those), and make
``$(anon name)`` deterministic (``name_anon``) so names compare.
"""

from __future__ import annotations

import json
import math
import shlex
import shutil
import subprocess
from pathlib import Path
from typing import Any

#: Marks the JSON line a probe prints among whatever else the loader prints.
MARK = "@@corpus@@ "

_COMMON = r"""
import json, sys
MARK = "@@corpus@@ "
PLACEHOLDER = "<command output>"

def jsonable(value):
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    if isinstance(value, dict):
        return {str(k): jsonable(v) for k, v in value.items()}
    if hasattr(value, "data") and isinstance(value.data, bytes):
        return "<binary %d bytes>" % len(value.data)
    return repr(value)

def flatten(name, value, into):
    if isinstance(value, dict):
        for key, item in value.items():
            flatten(name.rstrip("/") + "/" + str(key), item, into)
    else:
        into[name] = jsonable(value)
"""

#: Run by Debian's Python: ``python3 -c ROSLAUNCH_PROBE FILE``.
ROSLAUNCH_PROBE = (
    _COMMON
    + r"""
import rosgraph.names
rosgraph.names.anonymous_name = lambda base: base + "_anon"
import roslaunch.config, roslaunch.loader, roslaunch.xmlloader

_value = roslaunch.loader.Loader.param_value
def param_value(self, verbose, name, ptype, value, textfile, binfile, command):
    if value is None and textfile is None and binfile is None and command is not None:
        return PLACEHOLDER
    return _value(self, verbose, name, ptype, value, textfile, binfile, command)
roslaunch.loader.Loader.param_value = param_value

config = roslaunch.config.ROSLaunchConfig()
try:
    loader = roslaunch.xmlloader.XmlLoader()
    loader.ignore_unset_args = False  # read on a missing arg; only roslaunch's CLI sets it
    loader.load(sys.argv[1], config, argv=[], verbose=False)
except Exception as error:
    lines = [line for line in str(error).splitlines() if line.strip()]
    text = " ".join((lines[0] if lines else "").split())
    print(MARK + json.dumps({"accepts": False, "error": type(error).__name__ + ": " + text}))
    sys.exit(0)
params = {}
for name, param in config.params.items():
    flatten(name, param.value, params)
nodes = [
    {"pkg": n.package, "type": n.type, "name": n.name, "namespace": n.namespace,
     "args": n.args, "remaps": [list(r) for r in n.remap_args],
     "env": [list(e) for e in n.env_args]}
    for n in config.nodes
]
deletes = [
    e.args[1] for e in config.executables
    if getattr(e, "command", None) == "rosparam" and e.args and e.args[0] == "delete"
]
print(MARK + json.dumps({"accepts": True, "nodes": nodes, "params": params, "deletes": deletes}))
"""
)

#: Run by workbench's Python: ``python -c WORKBENCH_LAUNCH_PROBE FILE``. A refusal exits 1
#: with workbench's one line; anything but a WorkbenchError ends in a traceback.
WORKBENCH_LAUNCH_PROBE = (
    _COMMON
    + r"""
from pathlib import Path
import workbench.bus.names as names
_anon = names.anonymous_name
def anon(base):
    return base + "_anon"
names.anonymous_name = anon
from workbench.bus.launch import load_launch
from workbench.errors import WorkbenchError
for module in list(sys.modules.values()):
    if getattr(module, "anonymous_name", None) is _anon:
        module.anonymous_name = anon
try:
    plan = load_launch(Path(sys.argv[1]), {}, dry_run=False,
                       command_runner=lambda command, launch_file: PLACEHOLDER)
except WorkbenchError as error:
    print(MARK + json.dumps({"accepts": False, "error": error.one_line()}))
    print("error: " + error.one_line(), file=sys.stderr)
    sys.exit(1)
params = {}
for name, value in plan.params.items():
    flatten(name, value, params)
nodes = []
for spec in plan.nodes:
    env = getattr(spec, "env", None)
    nodes.append({"pkg": spec.pkg, "type": spec.type, "name": spec.name,
                  "namespace": spec.namespace, "args": list(spec.args),
                  "remaps": [[a, b] for a, b in spec.remaps.items()],
                  "env": None if env is None else [list(e) for e in dict(env).items()]})
print(MARK + json.dumps({"accepts": True, "nodes": nodes, "params": params,
                         "deletes": list(getattr(plan, "deletes", []))}))
"""
)

#: Run by workbench's Python: ``python -c XACRO_PROBE FILE OUT`` writes the expanded URDF.
XACRO_PROBE = r"""
import sys
from pathlib import Path
from workbench.errors import WorkbenchError
from workbench.model.sources import expand_xacro
try:
    Path(sys.argv[2]).write_text(expand_xacro(Path(sys.argv[1])))
except WorkbenchError as error:
    print("error: " + error.one_line(), file=sys.stderr)
    sys.exit(1)
"""

#: Run by Debian's Python: ``python3 -c ROSBAG_PROBE FILE``.
ROSBAG_PROBE = r"""
import sys, rosbag
with rosbag.Bag(sys.argv[1]) as bag:
    print(bag.get_message_count())
"""

#: A libsdformat checker: loads a world or model as Gazebo's parser does (``model://``
#: through GAZEBO_MODEL_PATH), prints ``error: ...``/``warning: ...`` lines, exits 1 on
#: errors. Invalid inertia is a warning: Gazebo 11's libsdformat 9 does not check it.
SDF_CHECK_SOURCE = r"""
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <sdf/sdf.hh>

int main(int argc, char **argv) {
  if (argc != 2) {
    std::cerr << "usage: sdf_check FILE\n";
    return 2;
  }
  sdf::ParserConfig config;
  if (const char *paths = std::getenv("GAZEBO_MODEL_PATH")) {
    std::stringstream list(paths);
    std::string dir;
    while (std::getline(list, dir, ':'))
      if (!dir.empty()) config.AddURIPath("model://", dir);
  }
  sdf::Root root;
  sdf::Errors errors = root.Load(argv[1], config);
  // Root adds "Failed to load a world." after any error of the world, invalid inertia too.
  auto soft = [](const sdf::Error &e) {
    return e.Code() == sdf::ErrorCode::LINK_INERTIA_INVALID;
  };
  auto summary = [](const sdf::Error &e) {
    return e.Code() == sdf::ErrorCode::ELEMENT_INVALID && e.Message().rfind("Failed to load a", 0) == 0;
  };
  int failed = 0;
  for (const auto &e : errors)
    failed |= !soft(e) && !summary(e);
  for (const auto &e : errors) {
    bool hard = !soft(e) && (failed || !summary(e));
    std::cout << (hard ? "error: " : "warning: ") << e.Message() << "\n";
  }
  return failed;
}
"""

SDFORMAT_PACKAGES = ("sdformat14", "sdformat13", "sdformat12")


def have_python_module(python: str, module: str) -> bool:
    """``python`` exists and imports ``module``."""
    if shutil.which(python) is None and not Path(python).is_file():
        return False
    done = subprocess.run([python, "-c", f"import {module}"], capture_output=True, timeout=120)
    return done.returncode == 0


def build_sdf_check(work: Path) -> Path | None:
    """Compile :data:`SDF_CHECK_SOURCE` into ``work``; None without g++ or libsdformat."""
    if shutil.which("g++") is None or shutil.which("pkg-config") is None:
        return None
    for package in SDFORMAT_PACKAGES:
        flags = subprocess.run(
            ["pkg-config", "--cflags", "--libs", package], capture_output=True, text=True
        )
        if flags.returncode != 0:
            continue
        source, program = work / "sdf_check.cc", work / "sdf_check"
        source.write_text(SDF_CHECK_SOURCE)
        built = subprocess.run(
            ["g++", "-std=c++17", str(source), "-o", str(program), *shlex.split(flags.stdout)],
            capture_output=True,
            timeout=600,
        )
        if built.returncode == 0:
            return program
    return None


def probe_json(text: str) -> dict[str, Any] | None:
    """The JSON a probe printed after :data:`MARK` (the last such line), or None."""
    for line in reversed(text.splitlines()):
        if line.startswith(MARK):
            return json.loads(line[len(MARK) :])
    return None


# --- comparing resolved launch files ---------------------------------------------------


def _canonical(name: str) -> str:
    """A ROS name without doubled or trailing slashes (roslaunch's canonicalize_name)."""
    if not name or name == "/":
        return name
    while "//" in name:
        name = name.replace("//", "/")
    return name.rstrip("/") or "/"


def _node_key(node: dict[str, Any]) -> str:
    namespace = _canonical(node["namespace"] or "/")
    return (namespace.rstrip("/") + "/" + (node["name"] or "")).replace("//", "/")


def _args(args: Any) -> list[str]:
    if isinstance(args, list):
        return [str(a) for a in args]
    try:
        return shlex.split(args or "")
    except ValueError:
        return str(args).split()


def _same_value(ours: Any, ros: Any) -> bool:
    if isinstance(ours, bool) or isinstance(ros, bool):
        return type(ours) is type(ros) and ours == ros
    if isinstance(ours, (int, float)) and isinstance(ros, (int, float)):
        return math.isclose(ours, ros, rel_tol=1e-9, abs_tol=1e-12) or (
            math.isnan(ours) and math.isnan(ros)
        )
    if isinstance(ours, list) and isinstance(ros, list):
        return len(ours) == len(ros) and all(map(_same_value, ours, ros))
    return ours == ros


def _short(value: Any, length: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= length else text[: length - 3] + "..."


def compare_launch(ours: dict[str, Any], ros: dict[str, Any]) -> list[str]:
    """How workbench's resolved launch differs from roslaunch's (empty when it does not).

    Compared: the nodes by full name with package, type, args (as the words a shell
    would split), remappings (canonical names) and, when workbench reports them,
    environment; every parameter's name, and its value unless it is a command's
    output; the parameters deleted.
    """
    problems: list[str] = []
    our_nodes = {_node_key(n): n for n in ours["nodes"]}
    ros_nodes = {_node_key(n): n for n in ros["nodes"]}
    if len(our_nodes) != len(ours["nodes"]):
        problems.append("workbench lists a node twice")
    for name in sorted(set(ros_nodes) - set(our_nodes)):
        problems.append(f"node {name} missing")
    for name in sorted(set(our_nodes) - set(ros_nodes)):
        problems.append(f"node {name} not in roslaunch's")
    for name in sorted(set(our_nodes) & set(ros_nodes)):
        a, b = our_nodes[name], ros_nodes[name]
        if (a["pkg"], a["type"]) != (b["pkg"], b["type"]):
            problems.append(f"node {name} runs {a['pkg']}/{a['type']}, not {b['pkg']}/{b['type']}")
        if _args(a["args"]) != _args(b["args"]):
            problems.append(f"node {name} args {_args(a['args'])} vs {_args(b['args'])}")
        ours_remaps = {_canonical(x): _canonical(y) for x, y in a["remaps"]}
        ros_remaps = {_canonical(x): _canonical(y) for x, y in b["remaps"]}
        if ours_remaps != ros_remaps:
            problems.append(f"node {name} remaps {ours_remaps} vs {ros_remaps}")
        if a.get("env") is not None and dict(map(tuple, a["env"])) != dict(map(tuple, b["env"])):
            problems.append(f"node {name} env {a['env']} vs {b['env']}")
    our_params, ros_params = ours["params"], ros["params"]
    missing = sorted(set(ros_params) - set(our_params))
    extra = sorted(set(our_params) - set(ros_params))
    if missing:
        problems.append(f"{len(missing)} params missing ({', '.join(missing[:3])})")
    if extra:
        problems.append(f"{len(extra)} params not in roslaunch's ({', '.join(extra[:3])})")
    for name in sorted(set(our_params) & set(ros_params)):
        if not _same_value(our_params[name], ros_params[name]):
            problems.append(
                f"param {name} = {_short(our_params[name])} vs {_short(ros_params[name])}"
            )
    if sorted(map(_canonical, ours.get("deletes", []))) != sorted(
        map(_canonical, ros.get("deletes", []))
    ):
        problems.append(f"deleted params {ours.get('deletes')} vs {ros.get('deletes')}")
    return problems
