"""Resolve launch files with ROS 1's own roslaunch loader and print what it planned as JSON.

Runs under the system Python that has Debian's ``python3-roslaunch`` (``/usr/bin/python3``),
never under workbench's environment: it imports no workbench module. It reads a JSON list
of jobs on stdin, ``[{"file": PATH, "argv": ["name:=value", ...], "env": {NAME: VALUE}}]``,
loads each with ``roslaunch.xmlloader.XmlLoader().load(file, ROSLaunchConfig(), argv=...)``
(no master, no process started) and prints one JSON list with, per job, either
``{"error": MESSAGE}`` or the plan: nodes and tests (package, type, name, namespace, args,
remaps, env, output, respawn, respawn_delay, required, launch_prefix, cwd, machine),
parameters, cleared namespaces, ``rosparam`` commands and machines.

Two things are replaced for comparison: ``$(anon id)`` gives ``id_anonN`` (N counts the
calls) instead of a random name, and ``<param command=...>`` gives the marker
``<command: ...>`` instead of running the program (workbench's dry run does not run it
either; the differential compares the command text).

Usage: ``/usr/bin/python3 benchmarks/roslaunch_oracle.py < jobs.json``, or for one file
with this process's environment, ``/usr/bin/python3 benchmarks/roslaunch_oracle.py FILE
[NAME:=VALUE ...]`` (prints that file's result alone).
"""

import base64
import json
import math
import os
import sys

COMMAND_MARKER = "<command: {}>"


def _install_replacements():
    import rosgraph.names
    import roslaunch.loader

    calls = [0]

    def anonymous_name(id):
        calls[0] += 1
        return f"{id}_anon{calls[0]}"

    rosgraph.names.anonymous_name = anonymous_name
    original = roslaunch.loader.Loader.param_value

    def param_value(self, verbose, name, ptype, value, textfile, binfile, command):
        if command is not None:
            return COMMAND_MARKER.format(command)
        return original(self, verbose, name, ptype, value, textfile, binfile, command)

    roslaunch.loader.Loader.param_value = param_value
    return calls


def plain(value):
    """A parameter value as JSON: bytes and non-finite floats spelled out, keys as text."""
    if isinstance(value, bool) or value is None or isinstance(value, (int, str)):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else {"float": repr(value)}
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    data = getattr(value, "data", None)  # xmlrpc Binary
    if isinstance(data, bytes):
        return {"binary": base64.b64encode(data).decode()}
    return {"repr": repr(value)}


def _node(node, test=False):
    out = {
        "pkg": node.package,
        "type": node.type,
        "name": node.name,
        "namespace": node.namespace,
        "args": node.args,
        "remaps": [list(r) for r in node.remap_args],
        "env": [list(e) for e in node.env_args],
        "launch_prefix": node.launch_prefix,
        "cwd": node.cwd,
        "machine": node.machine_name,
    }
    if test:
        out.update(test_name=node.test_name, time_limit=node.time_limit, retry=node.retry)
    else:
        out.update(
            output=node.output,
            respawn=node.respawn,
            respawn_delay=node.respawn_delay,
            required=node.required,
        )
    return out


def resolve(job, calls):
    import roslaunch.config
    import roslaunch.xmlloader

    saved = dict(os.environ)
    os.environ.update(job.get("env", {}))
    calls[0] = 0
    try:
        config = roslaunch.config.ROSLaunchConfig()
        loader = roslaunch.xmlloader.XmlLoader()
        loader.ignore_unset_args = False
        loader.load(job["file"], config, argv=list(job.get("argv", [])), verbose=False)
    except Exception as error:  # every failure is the answer for this job
        return {"error": f"{type(error).__name__}: {' '.join(str(error).split())}"}
    finally:
        os.environ.clear()
        os.environ.update(saved)
    executables = [[e.command, [a for a in e.args]] for e in config.executables]
    return {
        "nodes": [_node(n) for n in config.nodes],
        "tests": [_node(t, test=True) for t in config.tests],
        "params": {key: plain(p.value) for key, p in config.params.items()},
        "clear_params": list(config.clear_params),
        "executables": executables,
        "machines": {name: m.address for name, m in config.machines.items() if name},
    }


def main():
    one = len(sys.argv) > 1
    jobs = [{"file": sys.argv[1], "argv": sys.argv[2:]}] if one else json.load(sys.stdin)
    calls = _install_replacements()
    real_stdout, real_stderr = sys.stdout, sys.stderr
    results = []
    with open(os.devnull, "w") as devnull:
        for job in jobs:
            sys.stdout = sys.stderr = devnull  # roslaunch prints warnings; keep stdout JSON
            try:
                results.append(resolve(job, calls))
            finally:
                sys.stdout, sys.stderr = real_stdout, real_stderr
    json.dump(results[0] if one else results, real_stdout)


if __name__ == "__main__":
    main()
