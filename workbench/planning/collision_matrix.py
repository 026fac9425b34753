"""The default self-collision matrix, computed the way MoveIt's setup assistant does.

Every pair of links that carry collision geometry is classified:

1. ``Adjacent`` -- the links are joined by one joint, or by a chain of joints
   through links without collision geometry.
2. ``Default`` -- they are in collision in the default state (each joint at 0,
   or mid-range when 0 is outside its limits).
3. ``Always`` -- in rounds of 200 random states, in collision in more than
   95 % of them (repeated until a round disables nothing new).
4. ``Never`` -- never seen in collision over ``samples`` random states
   (10,000 by default, seeded).

Every other pair must be checked by the planner. Collision is Drake's
SceneGraph point-pair penetration on the robot's proximity geometry, with all
of the plant's automatic collision filters lifted so that adjacent and welded
links are seen too (meshes are checked as their convex hulls, as Drake does for
penetration queries). Random states are uniform within the joint limits
(continuous joints in [-pi, pi]), drawn from ``numpy.random.default_rng(seed)``.
"""

from __future__ import annotations

import itertools
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from workbench.planning.srdf import DisabledCollision

#: Random states per round of the ``Always`` test, and the fraction that counts as always.
ALWAYS_ROUND = 200
ALWAYS_FRACTION = 0.95

Pair = tuple[str, str]


@dataclass
class CollisionMatrix:
    """The classification of every link pair with collision geometry.

    Attributes:
        links: Links with collision geometry, in the robot's order.
        reasons: Each pair ``(a, b)`` with ``a < b`` to ``Adjacent``, ``Default``,
            ``Always``, ``Never`` or ``None`` (must be checked).
        counts: How many of the sampled states (``Always`` rounds + ``Never``
            samples) had each pair in collision.
        sampled: Total number of random states checked.
        samples: The requested number of ``Never`` samples.
        seed: The seed of the random states.
        seconds: Wall time of the computation.
    """

    links: list[str]
    reasons: dict[Pair, str | None]
    counts: dict[Pair, int] = field(default_factory=dict)
    sampled: int = 0
    samples: int = 0
    seed: int = 0
    seconds: float = 0.0

    def disabled(self) -> list[DisabledCollision]:
        """The pairs that need no checking, sorted by link names (SRDF order)."""
        return [
            DisabledCollision(a, b, reason)
            for (a, b), reason in sorted(self.reasons.items())
            if reason is not None
        ]

    def enabled(self) -> list[Pair]:
        """The pairs a planner must check."""
        return sorted(p for p, reason in self.reasons.items() if reason is None)

    def summary(self) -> dict[str, int]:
        """Number of pairs per reason (``Check`` for enabled pairs) and in total."""
        out = {"Adjacent": 0, "Default": 0, "Always": 0, "Never": 0, "Check": 0}
        for reason in self.reasons.values():
            out[reason or "Check"] += 1
        out["Total"] = len(self.reasons)
        return out

    def rows(self) -> list[dict[str, Any]]:
        """One row per pair: ``link1``, ``link2``, ``reason`` and ``collision_fraction``."""
        return [
            {
                "link1": a,
                "link2": b,
                "reason": reason or "",
                "collision_fraction": self.counts.get((a, b), 0) / max(self.sampled, 1),
            }
            for (a, b), reason in sorted(self.reasons.items())
        ]

    def to_html(self, grid: bool = False) -> str:
        """The matrix as an HTML table: one row per pair, or a link-by-link grid.

        Args:
            grid: Draw the square link x link view (cells show the reason's
                initial: A(djacent), D(efault), L (always), N(ever), blank = check).
        """
        from html import escape

        colours = {
            "Adjacent": "#d9e7f7",
            "Default": "#f7e3c6",
            "Always": "#f5c6c6",
            "Never": "#dcefd9",
            None: "#ffffff",
        }
        if not grid:
            head = "<tr><th>link 1</th><th>link 2</th><th>reason</th><th>in collision</th></tr>"
            body = "".join(
                f'<tr style="background:{colours[r["reason"] or None]}">'
                f"<td>{escape(r['link1'])}</td><td>{escape(r['link2'])}</td>"
                f"<td>{r['reason'] or 'check'}</td>"
                f"<td>{100 * r['collision_fraction']:.2f} %</td></tr>"
                for r in self.rows()
            )
            return f"<table>{head}{body}</table>"
        letter = {"Adjacent": "A", "Default": "D", "Always": "L", "Never": "N", None: ""}
        head = "<tr><th></th>" + "".join(f"<th>{escape(n)}</th>" for n in self.links) + "</tr>"
        rows = []
        for a in self.links:
            cells = []
            for b in self.links:
                if a == b:
                    cells.append('<td style="background:#888"></td>')
                    continue
                reason = self.reasons[(min(a, b), max(a, b))]
                cells.append(
                    f'<td style="background:{colours[reason]};text-align:center">'
                    f"{letter[reason]}</td>"
                )
            rows.append(f"<tr><th>{escape(a)}</th>{''.join(cells)}</tr>")
        return f"<table>{head}{''.join(rows)}</table>"


