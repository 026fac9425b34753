"""AMCL's likelihood-field laser model (``amcl/sensors/amcl_laser.cpp``), vectorised.

For each particle the laser sits at ``particle ⊕ laser_pose``; every ``step``-th beam
(``step = (range_count - 1) // (laser_max_beams - 1)``, at least 1, from beam 0) whose
reading is below ``range_max`` and not NaN ends at a point whose distance ``z`` to the
nearest obstacle is read from the map's distance field (off the map:
``max_occ_dist``). A beam scores ``pz = z_hit exp(-z² / 2σ²) + z_rand / range_max``
and the particle's weight is multiplied by ``1 + Σ pz³`` (amcl's "ad-hoc weighting
scheme"). Max-range readings are skipped, as amcl's ``LikelihoodFieldModel`` does.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.navigation.amcl_map import AmclMap


@dataclass
class LaserScanData:
    """One scan as amcl's ``AMCLLaserData``: ranges with bearings in the robot frame.

    Attributes:
        ranges: Readings (m); amcl's substitutions done (see :func:`prepare_ranges`).
        bearings: Beam angles in the robot's base frame (rad).
        range_max: The scan's usable maximum range (m).
    """

    ranges: np.ndarray
    bearings: np.ndarray
    range_max: float


def prepare_ranges(ranges: np.ndarray, range_min: float, range_max: float) -> np.ndarray:
    """amcl's reading substitutions: ``<= range_min`` reads ``range_max``, ``> range_max`` reads inf.

    NaN readings stay NaN (the model skips them).
    """
    ranges = np.asarray(ranges, dtype=float)
    out = ranges.copy()
    with np.errstate(invalid="ignore"):
        out[ranges <= range_min] = range_max
        out[ranges > range_max] = np.inf
    return out


def beam_indices(range_count: int, max_beams: int) -> np.ndarray:
    """The beams amcl's likelihood field uses: every ``step``-th from 0 (empty if max_beams < 2)."""
    if max_beams < 2 or range_count < 1:
        return np.zeros(0, dtype=np.int64)
    step = max((range_count - 1) // (max_beams - 1), 1)
    return np.arange(0, range_count, step, dtype=np.int64)


class LikelihoodFieldModel:
    """The likelihood-field sensor model over one map.

    Args:
        amcl_map: The map; its distance field is (re)computed with ``max_occ_dist``.
        z_hit: Weight of the Gaussian hit term (``~laser_z_hit``).
        z_rand: Weight of the random term (``~laser_z_rand``).
        sigma_hit: Std dev of the hit term (m, ``~laser_sigma_hit``).
        max_occ_dist: Distance cap of the field (m, ``~laser_likelihood_max_dist``).
        max_beams: Beams used per scan (``~laser_max_beams``).
        laser_pose: The laser's ``(x, y, theta)`` on the robot (amcl keeps theta 0 and
            folds the mounting yaw into the bearings).
    """

    def __init__(
        self,
        amcl_map: AmclMap,
        *,
        z_hit: float = 0.95,
        z_rand: float = 0.05,
        sigma_hit: float = 0.2,
        max_occ_dist: float = 2.0,
        max_beams: int = 30,
        laser_pose: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> None:
        self.map = amcl_map
        self.z_hit, self.z_rand, self.sigma_hit = float(z_hit), float(z_rand), float(sigma_hit)
        self.max_beams = int(max_beams)
        self.laser_pose = np.asarray(laser_pose, dtype=float)
        if (
            amcl_map.max_occ_dist != max_occ_dist
            or amcl_map.occ_dist.shape != amcl_map.states.shape
        ):
            amcl_map.update_cspace(max_occ_dist)
        denom = 2.0 * self.sigma_hit * self.sigma_hit
        # the hit term per cell, plus one trailing entry for endpoints off the map
        hit = self.z_hit * np.exp(-(amcl_map.occ_dist**2) / denom)
        off = self.z_hit * np.exp(-(amcl_map.max_occ_dist**2) / denom)
        self._hit = np.append(hit.reshape(-1), off)

    def beam_likelihoods(self, poses: np.ndarray, data: LaserScanData) -> np.ndarray:
        """``(N, B)`` values ``pz`` of the used beams (0 for skipped readings)."""
        index = beam_indices(len(data.ranges), self.max_beams)
        ranges = data.ranges[index]
        with np.errstate(invalid="ignore"):
            used = np.isfinite(ranges) & (ranges < data.range_max)
        ranges, bearings = ranges[used], data.bearings[index][used]
        lx, ly, lt = self.laser_pose
        cos_t, sin_t = np.cos(poses[:, 2]), np.sin(poses[:, 2])
        sx = poses[:, 0] + cos_t * lx - sin_t * ly
        sy = poses[:, 1] + sin_t * lx + cos_t * ly
        angle = (poses[:, 2] + lt)[:, None] + bearings[None, :]
        hx = sx[:, None] + ranges[None, :] * np.cos(angle)
        hy = sy[:, None] + ranges[None, :] * np.sin(angle)
        m = self.map
        i, j, valid = m.cells_of(hx, hy)
        flat = np.where(valid, j * m.size_x + i, len(self._hit) - 1)
        return self._hit[flat] + self.z_rand / data.range_max

    def likelihoods(self, poses: np.ndarray, data: LaserScanData) -> np.ndarray:
        """``(N,)`` factors ``1 + Σ pz³`` for particles at ``poses`` (``LikelihoodFieldModel``)."""
        pz = self.beam_likelihoods(poses, data)
        return 1.0 + np.einsum("ij,ij,ij->i", pz, pz, pz)


__all__ = ["LaserScanData", "LikelihoodFieldModel", "beam_indices", "prepare_ranges"]
