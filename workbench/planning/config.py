"""A robot's planning configuration: ``planning/<robot>/planning.yaml`` plus its SRDF.

``planning.yaml`` gathers what MoveIt spreads over ``joint_limits.yaml``,
``ompl_planning.yaml`` and the controller files::

    robot: robot_arm                 # a urdf/ name, or a path relative to this file
    srdf: robot_arm.srdf             # relative to this file
    group: arm                       # the default planning group
    default_planner: RRTConnect      # an OMPL planner name
    planning_time: 1.0               # s, default time limit of one request
    edge_resolution: 0.01            # rad (m for prismatic), joint-space step between checks on an edge
    velocity_scaling: 1.0            # fraction of max_velocity a plan may use, (0, 1]
    acceleration_scaling: 1.0        # fraction of max_acceleration, (0, 1]
    joint_limits:                    # per joint; rad/s, rad/s^2 (m/s, m/s^2 for prismatic)
      shoulder_pan_joint: {max_velocity: 1.0, max_acceleration: 2.0}
    controller:                      # the joint-level controller executing plans in workbench.sim
      name: arm_controller
      type: inverse_dynamics         # inverse_dynamics | pid
      joints: [shoulder_pan_joint, ...]
      gains: {kp: 100.0, ki: 0.0, kd: 20.0}

Velocity limits come from the URDF; URDFs carry no acceleration limits, so
the setup writes ``max_acceleration = 2 * max_velocity`` (a joint reaches full
speed in 0.5 s). A joint without a velocity limit gets 1.0 rad/s (m/s).
Nothing here imports pydrake.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from workbench.errors import PlanningError
from workbench.paths import is_dir, is_file, planning_dir, urdf_dir
from workbench.planning.srdf import Srdf, SrdfError, read_srdf

CONFIG_FILE = "planning.yaml"
#: The first line of every planning.yaml the setup writes (how workbench knows it is its own).
CONFIG_HEADER = "# Planning configuration written by `workbench setup`; edit freely.\n"
#: Seconds a joint takes to reach its velocity limit under the default acceleration limit.
DEFAULT_ACCELERATION_TIME = 0.5
#: Velocity limit (rad/s or m/s) for joints whose URDF gives none.
DEFAULT_VELOCITY = 1.0
DEFAULT_PLANNER = "RRTConnect"
DEFAULT_EDGE_RESOLUTION = 0.01
DEFAULT_PLANNING_TIME = 1.0
CONTROLLER_TYPES = ("inverse_dynamics", "pid")
#: Largest planning.yaml or SRDF read, bytes.
MAX_CONFIG_BYTES = 16 * 1024 * 1024
DEFAULT_GAINS = {"kp": 100.0, "ki": 0.0, "kd": 20.0}
_ROBOT_SUFFIXES = (".urdf", ".xacro", ".urdf.xacro", ".sdf")
_KEYS = {
    "robot",
    "srdf",
    "group",
    "default_planner",
    "planning_time",
    "edge_resolution",
    "velocity_scaling",
    "acceleration_scaling",
    "joint_limits",
    "controller",
    "author",
}


class ConfigError(PlanningError):
    """A planning configuration is missing or malformed."""


class ConfigNotFoundError(ConfigError):
    """No ``planning.yaml`` exists for the robot (run ``workbench setup`` first)."""


@dataclass
class PlanningConfig:
    """Everything a planner needs besides the robot model.

    Attributes:
        robot: Path of the robot description (URDF/xacro/SDF).
        srdf: The semantic description (groups, states, disabled collisions).
        group: The default planning group.
        joint_limits: ``{joint: {"max_velocity": v, "max_acceleration": a}}`` in
            rad/s, rad/s^2 (m/s, m/s^2 for prismatic joints), unscaled.
        velocity_scaling: Fraction of ``max_velocity`` a plan may use.
        acceleration_scaling: Fraction of ``max_acceleration`` a plan may use.
        default_planner: OMPL planner name.
        planning_time: Default time limit of one planning request, s.
        edge_resolution: Largest joint-space step (Euclidean, rad or m) between
            collision checks along an edge.
        controller: ``{"name", "type", "joints", "gains": {"kp", "ki", "kd"}}``.
        author: ``{"name", "email"}`` if given at setup.
        path: The directory the configuration lives in (None if never saved).
        collision_matrix: The matrix computed by the setup (not saved; None when loaded).
    """

    robot: Path
    srdf: Srdf
    group: str
    joint_limits: dict[str, dict[str, float]]
    velocity_scaling: float = 1.0
    acceleration_scaling: float = 1.0
    default_planner: str = DEFAULT_PLANNER
    planning_time: float = DEFAULT_PLANNING_TIME
    edge_resolution: float = DEFAULT_EDGE_RESOLUTION
    controller: dict[str, Any] = field(default_factory=dict)
    author: dict[str, str] = field(default_factory=dict)
    path: Path | None = None
    collision_matrix: Any = field(default=None, repr=False, compare=False)

    @property
    def robot_name(self) -> str:
        """The robot's name (from the SRDF)."""
        return self.srdf.name

    def velocity_limits(self, joints: list[str], *, scaled: bool = True) -> list[float]:
        """Velocity limits of ``joints`` in order, times ``velocity_scaling`` unless ``scaled=False``."""
        factor = self.velocity_scaling if scaled else 1.0
        return [self._limit(j, "max_velocity") * factor for j in joints]

    def acceleration_limits(self, joints: list[str], *, scaled: bool = True) -> list[float]:
        """Acceleration limits of ``joints`` in order, times ``acceleration_scaling`` unless unscaled."""
        factor = self.acceleration_scaling if scaled else 1.0
        return [self._limit(j, "max_acceleration") * factor for j in joints]

    def _limit(self, joint: str, key: str) -> float:
        if joint not in self.joint_limits:
            raise ConfigError(
                f"planning.yaml has no limits for joint '{joint}'",
                path=self._file(),
                hint="re-run workbench setup or add the joint under joint_limits",
            )
        return float(self.joint_limits[joint][key])

    def _file(self) -> Path | None:
        return self.path / CONFIG_FILE if self.path is not None else None

    def to_dict(self) -> dict[str, Any]:
        """The ``planning.yaml`` content (paths relative to ``self.path`` where possible)."""
        base = self.path
        srdf_name = f"{self.srdf.name}.srdf"
        data: dict[str, Any] = {
            "robot": _robot_reference(self.robot, base),
            "srdf": srdf_name,
            "group": self.group,
            "default_planner": self.default_planner,
            "planning_time": float(self.planning_time),
            "edge_resolution": float(self.edge_resolution),
            "velocity_scaling": float(self.velocity_scaling),
            "acceleration_scaling": float(self.acceleration_scaling),
            "joint_limits": {
                name: {k: round(float(v), 6) for k, v in limits.items()}
                for name, limits in self.joint_limits.items()
            },
            "controller": self.controller,
        }
        if self.author:
            data["author"] = dict(self.author)
        return data

    def save(
        self, out_dir: str | os.PathLike[str] | None = None, *, create_parents: bool = False
    ) -> Path:
        """Write ``<robot>.srdf`` and ``planning.yaml`` into ``out_dir`` (default: ``self.path``).

        The folder itself is created when missing, its parents only with
        ``create_parents`` (workbench's own ``planning/``); files already there are
        replaced only when ``workbench setup`` wrote them.

        Args:
            out_dir: The configuration folder.
            create_parents: Also create missing parent folders.

        Returns:
            The directory written.

        Raises:
            ConfigError: The parent folder is missing, the robot's name cannot name a file,
                a file there is someone else's, or writing failed.
        """
        from workbench.model.limits import file_stem_problem
        from workbench.output_files import check_output, write_output

        target = Path(out_dir) if out_dir is not None else self.path
        if target is None:
            target, create_parents = config_dir(self.robot_name), True
        problem = file_stem_problem(self.srdf.name)
        if problem is not None:
            raise ConfigError(
                f"the robot's name '{self.srdf.name[:40]}' cannot name the SRDF file: it {problem}",
                hint="rename the robot in its description",
            )
        check_config_dir(target, create_parents=create_parents)
        try:
            target.mkdir(parents=create_parents, exist_ok=True)
        except OSError as error:
            raise ConfigError(
                f"cannot create the configuration folder: {error.strerror}", path=target
            ) from None
        srdf_path = check_output(target / f"{self.srdf.name}.srdf", "srdf", error=ConfigError)
        yaml_path = check_output(target / CONFIG_FILE, "planning-yaml", error=ConfigError)
        self.path = target
        write_output(srdf_path, self.srdf.to_xml(), error=ConfigError)
        self.srdf.path = srdf_path
        text = yaml.safe_dump(self.to_dict(), sort_keys=False, default_flow_style=None, width=100)
        write_output(yaml_path, CONFIG_HEADER + text, error=ConfigError)
        return target