def default_state(lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """MoveIt's default state: 0 where 0 is within the limits, else the middle of the range."""
    lower = np.asarray(lower, dtype=float)
    upper = np.asarray(upper, dtype=float)
    finite = np.isfinite(lower) & np.isfinite(upper)
    middle = np.where(
        finite, 0.5 * (np.where(finite, lower, 0.0) + np.where(finite, upper, 0.0)), 0.0
    )
    return np.where((lower <= 0.0) & (upper >= 0.0), 0.0, middle)


def sampling_bounds(lower: np.ndarray, upper: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Finite bounds for uniform sampling: unlimited joints use [-pi, pi]."""
    lo = np.where(np.isfinite(lower), lower, -np.pi)
    hi = np.where(np.isfinite(upper), upper, np.pi)
    return lo, hi


def adjacent_pairs(robot: Any, geometry_links: set[str]) -> set[Pair]:
    """Pairs joined by a joint, or through links without collision geometry (MoveIt's rule)."""
    graph: dict[str, set[str]] = {}
    for j in robot.joints:
        graph.setdefault(j.parent, set()).add(j.child)
        graph.setdefault(j.child, set()).add(j.parent)
    changed = True
    while changed:
        changed = False
        for link, neighbours in list(graph.items()):
            if link in geometry_links:
                continue
            for a, b in itertools.combinations(sorted(neighbours), 2):
                if b not in graph[a]:
                    graph[a].add(b)
                    graph[b].add(a)
                    changed = True
    pairs: set[Pair] = set()
    for a, neighbours in graph.items():
        for b in neighbours:
            if a != b and a in geometry_links and b in geometry_links:
                pairs.add((min(a, b), max(a, b)))
    return pairs


class SelfCollisionProbe:
    """Lists the colliding link pairs of one robot at given joint positions.

    Loads its own copy of the robot into a fresh Drake diagram, lifts the
    plant's collision filters between the robot's links, and answers
    :meth:`colliding_pairs` from SceneGraph's point-pair penetration query.

    Args:
        source: A ``urdf/`` name, a path, a ``RobotDescription`` or a loaded ``Robot``
            (its description is reused, the file is not read again).
    """

    def __init__(self, source: Any) -> None:
        from pydrake.geometry import CollisionFilterDeclaration, GeometrySet, Role
        from pydrake.systems.framework import DiagramBuilder

        from workbench.model import load_robot

        builder = DiagramBuilder()
        self.robot = load_robot(source, builder=builder)
        self.robot.finalize()
        plant, scene_graph = self.robot.plant, self.robot.scene_graph
        self._diagram = builder.Build()
        self._context = self._diagram.CreateDefaultContext()
        self._plant = plant
        self._plant_context = plant.GetMyMutableContextFromRoot(self._context)
        self._sg_context = scene_graph.GetMyMutableContextFromRoot(self._context)
        self._port = scene_graph.get_query_output_port()
        inspector = scene_graph.model_inspector()
        robot_bodies = {
            plant.get_body(index).name()
            for index in plant.GetBodyIndices(self.robot.model_instance)
        }
        ids = []
        self._link_of: dict[Any, str] = {}
        for gid in inspector.GetGeometryIds(
            GeometrySet(inspector.GetAllFrameIds()), Role.kProximity
        ):
            body = plant.GetBodyFromFrameId(inspector.GetFrameId(gid))
            if body is None or body.name() not in robot_bodies:
                continue
            self._link_of[gid] = body.name()
            ids.append(gid)
        ids.sort(key=lambda g: g.get_value())
        scene_graph.collision_filter_manager(self._sg_context).Apply(
            CollisionFilterDeclaration().AllowWithin(GeometrySet(ids))
        )
        order = [link.name for link in self.robot.links]
        present = set(self._link_of.values())
        self.geometry_links: list[str] = [n for n in order if n in present]
        self.geometry_links += sorted(present - set(self.geometry_links))
        self.lower = np.asarray(self.robot.lower_limits, dtype=float)
        self.upper = np.asarray(self.robot.upper_limits, dtype=float)

    def colliding_pairs(self, q: np.ndarray) -> set[Pair]:
        """Link pairs ``(a, b)``, ``a < b``, whose geometries penetrate at positions ``q``."""
        self._plant.SetPositions(self._plant_context, self.robot.model_instance, q)
        pairs: set[Pair] = set()
        for hit in self._port.Eval(self._sg_context).ComputePointPairPenetration():
            a = self._link_of.get(hit.id_A)
            b = self._link_of.get(hit.id_B)
            if a is None or b is None or a == b:
                continue
            pairs.add((a, b) if a < b else (b, a))
        return pairs


def compute_collision_matrix(
    source: Any,
    *,
    samples: int = 10000,
    seed: int = 0,
    always_fraction: float = ALWAYS_FRACTION,
    progress: Callable[[int, int], None] | None = None,
) -> CollisionMatrix:
    """Classify every link pair of a robot as MoveIt's setup assistant does.

    Args:
        source: A ``urdf/`` name, a path, or a loaded ``Robot``.
        samples: Random states for the ``Never`` test (MoveIt's sampling density).
        seed: Seed of the random states.
        always_fraction: Fraction of a round's states in collision above which a
            pair is ``Always`` in collision.
        progress: Called as ``progress(done, total)`` during the ``Never`` sampling.

    Returns:
        The :class:`CollisionMatrix`.
    """
    start = time.perf_counter()
    probe = source if isinstance(source, SelfCollisionProbe) else SelfCollisionProbe(source)
    links = probe.geometry_links
    reasons: dict[Pair, str | None] = {
        (min(a, b), max(a, b)): None for a, b in itertools.combinations(links, 2)
    }
    for pair in adjacent_pairs(probe.robot, set(links)):
        reasons[pair] = "Adjacent"
    for pair in probe.colliding_pairs(default_state(probe.lower, probe.upper)):
        if reasons.get(pair, "x") is None:
            reasons[pair] = "Default"

    rng = np.random.default_rng(seed)
    lo, hi = sampling_bounds(probe.lower, probe.upper)
    counts: dict[Pair, int] = {}
    seen: set[Pair] = set()
    sampled = 0
    limit = int(ALWAYS_ROUND * always_fraction)
    while True:
        round_counts: dict[Pair, int] = {}
        for q in rng.uniform(lo, hi, size=(ALWAYS_ROUND, len(lo))):
            for pair in probe.colliding_pairs(q):
                counts[pair] = counts.get(pair, 0) + 1
                if reasons.get(pair, "x") is None:
                    round_counts[pair] = round_counts.get(pair, 0) + 1
                    seen.add(pair)
        sampled += ALWAYS_ROUND
        found = [pair for pair, n in round_counts.items() if n > limit]
        for pair in found:
            reasons[pair] = "Always"
        if not found:
            break

    batch = 1000
    done = 0
    while done < samples:
        n = min(batch, samples - done)
        for q in rng.uniform(lo, hi, size=(n, len(lo))):
            for pair in probe.colliding_pairs(q):
                counts[pair] = counts.get(pair, 0) + 1
                seen.add(pair)
        done += n
        sampled += n
        if progress is not None:
            progress(done, samples)
    for pair, reason in reasons.items():
        if reason is None and pair not in seen:
            reasons[pair] = "Never"
    return CollisionMatrix(
        links=list(links),
        reasons=reasons,
        counts=counts,
        sampled=sampled,
        samples=samples,
        seed=seed,
        seconds=time.perf_counter() - start,
    )
