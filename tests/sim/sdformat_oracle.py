"""libsdformat as the judge of SDF files: a small C++ program built against Debian's libsdformat12.

``sdformat/sdformat_check.cc`` loads a file with ``sdf::Root::Load`` (model:// looked up in
``GAZEBO_MODEL_PATH``) and prints JSON: the errors, and every model, link and joint it sees
with poses and axes. It is compiled once per test session with g++ (Debian packages
``g++``, ``pkg-config``, ``libsdformat-dev``); without them the tests that need it skip
(fail under WORKBENCH_REQUIRE_ALL=1).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest
from skipping import skip_or_fail

SOURCE = Path(__file__).resolve().parent / "sdformat" / "sdformat_check.cc"
PACKAGES = "g++ pkg-config libsdformat-dev"
#: libsdformat's renaming of a joint named like a link (Model.cc, SDFormat before 1.7).
_RENAMED = re.compile(
    r"Joint with name \[(.+?)\] in model with name \[(.+?)\] has a name collision, changing joint name to \[(.+?)\]"
)
_COLOUR = re.compile(r"\x1b\[[0-9;]*m")


def build_checker(folder: Path) -> Path:
    """Compile the checker into ``folder``; skip (or fail) when the compiler or library is missing."""
    if shutil.which("g++") is None or shutil.which("pkg-config") is None:
        skip_or_fail(
            f"g++ and pkg-config are needed for the libsdformat oracle (apt-get install {PACKAGES})"
        )
    flags = subprocess.run(
        ["pkg-config", "--cflags", "--libs", "sdformat12"], capture_output=True, text=True
    )
    if flags.returncode != 0:
        skip_or_fail(f"libsdformat12 headers are not installed (apt-get install {PACKAGES})")
    binary = folder / "sdformat_check"
    done = subprocess.run(
        ["g++", "-O1", str(SOURCE), "-o", str(binary), *flags.stdout.split()],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    return binary


_BUILT: dict[str, Path] = {}


def session_checker(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The compiled checker, built once per test session (call it from a fixture)."""
    if "checker" not in _BUILT:
        _BUILT["checker"] = build_checker(tmp_path_factory.mktemp("sdformat_oracle"))
    return _BUILT["checker"]


@dataclass
class OracleModel:
    """A model as libsdformat sees it, nested models flattened as Gazebo names them.

    Attributes:
        name: The model's name.
        links: ``NESTED::link`` name -> pose in the (top) model frame, 4x4.
        joints: ``NESTED::joint`` name (as the file spells it) -> (parent, child, axis in the
            top model frame or None).
    """

    name: str
    links: dict[str, np.ndarray] = field(default_factory=dict)
    joints: dict[str, tuple[str, str, np.ndarray | None]] = field(default_factory=dict)


@dataclass
class OracleResult:
    """What libsdformat said about one file."""

    errors: list[str]
    warnings: list[str]
    model: OracleModel | None
    world_models: list[OracleModel]
    raw: dict

    @property
    def accepted(self) -> bool:
        return not self.errors


def run_oracle(checker: Path, path: Path, model_path: str = "") -> OracleResult:
    """libsdformat's view of ``path`` (``model_path``: GAZEBO_MODEL_PATH for model:// URIs)."""
    env = {"PATH": os.environ.get("PATH", ""), "GAZEBO_MODEL_PATH": model_path, "LC_ALL": "C"}
    done = subprocess.run(
        [str(checker), str(path)], capture_output=True, text=True, env=env, timeout=120
    )
    assert done.returncode == 0, done.stderr
    data = json.loads(done.stdout)
    warnings = [_COLOUR.sub("", line) for line in done.stderr.splitlines() if line.strip()]
    renamed = {(m.group(2), m.group(3)): m.group(1) for m in map(_RENAMED.search, warnings) if m}
    model = _flatten(data["model"], renamed) if data["model"] else None
    world_models = [_flatten(m, renamed) for w in data["worlds"] for m in w["models"]]
    return OracleResult([e["message"] for e in data["errors"]], warnings, model, world_models, data)


def _pose(values: list[float]) -> np.ndarray:
    from workbench.spatial import pose_matrix

    return pose_matrix(values[:3], rpy=values[3:])


def _flatten(model: dict, renamed: dict[tuple[str, str], str]) -> OracleModel:
    """Nested models merged into ``model`` as Gazebo names them, poses in ``model``'s frame;
    joints libsdformat renamed (a joint named like a link) get the file's name back."""
    result = OracleModel(model["name"])

    def walk(item: dict, prefix: str, X_TM: np.ndarray) -> None:
        for link in item["links"]:
            result.links[prefix + link["name"]] = X_TM @ _pose(link["pose"])
        for joint in item["joints"]:
            name = renamed.get((item["name"], joint["name"]), joint["name"])
            axis = None if joint["axis"] is None else X_TM[:3, :3] @ np.array(joint["axis"])
            parent = joint["parent"] if joint["parent"] == "world" else prefix + joint["parent"]
            result.joints[prefix + name] = (parent, prefix + joint["child"], axis)
        for nested in item["models"]:
            walk(nested, f"{prefix}{nested['name']}::", X_TM @ _pose(nested["pose"]))

    walk(model, "", np.eye(4))
    return result