def check_config_dir(target: Path, *, create_parents: bool = False) -> None:
    """Check, before any work, that a configuration may be written into ``target``.

    Raises:
        ConfigError: Its parent folder is missing (unless ``create_parents``), it is not
            a folder, or its ``planning.yaml`` was not written by ``workbench setup``.
    """
    from workbench.output_files import check_output

    if not create_parents and not target.parent.is_dir():
        raise ConfigError(
            f"cannot write the configuration: the folder {target.parent} does not exist",
            path=target,
            hint="create it first; workbench creates only the configuration folder itself",
        )
    if target.exists() and not target.is_dir():
        raise ConfigError(
            "cannot write the configuration: this is not a folder",
            path=target,
            hint="give the folder the configuration goes into",
        )
    if target.is_dir():
        check_output(target / CONFIG_FILE, "planning-yaml", error=ConfigError)


def config_dir(robot_name: str | os.PathLike[str]) -> Path:
    """Where ``workbench setup`` writes a robot's configuration: ``planning/<name>/``.

    Args:
        robot_name: A robot name, or the path of its description (its stem is used).
    """
    name = str(robot_name)
    if os.sep in name or name.endswith(_ROBOT_SUFFIXES):
        name = Path(name).name
        for suffix in sorted(_ROBOT_SUFFIXES, key=len, reverse=True):
            if name.endswith(suffix):
                name = name[: -len(suffix)]
                break
    return planning_dir() / name


