"""AMCL without the bus: the decisions of ``AmclNode::laserReceived`` on odometry and scans.

A :class:`Localizer` owns the filter, the motion model and the laser model of one map.
Each scan comes with the odometry pose of the robot at the scan's stamp; the filter
moves and weighs only after the odometry changed by more than ``update_min_d`` in x
or y or ``update_min_a`` in heading since the last update (or when an update is forced),
and resamples every ``resample_interval``-th update. The very first scan after an
(re)initialisation only records the odometry pose, and the pose is then published at
once. The pose hypothesis is the mean of the heaviest cluster, with the covariance of
the whole particle set, as amcl publishes it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.navigation.amcl_filter import ParticleFilter
from workbench.navigation.amcl_laser import LaserScanData, LikelihoodFieldModel
from workbench.navigation.amcl_map import AmclMap
from workbench.navigation.amcl_motion import OdomModel, angle_diff
from workbench.navigation.amcl_params import AmclParams


@dataclass
class Estimate:
    """What one scan produced.

    Attributes:
        weighed: The particles were weighed by the scan.
        updated: The filter moved and weighed the particles.
        resampled: It also resampled them.
        publish: A new pose is to be published (after a resample or the first scan).
        pose: The heaviest cluster's mean ``(x, y, theta)`` in the map frame.
        cov: ``(3, 3)`` covariance of the particle set (x, y, theta).
    """

    weighed: bool = False
    updated: bool = False
    resampled: bool = False
    publish: bool = False
    pose: np.ndarray | None = None
    cov: np.ndarray | None = None


class Localizer:
    """AMCL's filter, models and update rules over one map.

    Args:
        amcl_map: The map (its distance field is computed here).
        params: The parameters.
        seed: Seed of every random draw (``~seed``).
    """

    def __init__(self, amcl_map: AmclMap, params: AmclParams, seed: int | None = None) -> None:
        self.map = amcl_map
        self.params = p = params
        self.rng = np.random.default_rng(p.seed if seed is None else seed)
        self.pf = ParticleFilter(
            p.min_particles,
            p.max_particles,
            p.recovery_alpha_slow,
            p.recovery_alpha_fast,
            amcl_map.uniform_poses,
            pop_err=p.kld_err,
            pop_z=p.kld_z,
            rng=self.rng,
            selective_resampling=p.selective_resampling,
        )
        self.odom = OdomModel(
            p.odom_model_type,
            p.odom_alpha1,
            p.odom_alpha2,
            p.odom_alpha3,
            p.odom_alpha4,
            p.odom_alpha5,
        )
        self.laser = LikelihoodFieldModel(
            amcl_map,
            z_hit=p.laser_z_hit,
            z_rand=p.laser_z_rand,
            sigma_hit=p.laser_sigma_hit,
            max_occ_dist=p.laser_likelihood_max_dist,
            max_beams=p.laser_max_beams,
        )
        self.pf_init = False
        self.pf_odom_pose = np.zeros(3)
        self.resample_count = 0
        self.force_update = False
        self.updates = 0
        self.pf.init_gaussian(
            np.array([p.initial_pose_x, p.initial_pose_y, p.initial_pose_a]),
            np.diag([p.initial_cov_xx, p.initial_cov_yy, p.initial_cov_aa]),
        )

    def set_pose(self, mean: np.ndarray, cov: np.ndarray) -> None:
        """Restart the filter around ``mean`` with ``(3, 3)`` ``cov`` (``applyInitialPose``)."""
        self.pf.init_gaussian(mean, cov)
        self.pf_init = False

    def global_localization(self) -> None:
        """Spread the particles uniformly over free space (``global_localization``)."""
        self.pf.init_uniform()
        self.pf_init = False

    def set_laser_pose(self, x: float, y: float) -> None:
        """The laser's position on the robot (m); its yaw goes into the bearings."""
        self.laser.laser_pose = np.array([x, y, 0.0])

    def process(self, odom_pose: np.ndarray, scan: LaserScanData) -> Estimate:
        """Handle one scan whose robot odometry pose is ``odom_pose`` (odom frame)."""
        odom_pose = np.asarray(odom_pose, dtype=float)
        p, out = self.params, Estimate()
        if not self.pf_init:
            self.pf_odom_pose = odom_pose.copy()
            self.pf_init = True
            self.resample_count = 0
            out.publish = True
            update = True
            first = True
        else:
            delta = odom_pose - self.pf_odom_pose
            delta[2] = angle_diff(odom_pose[2], self.pf_odom_pose[2])
            update = (
                abs(delta[0]) > p.update_min_d
                or abs(delta[1]) > p.update_min_d
                or abs(delta[2]) > p.update_min_a
                or self.force_update
            )
            self.force_update = False
            first = False
            if update:
                self.odom.sample(self.pf.poses, odom_pose, delta, self.rng)
        if update:
            self.pf.update_sensor(self.laser.likelihoods(self.pf.poses, scan))
            self.pf_odom_pose = odom_pose.copy()
            self.updates += 1
            out.weighed, out.updated = True, not first
            self.resample_count += 1
            if self.resample_count % max(p.resample_interval, 1) == 0:
                self.pf.resample()
                out.resampled = out.publish = True
        if out.publish:
            best = self.pf.best_cluster()
            if best is not None:
                out.pose, out.cov = best.mean.copy(), self.pf.cov.copy()
            else:
                out.publish = False
        return out


__all__ = ["Estimate", "Localizer"]
