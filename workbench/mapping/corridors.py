"""A simulated corridor log: a ring of long corridors driven twice, odometry with systematic error.

Long corridors are where scan matching is weakest: two parallel walls pin
the robot across the corridor and in heading, but hardly along it. The
floor plan is a ring of 2 m wide corridors round a block of rooms (a few
doors open onto the corridor) with two rooms outside the ring. The robot
follows the centre line of the ring twice. Its odometry has a systematic
scale error, a systematic heading error on turns and a small heading drift
per metre (a wheel-diameter mismatch), plus random noise. The laser has a
maximum range; beams that hit nothing within it read exactly that range
(no return), as real lasers report.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.mapping.geometry import between, compose, wrap_angle
from workbench.mapping.scan import Scan
from workbench.mapping.simulate import raycast


def wall(a: tuple[float, float], b: tuple[float, float], doors: tuple[float, ...] = ()) -> list:
    """Segments of a straight wall from ``a`` to ``b`` with 1 m doors centred ``doors`` m from ``a``."""
    start, end = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    length = float(np.hypot(*(end - start)))
    unit = (end - start) / length
    cuts = [0.0]
    for d in sorted(doors):
        cuts += [d - 0.5, d + 0.5]
    cuts.append(length)
    return [
        [start + unit * cuts[k], start + unit * cuts[k + 1]]
        for k in range(0, len(cuts), 2)
        if cuts[k + 1] > cuts[k]
    ]


@dataclass
class CorridorWorld:
    """A ring of corridors round a block of rooms.

    Attributes:
        segments: The walls, ``(N, 2, 2)`` segments (m).
        path: The centre line of the ring as a closed polygon ``(K, 2)`` (m), counter-clockwise.
        width: Corridor width (m).
    """

    segments: np.ndarray
    path: np.ndarray
    width: float


def corridor_world(length: float = 40.0, depth: float = 20.0, width: float = 2.0) -> CorridorWorld:
    """A ``length`` x ``depth`` m ring of ``width`` m corridors with rooms inside and out.

    The inner block is split into rooms by cross walls; each long side has
    two doors, each short side one. Two rooms lie outside the ring (beside
    the bottom corridor), each with a door onto it.
    """
    w = width
    x0, y0, x1, y1 = 0.0, 0.0, length, depth
    segs: list = []
    # Outer wall, with two doors into the outside rooms along the bottom corridor.
    segs += wall((x0, y0), (x1, y0), doors=(0.3 * length, 0.7 * length))
    segs += wall((x1, y0), (x1, y1))
    segs += wall((x1, y1), (x0, y1))
    segs += wall((x0, y1), (x0, y0))
    # Inner block: doors at a quarter and at two thirds of the long sides, mid short sides.
    ix0, iy0, ix1, iy1 = x0 + w, y0 + w, x1 - w, y1 - w
    inner_len, inner_dep = ix1 - ix0, iy1 - iy0
    segs += wall((ix0, iy0), (ix1, iy0), doors=(0.2 * inner_len, 0.62 * inner_len))
    segs += wall((ix1, iy0), (ix1, iy1), doors=(0.5 * inner_dep,))
    segs += wall((ix1, iy1), (ix0, iy1), doors=(0.35 * inner_len, 0.8 * inner_len))
    segs += wall((ix0, iy1), (ix0, iy0), doors=(0.5 * inner_dep,))
    # Rooms inside the block: cross walls and a spine.
    mid_y = 0.5 * (iy0 + iy1)
    segs += wall((ix0, mid_y), (ix1, mid_y), doors=(0.5 * inner_len,))
    for fraction in (0.4, 0.75):
        x = ix0 + fraction * inner_len
        segs += wall((x, iy0), (x, iy1), doors=(0.25 * inner_dep, 0.75 * inner_dep))
    # Two rooms below the bottom corridor, 4 m deep, with a table-like box in one.
    for left, right in ((0.2 * length, 0.4 * length), (0.6 * length, 0.8 * length)):
        segs += wall((left, y0), (left, y0 - 4.0))
        segs += wall((left, y0 - 4.0), (right, y0 - 4.0))
        segs += wall((right, y0 - 4.0), (right, y0))
    cx = 0.65 * length
    segs += [
        [(cx, -2.5), (cx + 1.2, -2.5)],
        [(cx + 1.2, -2.5), (cx + 1.2, -1.8)],
        [(cx + 1.2, -1.8), (cx, -1.8)],
        [(cx, -1.8), (cx, -2.5)],
    ]
    h = 0.5 * w
    path = np.array([[x0 + h, y0 + h], [x1 - h, y0 + h], [x1 - h, y1 - h], [x0 + h, y1 - h]])
    return CorridorWorld(np.asarray(segs, dtype=float).reshape(-1, 2, 2), path, w)


def ring_trajectory(
    corners: np.ndarray, step: float, laps: int = 2, turn_radius: float = 0.5
) -> np.ndarray:
    """Poses ``(N, 3)`` every ``step`` m round a closed polygon ``laps`` times, corners rounded.

    Starts in the middle of the first side so that the first lap's end
    rejoins its start inside a corridor.
    """
    corners = np.asarray(corners, dtype=float)
    n = len(corners)
    pieces = []  # dense polyline of one lap
    start = 0.5 * (corners[0] + corners[1])
    pieces.append(start[None])
    for k in range(n):
        a, b, c = corners[(k) % n], corners[(k + 1) % n], corners[(k + 2) % n]
        u1 = (b - a) / np.hypot(*(b - a))
        u2 = (c - b) / np.hypot(*(c - b))
        p_in, p_out = b - u1 * turn_radius, b + u2 * turn_radius
        t = np.linspace(0.0, 1.0, 40)[:, None]
        # A quadratic Bezier round the corner.
        arc = (1 - t) ** 2 * p_in + 2 * (1 - t) * t * b + t**2 * p_out
        pieces.append(arc)
    pieces.append(start[None])
    lap = np.concatenate(pieces)
    dense = np.concatenate([lap] + [lap[1:]] * (laps - 1))
    seg = np.hypot(*np.diff(dense, axis=0).T)
    along = np.concatenate([[0.0], np.cumsum(seg)])
    samples = np.arange(0.0, along[-1], step)
    x = np.interp(samples, along, dense[:, 0])
    y = np.interp(samples, along, dense[:, 1])
    heading = np.unwrap(np.arctan2(np.gradient(y), np.gradient(x)))
    return np.column_stack([x, y, wrap_angle(heading)])


def biased_odometry(
    truth: np.ndarray,
    *,
    scale: float,
    turn_scale: float,
    drift: float,
    noise: tuple[float, float],
    seed: int,
) -> np.ndarray:
    """Odometry ``(N, 3)`` from true poses with systematic and random error.

    Each true step's translation is multiplied by ``1 + scale``, its rotation by
    ``1 + turn_scale``, ``drift`` rad per metre is added to the heading, and
    Gaussian noise of ``noise`` (m per m, rad per m) std dev per step is added.
    """
    rng = np.random.default_rng(seed)
    out = [np.asarray(truth[0], dtype=float).copy()]
    for k in range(1, len(truth)):
        d = between(truth[k - 1], truth[k])
        dist = float(np.hypot(d[0], d[1]))
        step = np.array(
            [
                d[0] * (1 + scale) + rng.normal(0.0, noise[0] * dist + 1e-4),
                d[1] * (1 + scale) + rng.normal(0.0, noise[0] * dist + 1e-4),
                d[2] * (1 + turn_scale) + drift * dist + rng.normal(0.0, noise[1] * dist + 1e-4),
            ]
        )
        out.append(compose(out[-1], step))
    return np.array(out)


@dataclass
class CorridorLog:
    """A simulated corridor log.

    Attributes:
        scans: Scans in time order; ``reference`` is the true pose, ``odom`` the odometry.
        world: The floor plan.
        truth: True sensor poses ``(N, 3)``.
        odometry: Odometry poses ``(N, 3)``.
        errors: The drawn systematic errors (``scale``, ``turn_scale``, ``drift``).
    """

    scans: list[Scan]
    world: CorridorWorld
    truth: np.ndarray
    odometry: np.ndarray
    errors: dict[str, float]


def corridor_log(
    seed: int = 0,
    *,
    beams: int = 360,
    fov: float = 2.0 * np.pi,
    max_range: float = 30.0,
    step: float = 0.1,
    rate: float = 5.0,
    laps: int = 2,
    range_noise: float = 0.01,
    scale_error: float = 0.03,
    heading_error: float = 0.03,
    length: float = 40.0,
    depth: float = 20.0,
) -> CorridorLog:
    """The corridor world driven ``laps`` times with seeded, systematically wrong odometry.

    Args:
        seed: Seeds the systematic errors' signs and sizes and all noise.
        beams: Beams per scan over ``fov`` (360 over 360 degrees: 1 degree apart).
        fov: Field of view (rad), centred ahead.
        max_range: Laser range (m); beams hitting nothing read exactly this.
        step: Travel between scans (m).
        rate: Scans per second (sets the stamps).
        laps: Times round the ring.
        range_noise: Std dev of range noise (m).
        scale_error: Size of the odometry's translation scale error (fraction); the
            drawn error lies between 0.7 and 1.0 times this, with a random sign.
        heading_error: Size of the scale error of odometry turns (fraction), drawn alike.
        length, depth: Outer size of the ring (m).
    """
    rng = np.random.default_rng(seed)
    world = corridor_world(length, depth)
    truth = ring_trajectory(world.path, step, laps)

    def draw(size: float) -> float:
        return float(rng.choice([-1.0, 1.0]) * rng.uniform(0.7, 1.0) * size)

    errors = {
        "scale": draw(scale_error),
        "turn_scale": draw(heading_error),
        "drift": draw(np.radians(0.1)),  # rad per metre
    }
    odometry = biased_odometry(
        truth,
        scale=errors["scale"],
        turn_scale=errors["turn_scale"],
        drift=errors["drift"],
        noise=(0.005, np.radians(0.2)),
        seed=int(rng.integers(1 << 31)),
    )
    if fov >= 2.0 * np.pi - 1e-9:
        angles = -np.pi + 2.0 * np.pi * np.arange(beams) / beams
    else:
        angles = np.linspace(-fov / 2, fov / 2, beams)
    scans = []
    for k, pose in enumerate(truth):
        ranges = raycast(world.segments, pose, angles, max_range)
        noisy = ranges + rng.normal(0.0, range_noise, beams)
        ranges = np.where(ranges >= max_range, max_range, np.minimum(noisy, max_range - 1e-3))
        scans.append(
            Scan(
                stamp=k / rate,
                ranges=ranges,
                angles=angles.copy(),
                odom=odometry[k].copy(),
                max_range=max_range,
                reference=pose.copy(),
                source=f"corridors[{k}]",
            )
        )
    return CorridorLog(scans, world, truth, odometry, errors)