def find_config(source: str | os.PathLike[str]) -> Path:
    """The ``planning.yaml`` for a robot name, a config directory or the file itself.

    Raises:
        ConfigNotFoundError: None exists.
    """
    path = Path(source)
    if is_file(path) and path.suffix in (".yaml", ".yml"):
        return path
    if is_dir(path) and is_file(path / CONFIG_FILE):
        return path / CONFIG_FILE
    candidate = config_dir(source) / CONFIG_FILE
    if is_file(candidate):
        return candidate
    raise ConfigNotFoundError(
        f"no planning configuration for '{source}' (looked for {candidate})",
        hint=f"run: workbench setup {source}",
    )


def load_config(source: str | os.PathLike[str]) -> PlanningConfig:
    """Load a planning configuration.

    Args:
        source: A robot name (``robot_arm`` -> ``planning/robot_arm/planning.yaml``),
            a robot description path (its stem names the directory), a config
            directory, or a ``planning.yaml`` path.

    Raises:
        ConfigNotFoundError: There is none (run ``workbench setup ROBOT``).
        ConfigError: The YAML is malformed or a field is wrong (file and line).
        SrdfError: The SRDF is malformed.
    """
    file = find_config(source)
    try:
        data = yaml.safe_load(_read_text(file))
    except yaml.MarkedYAMLError as exc:
        line = exc.problem_mark.line + 1 if exc.problem_mark else None
        problem = " ".join(str(exc.problem or exc).split())
        raise ConfigError(f"malformed YAML: {problem}", path=file, line=line) from None
    except yaml.YAMLError as exc:
        raise ConfigError(f"malformed YAML: {' '.join(str(exc).split())}", path=file) from None
    except RecursionError:
        raise ConfigError("the YAML is nested too deeply", path=file) from None
    if not isinstance(data, dict):
        raise ConfigError("expected a mapping of settings", path=file)
    unknown = sorted(set(data) - _KEYS)
    if unknown:
        raise ConfigError(
            f"unknown setting '{unknown[0]}'", path=file, hint="known: " + ", ".join(sorted(_KEYS))
        )
    for key in ("robot", "srdf", "group", "joint_limits"):
        if key not in data:
            raise ConfigError(f"missing setting '{key}'", path=file)
    base = file.parent
    robot = _resolve_robot(str(data["robot"]), base, file)
    srdf_path = base / str(data["srdf"])
    srdf = read_srdf(srdf_path)
    group = str(data["group"])
    try:
        srdf.group(group)
    except SrdfError as exc:
        raise ConfigError(f"group: {exc.message}", path=file, hint=exc.hint) from None
    limits = _read_limits(data["joint_limits"], file)
    controller = data.get("controller") or {}
    if not isinstance(controller, dict):
        raise ConfigError("controller must be a mapping", path=file)
    ctype = controller.get("type", "inverse_dynamics")
    if ctype not in CONTROLLER_TYPES:
        raise ConfigError(
            f"controller type '{ctype}' is not supported",
            path=file,
            hint="use " + " or ".join(CONTROLLER_TYPES),
        )
    return PlanningConfig(
        robot=robot,
        srdf=srdf,
        group=group,
        joint_limits=limits,
        velocity_scaling=_fraction(data, "velocity_scaling", file),
        acceleration_scaling=_fraction(data, "acceleration_scaling", file),
        default_planner=str(data.get("default_planner", DEFAULT_PLANNER)),
        planning_time=_positive(data, "planning_time", DEFAULT_PLANNING_TIME, file),
        edge_resolution=_positive(data, "edge_resolution", DEFAULT_EDGE_RESOLUTION, file),
        controller=controller,
        author=dict(data.get("author") or {}),
        path=base,
    )


