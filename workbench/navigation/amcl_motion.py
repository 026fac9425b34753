"""AMCL's odometry motion models (``amcl/sensors/amcl_odom.cpp``), vectorised over particles.

``diff`` and ``omni`` are amcl's original models, which pass the *variance* expressions
of Probabilistic Robotics to the Gaussian sampler as standard deviations;
``diff-corrected`` and ``omni-corrected`` take their square roots (and the corrected
omni model pairs the alphas differently), exactly as amcl does. The odometry change
``delta`` is the difference of two odometry poses in the odometry frame, its angle
wrapped (``AmclNode::laserReceived``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: ``odom_model_type`` values amcl accepts.
MODELS = ("diff", "omni", "diff-corrected", "omni-corrected")


def normalize(z: np.ndarray | float) -> np.ndarray | float:
    """Angle in ``(-pi, pi]`` (amcl's ``normalize``)."""
    return np.arctan2(np.sin(z), np.cos(z))


def angle_diff(a: np.ndarray | float, b: np.ndarray | float) -> np.ndarray | float:
    """The signed smallest difference ``a - b`` (amcl's ``angle_diff``), rad."""
    d1 = np.asarray(normalize(a)) - np.asarray(normalize(b))
    d2 = 2 * np.pi - np.abs(d1)
    d2 = np.where(d1 > 0, -d2, d2)
    out = np.where(np.abs(d1) < np.abs(d2), d1, d2)
    return float(out) if out.ndim == 0 else out


def _scalar_diff(a: float, b: float) -> float:
    return float(angle_diff(a, b))


@dataclass(frozen=True)
class OdomModel:
    """An odometry motion model with its noise parameters.

    Attributes:
        model_type: One of :data:`MODELS`.
        alpha1: Rotation noise from rotation (``~odom_alpha1``).
        alpha2: Rotation noise from translation (``~odom_alpha2``).
        alpha3: Translation noise from translation (``~odom_alpha3``).
        alpha4: Translation noise from rotation (``~odom_alpha4``).
        alpha5: Strafe noise from translation, omni models only (``~odom_alpha5``).
    """

    model_type: str = "diff"
    alpha1: float = 0.2
    alpha2: float = 0.2
    alpha3: float = 0.2
    alpha4: float = 0.2
    alpha5: float = 0.2

    def sample(
        self, poses: np.ndarray, odom_pose: np.ndarray, delta: np.ndarray, rng: np.random.Generator
    ) -> None:
        """Move every particle by a noisy copy of the odometry change, in place.

        Args:
            poses: ``(N, 3)`` particle poses ``(x, y, theta)`` in the map frame; updated.
            odom_pose: The new odometry pose ``(x, y, theta)`` (odometry frame).
            delta: Odometry change since the last update ``(dx, dy, dtheta)``.
            rng: The random generator.
        """
        if self.model_type in ("omni", "omni-corrected"):
            self._omni(poses, odom_pose, delta, rng)
        else:
            self._diff(poses, odom_pose, delta, rng)
        poses[:, 2] = normalize(poses[:, 2])

    def _diff(
        self, poses: np.ndarray, odom_pose: np.ndarray, delta: np.ndarray, rng: np.random.Generator
    ) -> None:
        old_theta = odom_pose[2] - delta[2]
        trans = float(np.hypot(delta[0], delta[1]))
        # in-place rotation: no bearing from two nearly equal positions
        rot1 = 0.0 if trans < 0.01 else _scalar_diff(np.arctan2(delta[1], delta[0]), old_theta)
        rot2 = _scalar_diff(delta[2], rot1)
        # backward and forward motion get the same noise
        rot1_noise = min(abs(_scalar_diff(rot1, 0.0)), abs(_scalar_diff(rot1, np.pi)))
        rot2_noise = min(abs(_scalar_diff(rot2, 0.0)), abs(_scalar_diff(rot2, np.pi)))
        a1, a2, a3, a4 = self.alpha1, self.alpha2, self.alpha3, self.alpha4
        sd_rot1 = a1 * rot1_noise**2 + a2 * trans**2
        sd_trans = a3 * trans**2 + a4 * rot1_noise**2 + a4 * rot2_noise**2
        sd_rot2 = a1 * rot2_noise**2 + a2 * trans**2
        if self.model_type == "diff-corrected":
            sd_rot1, sd_trans, sd_rot2 = np.sqrt([sd_rot1, sd_trans, sd_rot2])
        noise = rng.standard_normal((len(poses), 3))
        rot1_hat = angle_diff(rot1, noise[:, 0] * sd_rot1)
        trans_hat = trans - noise[:, 1] * sd_trans
        rot2_hat = angle_diff(rot2, noise[:, 2] * sd_rot2)
        heading = poses[:, 2] + rot1_hat
        poses[:, 0] += trans_hat * np.cos(heading)
        poses[:, 1] += trans_hat * np.sin(heading)
        poses[:, 2] += rot1_hat + rot2_hat

    def _omni(
        self, poses: np.ndarray, odom_pose: np.ndarray, delta: np.ndarray, rng: np.random.Generator
    ) -> None:
        old_theta = odom_pose[2] - delta[2]
        trans = float(np.hypot(delta[0], delta[1]))
        rot = float(delta[2])
        a1, a2, a3, a4, a5 = self.alpha1, self.alpha2, self.alpha3, self.alpha4, self.alpha5
        if self.model_type == "omni-corrected":
            sd_trans = np.sqrt(a3 * trans**2 + a4 * rot**2)
            sd_rot = np.sqrt(a1 * rot**2 + a2 * trans**2)
            sd_strafe = np.sqrt(a4 * rot**2 + a5 * trans**2)
        else:
            sd_trans = a3 * trans**2 + a1 * rot**2
            sd_rot = a4 * rot**2 + a2 * trans**2
            sd_strafe = a1 * rot**2 + a5 * trans**2
        noise = rng.standard_normal((len(poses), 3))
        bearing = angle_diff(np.arctan2(delta[1], delta[0]), old_theta) + poses[:, 2]
        cs, sn = np.cos(bearing), np.sin(bearing)
        trans_hat = trans + noise[:, 0] * sd_trans
        rot_hat = rot + noise[:, 1] * sd_rot
        strafe_hat = noise[:, 2] * sd_strafe
        poses[:, 0] += trans_hat * cs + strafe_hat * sn
        poses[:, 1] += trans_hat * sn - strafe_hat * cs
        poses[:, 2] += rot_hat


__all__ = ["MODELS", "OdomModel", "angle_diff", "normalize"]
