"""amcl's private parameters, with the names and defaults of ``amcl_node.cpp`` (Noetic).

``~seed`` is workbench's own: the seed of every random draw (amcl seeds ``drand48``
from the clock). ``laser_model_type`` ``beam`` and ``likelihood_field_prob`` are
accepted with a warning and run the ``likelihood_field`` model; an unknown laser or
odometry model type warns and falls back to ``likelihood_field`` / ``diff`` as amcl does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

from workbench.errors import MappingError
from workbench.navigation.amcl_motion import MODELS


class AmclError(MappingError):
    """A bad amcl parameter or input."""


@dataclass
class AmclParams:
    """amcl's parameters (see the ROS wiki page of amcl for their meaning)."""

    min_particles: int = 100
    max_particles: int = 5000
    kld_err: float = 0.01
    kld_z: float = 0.99
    update_min_d: float = 0.2
    update_min_a: float = math.pi / 6.0
    resample_interval: int = 2
    transform_tolerance: float = 0.1
    recovery_alpha_slow: float = 0.001
    recovery_alpha_fast: float = 0.1
    initial_pose_x: float = 0.0
    initial_pose_y: float = 0.0
    initial_pose_a: float = 0.0
    initial_cov_xx: float = 0.5 * 0.5
    initial_cov_yy: float = 0.5 * 0.5
    initial_cov_aa: float = (math.pi / 12.0) * (math.pi / 12.0)
    gui_publish_rate: float = -1.0
    save_pose_rate: float = 0.5
    use_map_topic: bool = False
    first_map_only: bool = False
    selective_resampling: bool = False
    laser_min_range: float = -1.0
    laser_max_range: float = -1.0
    laser_max_beams: int = 30
    laser_z_hit: float = 0.95
    laser_z_short: float = 0.1
    laser_z_max: float = 0.05
    laser_z_rand: float = 0.05
    laser_sigma_hit: float = 0.2
    laser_lambda_short: float = 0.1
    laser_likelihood_max_dist: float = 2.0
    laser_model_type: str = "likelihood_field"
    odom_model_type: str = "diff"
    odom_alpha1: float = 0.2
    odom_alpha2: float = 0.2
    odom_alpha3: float = 0.2
    odom_alpha4: float = 0.2
    odom_alpha5: float = 0.2
    odom_frame_id: str = "odom"
    base_frame_id: str = "base_link"
    global_frame_id: str = "map"
    tf_broadcast: bool = True
    force_update_after_initialpose: bool = False
    force_update_after_set_map: bool = False
    seed: int = 0


#: Initial pose parameters whose NaN amcl ignores, with the words of its warning.
_INITIAL = {
    "initial_pose_x": "initial pose X position",
    "initial_pose_y": "initial pose Y position",
    "initial_pose_a": "initial pose Yaw",
    "initial_cov_xx": "initial covariance XX",
    "initial_cov_yy": "initial covariance YY",
    "initial_cov_aa": "initial covariance AA",
}


def _convert(name: str, value: Any, kind: type) -> Any:
    what = {bool: "a boolean", int: "an integer", float: "a number", str: "a string"}[kind]
    if kind is bool and isinstance(value, bool):
        return value
    if kind is int and isinstance(value, int) and not isinstance(value, bool):
        return value
    if kind is float and isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    if kind is str and isinstance(value, str):
        return value
    raise AmclError(f"parameter ~{name} must be {what}, got {value!r}")


def strip_slash(frame: str) -> str:
    """A frame id without its leading ``/`` (amcl's ``stripSlash``)."""
    return frame[1:] if frame.startswith("/") else frame


def read_params(node: Any, warn: Any = None) -> AmclParams:
    """amcl's parameters from ``node``'s private namespace.

    Args:
        node: The bus node.
        warn: ``warn(text)`` for amcl's warnings (default: the node's logger).

    Raises:
        AmclError: A parameter has the wrong type or an impossible value.
    """
    warn = warn or node.get_logger().warn
    p = AmclParams()
    for f in fields(AmclParams):
        if not node.has_param("~" + f.name):
            continue
        kind = {"int": int, "float": float, "bool": bool, "str": str}[str(f.type)]
        value = _convert(f.name, node.get_param("~" + f.name), kind)
        if f.name in _INITIAL and math.isnan(value):
            warn(f"ignoring NAN in {_INITIAL[f.name]}")
            continue
        setattr(p, f.name, value)
    if p.laser_model_type not in ("likelihood_field", "beam", "likelihood_field_prob"):
        warn(
            f'Unknown laser model type "{p.laser_model_type}"; defaulting to likelihood_field model'
        )
        p.laser_model_type = "likelihood_field"
    elif p.laser_model_type != "likelihood_field":
        warn(
            f'laser model type "{p.laser_model_type}" is not implemented in workbench; '
            "using the likelihood_field model"
        )
    if p.odom_model_type not in MODELS:
        warn(f'Unknown odom model type "{p.odom_model_type}"; defaulting to diff model')
        p.odom_model_type = "diff"
    if p.min_particles > p.max_particles:
        warn(
            "You've set min_particles to be greater than max particles, this isn't allowed "
            "so they'll be set to be equal."
        )
        p.max_particles = p.min_particles
    for name in ("min_particles", "max_particles", "resample_interval"):
        if getattr(p, name) < 1:
            raise AmclError(f"parameter ~{name} must be at least 1, got {getattr(p, name)}")
    if not 0 < p.kld_err < 1:
        raise AmclError(f"parameter ~kld_err must be between 0 and 1, got {p.kld_err}")
    if p.laser_sigma_hit <= 0:
        raise AmclError(f"parameter ~laser_sigma_hit must be positive, got {p.laser_sigma_hit}")
    p.odom_frame_id = strip_slash(p.odom_frame_id)
    p.base_frame_id = strip_slash(p.base_frame_id)
    p.global_frame_id = strip_slash(p.global_frame_id)
    return p


__all__ = ["AmclError", "AmclParams", "read_params", "strip_slash"]