def _read_text(file: Path) -> str:
    """A configuration file's text: a regular UTF-8 file of at most a few megabytes."""
    from workbench.errors import ModelError
    from workbench.model.limits import check_input_file

    try:
        return check_input_file(file, "planning configuration", MAX_CONFIG_BYTES).read_text(
            encoding="utf-8"
        )
    except ModelError as error:
        raise ConfigError(error.message, path=file, hint=error.hint) from None
    except UnicodeDecodeError:
        raise ConfigError("the file is not UTF-8 text", path=file) from None
    except OSError as error:
        raise ConfigError(f"cannot read the file: {error.strerror}", path=file) from None


def default_joint_limits(joints: list[Any]) -> dict[str, dict[str, float]]:
    """Velocity and acceleration limits for movable joints (``JointInfo``-like).

    Velocity is the URDF's (``DEFAULT_VELOCITY`` when absent, zero or infinite);
    acceleration is ``velocity / DEFAULT_ACCELERATION_TIME``.
    """
    out: dict[str, dict[str, float]] = {}
    for j in joints:
        v = j.velocity
        if v is None or not math.isfinite(v) or v <= 0:
            v = DEFAULT_VELOCITY
        out[j.name] = {
            "max_velocity": float(v),
            "max_acceleration": float(v) / DEFAULT_ACCELERATION_TIME,
        }
    return out


def default_controller(name: str, joints: list[str]) -> dict[str, Any]:
    """The default controller entry: inverse dynamics with PD(+I) gains on ``joints``."""
    return {
        "name": name,
        "type": "inverse_dynamics",
        "joints": list(joints),
        "gains": dict(DEFAULT_GAINS),
    }


# --- helpers -----------------------------------------------------------------------


def _robot_reference(robot: Path, base: Path | None) -> str:
    robot = Path(robot).resolve()
    try:
        if robot.parent == urdf_dir().resolve() and robot.suffix == ".urdf":
            return robot.stem
    except OSError:
        pass
    if base is not None:
        try:
            return os.path.relpath(robot, Path(base).resolve())
        except ValueError:
            pass
    return str(robot)


def _resolve_robot(value: str, base: Path, file: Path) -> Path:
    candidates = []
    if "/" not in value and not value.endswith(_ROBOT_SUFFIXES):
        for suffix in _ROBOT_SUFFIXES:
            candidates.append(urdf_dir() / f"{value}{suffix}")
    candidates.append(base / value)
    candidates.append(Path(value).expanduser())
    for candidate in candidates:
        if is_file(candidate):
            return candidate.resolve()
    raise ConfigError(
        f"robot '{value}' not found (tried {', '.join(str(c) for c in candidates)})",
        path=file,
        hint="fix the robot: entry or re-run workbench setup",
    )


def _read_limits(raw: Any, file: Path) -> dict[str, dict[str, float]]:
    if not isinstance(raw, dict):
        raise ConfigError("joint_limits must map joint names to limits", path=file)
    out: dict[str, dict[str, float]] = {}
    for joint, limits in raw.items():
        if not isinstance(limits, dict):
            raise ConfigError(f"joint_limits.{joint} must be a mapping", path=file)
        entry = {}
        for key in ("max_velocity", "max_acceleration"):
            value = limits.get(key)
            if not isinstance(value, (int, float)) or value <= 0 or not math.isfinite(value):
                raise ConfigError(
                    f"joint_limits.{joint}.{key} must be a positive number, got {value!r}",
                    path=file,
                )
            entry[key] = float(value)
        out[str(joint)] = entry
    return out


def _fraction(data: dict[str, Any], key: str, file: Path) -> float:
    value = data.get(key, 1.0)
    if not isinstance(value, (int, float)) or not 0 < value <= 1:
        raise ConfigError(f"{key} must be in (0, 1], got {value!r}", path=file)
    return float(value)


def _positive(data: dict[str, Any], key: str, default: float, file: Path) -> float:
    value = data.get(key, default)
    if not isinstance(value, (int, float)) or not (math.isfinite(value) and value > 0):
        raise ConfigError(f"{key} must be a positive number, got {value!r}", path=file)
    return float(value)
