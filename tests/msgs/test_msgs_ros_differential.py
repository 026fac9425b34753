"""Every message and service of the Noetic packages workbench carries, against ROS's own.

Debian ships ROS 1's generated Python for the common message packages
(``python3-std-msgs``, ``python3-geometry-msgs``, ``python3-nav-msgs`` ...); each
class holds the md5sum ``genmsg`` computed from the ``.msg``/``.srv`` file. For
each of those packages workbench must know every type Debian's has, with the same
md5sum, for a message, a service and a service's request and response: the md5 is
what ROS nodes and bags compare before they exchange a byte. Skips (fails under
``WORKBENCH_REQUIRE_ALL=1``) without the packages; ``.ci/run`` installs them.
"""

from __future__ import annotations

import json
import subprocess

import pytest
from skipping import skip_or_fail

from workbench.msgs import md5sum

ROS_PYTHON = "/usr/bin/python3"
#: The Noetic packages workbench claims in full.
PACKAGES = (
    "actionlib_msgs",
    "diagnostic_msgs",
    "geometry_msgs",
    "move_base_msgs",
    "nav_msgs",
    "rosgraph_msgs",
    "sensor_msgs",
    "shape_msgs",
    "std_msgs",
    "std_srvs",
    "stereo_msgs",
    "tf2_msgs",
    "trajectory_msgs",
    "visualization_msgs",
)

# Lists each package's generated modules (msg/_Name.py, srv/_Name.py) and their md5sums.
_LIST_TYPES = """
import importlib, json, pkgutil, sys
found = {}
for package in sys.argv[1:]:
    for kind in ("msg", "srv"):
        try:
            module = importlib.import_module(f"{package}.{kind}")
        except ImportError:
            continue
        for info in pkgutil.iter_modules(module.__path__):
            if not info.name.startswith("_"):
                continue
            name = info.name[1:]
            generated = importlib.import_module(f"{package}.{kind}.{info.name}")
            entry = {"kind": kind, "md5": getattr(generated, name)._md5sum}
            if kind == "srv":
                entry["Request"] = getattr(generated, name + "Request")._md5sum
                entry["Response"] = getattr(generated, name + "Response")._md5sum
            found[f"{package}/{name}"] = entry
print(json.dumps(found))
"""


@pytest.fixture(scope="module")
def ros_types() -> dict[str, dict[str, str]]:
    try:
        done = subprocess.run(
            [ROS_PYTHON, "-c", _LIST_TYPES, *PACKAGES], capture_output=True, text=True, timeout=120
        )
    except (OSError, subprocess.TimeoutExpired):
        done = None
    if done is None or done.returncode != 0:
        skip_or_fail("ROS 1's message packages are not installed (apt-get install python3-*-msgs)")
    found = json.loads(done.stdout)
    packages = {name.split("/")[0] for name in found}
    if packages != set(PACKAGES):
        skip_or_fail(f"missing ROS 1 message packages: {sorted(set(PACKAGES) - packages)}")
    return found


def test_every_type_of_the_claimed_packages_exists_with_ros_md5(ros_types):
    assert len(ros_types) > 140
    wrong = {}
    for name, entry in sorted(ros_types.items()):
        try:
            ours = md5sum(name)
        except Exception as error:  # an unknown type is a failure to report, not a crash
            wrong[name] = f"missing: {error}"
            continue
        if ours != entry["md5"]:
            wrong[name] = f"md5 {ours} != ROS {entry['md5']}"
        if entry["kind"] == "srv":
            for part in ("Request", "Response"):
                if md5sum(name + part) != entry[part]:
                    wrong[name + part] = f"md5 {md5sum(name + part)} != ROS {entry[part]}"
    assert wrong == {}


def test_the_types_the_map_server_and_navigation_need_are_there(ros_types):
    for name in ("nav_msgs/GetMap", "nav_msgs/GetPlan", "nav_msgs/SetMap", "tf2_msgs/TF2Error"):
        assert name in ros_types
        assert md5sum(name) == ros_types[name]["md5"]
