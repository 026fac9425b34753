"""ROS's own tools as oracles for benchmarks/corpus.py, and the probes that read them.

* launch files: Debian's ``python3-roslaunch`` through :mod:`roslaunch_oracle`, compared
  with workbench's loader by :mod:`launch_compare`;
* robot descriptions: urdfdom's ``check_urdf`` and ``urdf_to_graphviz`` on the
  URDF (a xacro expanded by workbench's xacro, :data:`XACRO_PROBE`);
* worlds and models: libsdformat, through the small checker
  :data:`SDF_CHECK_SOURCE` compiled here with g++;
* bags: Debian's ``python3-rosbag`` (:data:`ROSBAG_PROBE`).
"""

from __future__ import annotations

import shlex
import shutil
import subprocess
from pathlib import Path

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
