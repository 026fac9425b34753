"""AMCL's particle filter (``amcl/pf/pf.c``) with numpy arrays for the particles.

The steps are pf.c's: initialise from a Gaussian or uniformly over free space,
move by the motion model, weight by the sensor model (keeping the slow and fast
averages of the weights, Probabilistic Robotics p. 258), and resample with
KLD-adaptive sample counts, injecting random poses with probability
``max(0, 1 - w_fast / w_slow)`` (``recovery_alpha_slow`` / ``recovery_alpha_fast``).

One difference in the resampler: pf.c draws each sample independently (a "naive
discrete event sampler", because low-variance resampling does not combine easily with
KLD's sequential stopping). Here the resampler draws ``max_samples`` indices with the
low-variance (systematic) comb, shuffles them and keeps the prefix the KLD rule
accepts: a random subset of a low-variance sample, so every particle's expected
number of copies is still proportional to its weight, with less resampling noise.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from workbench.navigation.amcl_kld import (
    Cluster,
    cluster_labels,
    cluster_stats,
    kld_count,
    resample_limits,
    weighted_stats,
)
from workbench.navigation.amcl_motion import normalize

#: A generator of random poses: ``(count, rng) -> (count, 3)``.
PoseGenerator = Callable[[int, np.random.Generator], np.ndarray]


class ParticleFilter:
    """A KLD-sampling particle filter over planar poses.

    Args:
        min_samples: Fewest particles after resampling (``~min_particles``).
        max_samples: Most particles (``~max_particles``).
        alpha_slow: Decay of the slow weight average (``~recovery_alpha_slow``).
        alpha_fast: Decay of the fast weight average (``~recovery_alpha_fast``).
        random_poses: Draws random poses (uniform over the map's free space).
        pop_err: KLD error bound (``~kld_err``).
        pop_z: KLD upper standard normal quantile (``~kld_z``).
        rng: The random generator every draw uses.
        selective_resampling: Resample only when the effective sample size drops
            below half the particles (``~selective_resampling``).

    Attributes:
        poses: ``(N, 3)`` particle poses ``(x, y, theta)`` (m, rad).
        weights: ``(N,)`` normalised weights.
        clusters: The clusters of the current set, after init and each resample.
        mean: The whole set's weighted mean pose.
        cov: The whole set's ``(3, 3)`` covariance (what amcl publishes).
        converged: All particles within 0.5 m (x and y) of their mean.
    """

    dist_threshold = 0.5

    def __init__(
        self,
        min_samples: int,
        max_samples: int,
        alpha_slow: float,
        alpha_fast: float,
        random_poses: PoseGenerator,
        *,
        pop_err: float = 0.01,
        pop_z: float = 0.99,
        rng: np.random.Generator | None = None,
        selective_resampling: bool = False,
    ) -> None:
        self.min_samples, self.max_samples = int(min_samples), int(max_samples)
        self.alpha_slow, self.alpha_fast = float(alpha_slow), float(alpha_fast)
        self.random_poses = random_poses
        self.rng = rng if rng is not None else np.random.default_rng(0)
        self.selective_resampling = bool(selective_resampling)
        self.limits = resample_limits(self.min_samples, self.max_samples, pop_err, pop_z)
        self.poses = np.zeros((self.max_samples, 3))
        self.weights = np.full(self.max_samples, 1.0 / self.max_samples)
        self.w_slow = self.w_fast = 0.0
        self.n_effective = float(self.max_samples)
        self.clusters: list[Cluster] = []
        self.mean = np.zeros(3)
        self.cov = np.zeros((3, 3))
        self.converged = False

    @property
    def count(self) -> int:
        """The number of particles now."""
        return len(self.poses)

    # ------------------------------------------------------------------ init
    def init_gaussian(self, mean: np.ndarray, cov: np.ndarray) -> None:
        """``max_samples`` particles from a Gaussian (``pf_init``); covariance via its eigenbasis."""
        values, vectors = np.linalg.eigh(np.asarray(cov, dtype=float))
        spread = np.sqrt(np.clip(values, 0.0, None))
        draws = self.rng.standard_normal((self.max_samples, 3)) * spread
        poses = np.asarray(mean, dtype=float) + draws @ vectors.T
        poses[:, 2] = normalize(poses[:, 2])
        self._reset(poses)

    def init_uniform(self) -> None:
        """``max_samples`` particles from the random pose generator (``pf_init_model``)."""
        self._reset(self.random_poses(self.max_samples, self.rng))

    def _reset(self, poses: np.ndarray) -> None:
        self.poses = poses
        self.weights = np.full(len(poses), 1.0 / len(poses))
        self.w_slow = self.w_fast = 0.0
        self.update_clusters()
        self.converged = False

    # --------------------------------------------------------------- updates
    def update_sensor(self, likelihoods: np.ndarray) -> None:
        """Multiply the weights by ``likelihoods`` and normalise (``pf_update_sensor``)."""
        weights = self.weights * likelihoods
        total = float(weights.sum())
        if total > 0.0 and np.isfinite(total):
            w_avg = total / len(weights)
            self.weights = weights / total
            self.w_slow = (
                w_avg
                if self.w_slow == 0.0
                else self.w_slow + self.alpha_slow * (w_avg - self.w_slow)
            )
            self.w_fast = (
                w_avg
                if self.w_fast == 0.0
                else self.w_fast + self.alpha_fast * (w_avg - self.w_fast)
            )
            self.n_effective = 1.0 / float(np.sum(self.weights**2))
        else:
            self.weights = np.full(len(weights), 1.0 / len(weights))
            self.n_effective = float(len(weights))

    def resample(self) -> None:
        """Draw a new set with a KLD-adaptive size and random-pose injection (``pf_update_resample``)."""
        if self.selective_resampling and self.n_effective > 0.5 * self.count:
            self.update_clusters()
            return
        w_diff = 0.0 if self.w_slow <= 0.0 else max(0.0, 1.0 - self.w_fast / self.w_slow)
        m = self.max_samples
        cumulative = np.cumsum(self.weights)
        comb = (self.rng.random() + np.arange(m)) / m * cumulative[-1]
        index = np.minimum(np.searchsorted(cumulative, comb, side="right"), self.count - 1)
        poses = self.poses[self.rng.permutation(index)]
        inject = self.rng.random(m) < w_diff
        if inject.any():
            poses[inject] = self.random_poses(int(inject.sum()), self.rng)
        poses = poses[: kld_count(poses, self.limits)]
        if w_diff > 0.0:
            self.w_slow = self.w_fast = 0.0
        self.poses = poses
        self.weights = np.full(len(poses), 1.0 / len(poses))
        self.update_clusters()
        self.update_converged()

    # ------------------------------------------------------------ statistics
    def update_clusters(self) -> None:
        """Recompute the clusters and the set's mean and covariance (``pf_cluster_stats``)."""
        labels = cluster_labels(self.poses)
        self.clusters = cluster_stats(self.poses, self.weights, labels)
        self.mean, self.cov = weighted_stats(self.poses, self.weights)

    def update_converged(self) -> bool:
        """Whether every particle lies within 0.5 m of the mean in x and y (``pf_update_converged``)."""
        centre = self.poses[:, :2].mean(axis=0)
        self.converged = bool(np.all(np.abs(self.poses[:, :2] - centre) <= self.dist_threshold))
        return self.converged

    def best_cluster(self) -> Cluster | None:
        """The cluster of greatest weight (amcl's pose hypothesis), None if none weighs anything."""
        best = max(self.clusters, key=lambda c: c.weight, default=None)
        return best if best is not None and best.weight > 0.0 else None


__all__ = ["ParticleFilter", "PoseGenerator"]
