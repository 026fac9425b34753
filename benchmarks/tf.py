"""tf lookups and inserts: workbench's Buffer against a plain scipy-Rotation implementation.

Run ``python benchmarks/tf.py`` (``--quick`` for a short run). A chain of 20
moving frames is filled with 100 stamps each (10 ms apart, random poses, seeded);
lookups are timed at random interpolated times over 1-, 5- and 20-hop paths.

* ``workbench core``: ``BufferCore.lookup`` (tuples out, tf2's full semantics:
  validation, tree walk, extrapolation checks).
* ``workbench msg``: ``Buffer.lookup_transform`` (a geometry_msgs/TransformStamped out).
* ``scipy baseline``: the same chain walked with precomputed per-frame
  ``scipy.spatial.transform.Slerp`` objects, ``np.searchsorted``, linear
  interpolation of translations and ``Rotation`` composition -- what one would
  write with scipy directly, knowing the path in advance.

Inserts: ``BufferCore.set_transform_values`` and ``Buffer.set_transform``
(message in) against appending to per-frame lists with ``Rotation.from_quat``.
Prints a table with the machine and writes ``benchmarks/results/tf.json``.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation, Slerp

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from machine import describe  # noqa: E402

from workbench.tf import Buffer, BufferCore  # noqa: E402
from workbench.tf.broadcaster import make_transform  # noqa: E402

SEED = 0
FRAMES = 21  # f0 (root) .. f20
STAMPS = 100
DT = 0.01
T0 = 1000.0


def make_data(rng: np.random.Generator):
    translations = rng.uniform(-1, 1, size=(FRAMES, STAMPS, 3))
    quats = Rotation.random(FRAMES * STAMPS, random_state=rng).as_quat().reshape(FRAMES, STAMPS, 4)
    stamps = T0 + DT * np.arange(STAMPS)
    return stamps, translations, quats


class ScipyChain:
    """The baseline: per-frame arrays and Slerp objects, walking a known chain."""

    def __init__(self, stamps, translations, quats) -> None:
        self.stamps = stamps
        self.translations = translations
        self.slerps = [None] + [
            Slerp(stamps, Rotation.from_quat(quats[i])) for i in range(1, FRAMES)
        ]

    def lookup(self, hops: int, t: float) -> tuple[np.ndarray, np.ndarray]:
        """Pose of frame ``hops`` in frame 0 at time ``t``."""
        i = int(np.searchsorted(self.stamps, t))
        s0, s1 = self.stamps[i - 1], self.stamps[i]
        r = (t - s0) / (s1 - s0)
        p = np.zeros(3)
        rot = Rotation.identity()
        for frame in range(hops, 0, -1):  # accumulate child-most first: X = X_edge * X
            tr = self.translations[frame]
            edge_p = tr[i - 1] + (tr[i] - tr[i - 1]) * r
            edge_r = self.slerps[frame](t)
            p = edge_r.apply(p) + edge_p
            rot = edge_r * rot
        return p, rot.as_quat()


REPEATS = 3


def timed(fn, n: int) -> float:
    """The best of REPEATS wall times of ``fn(n)`` (the machine is shared; the minimum is the
    least disturbed run)."""
    best = math.inf
    for _ in range(REPEATS):
        start = time.perf_counter()
        fn(n)
        best = min(best, time.perf_counter() - start)
    return best


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer repetitions")
    args = parser.parse_args()
    n_lookup = 2000 if args.quick else 20000
    n_base = 500 if args.quick else 3000
    rng = np.random.default_rng(SEED)
    stamps, translations, quats = make_data(rng)

    core, buf = BufferCore(), Buffer()
    for k, s in enumerate(stamps):
        for f in range(1, FRAMES):
            core.set_transform_values(
                f"f{f - 1}", f"f{f}", translations[f, k], quats[f, k], float(s)
            )
            buf.set_transform(
                make_transform(f"f{f - 1}", f"f{f}", translations[f, k], quats[f, k], float(s)), "b"
            )
    base = ScipyChain(stamps, translations, quats)
    times = rng.uniform(stamps[0], stamps[-1], size=n_lookup)

    rows = []
    for hops in (1, 5, 20):
        target, source = "f0", f"f{hops}"
        # the same answers first
        worst = 0.0
        for t in times[:200]:
            got = core.lookup(target, source, float(t))
            p, q = base.lookup(hops, float(t))
            worst = max(worst, float(np.abs(np.asarray(got.translation) - p).max()))
            dq = min(
                np.abs(np.asarray(got.rotation) - q).max(),
                np.abs(np.asarray(got.rotation) + q).max(),
            )
            worst = max(worst, float(dq))
        ts = [float(t) for t in times]

        def run_core(n, ts=ts, target=target, source=source):
            lookup = core.lookup
            for t in ts[:n]:
                lookup(target, source, t)

        def run_msg(n, ts=ts, target=target, source=source):
            lookup = buf.lookup_transform
            for t in ts[:n]:
                lookup(target, source, t)

        def run_base(n, ts=ts, hops=hops):
            for t in ts[:n]:
                base.lookup(hops, t)

        rate_core = n_lookup / timed(run_core, n_lookup)
        rate_msg = n_lookup / timed(run_msg, n_lookup)
        rate_base = n_base / timed(run_base, n_base)
        rows.append(
            {
                "case": f"lookup {hops}-hop",
                "workbench_core_per_s": rate_core,
                "workbench_msg_per_s": rate_msg,
                "scipy_baseline_per_s": rate_base,
                "ratio_core_vs_baseline": rate_core / rate_base,
                "max_abs_difference": worst,
            }
        )

    # inserts: a fresh frame per run so nothing is refused as old or repeated
    n_ins = 20000 if args.quick else 100000
    ins_t = T0 + 1e-3 * np.arange(n_ins)
    ins_tr = rng.uniform(-1, 1, size=(n_ins, 3)).tolist()
    ins_q = Rotation.random(n_ins, random_state=rng).as_quat().tolist()
    ins_s = ins_t.tolist()

    def insert_core(n):
        b = BufferCore(cache_time=1e6)
        put = b.set_transform_values
        for i in range(n):
            put("parent", "child", ins_tr[i], ins_q[i], ins_s[i])

    msgs = [make_transform("parent", "child", ins_tr[i], ins_q[i], ins_s[i]) for i in range(n_ins)]

    def insert_msg(n):
        b = Buffer(cache_time=1e6)
        put = b.set_transform
        for i in range(n):
            put(msgs[i], "bench")

    def insert_base(n):
        st, tr, rot = [], [], []
        for i in range(n):
            st.append(ins_s[i])
            tr.append(np.asarray(ins_tr[i]))
            rot.append(Rotation.from_quat(ins_q[i]))

    rate_core = n_ins / timed(insert_core, n_ins)
    rate_msg = n_ins / timed(insert_msg, n_ins)
    rate_base = n_ins / timed(insert_base, n_ins)
    rows.append(
        {
            "case": "set_transform",
            "workbench_core_per_s": rate_core,
            "workbench_msg_per_s": rate_msg,
            "scipy_baseline_per_s": rate_base,
            "ratio_core_vs_baseline": rate_core / rate_base,
            "max_abs_difference": 0.0,
        }
    )

    machine = describe(("numpy", "scipy"), seed=SEED, quick=args.quick, repeats=REPEATS)
    print(
        f"machine: {machine['cpu']}, {machine['cores']} cores, Python {machine['python']}, "
        f"numpy {machine['numpy']}, scipy {machine['scipy']}, seed {SEED}"
    )
    print(
        f"{FRAMES - 1} moving frames x {STAMPS} stamps; lookups at random interpolated times; "
        f"best of {REPEATS}; load average {machine['load_average'][0]:.1f}\n"
    )
    header = f"{'case':<16}{'core /s':>12}{'msg /s':>12}{'scipy /s':>12}{'core/scipy':>12}{'max diff':>11}"
    print(header)
    print("-" * len(header))
    for row in rows:
        print(
            f"{row['case']:<16}{row['workbench_core_per_s']:>12,.0f}{row['workbench_msg_per_s']:>12,.0f}"
            f"{row['scipy_baseline_per_s']:>12,.0f}{row['ratio_core_vs_baseline']:>11.1f}x"
            f"{row['max_abs_difference']:>11.1e}"
        )
    out = Path(__file__).resolve().parent / "results" / "tf.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"machine": machine, "results": rows}, indent=2) + "\n")
    print(f"\nwrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
