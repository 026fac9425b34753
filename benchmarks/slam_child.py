"""workbench's SLAM in a child process, so that its CPU time and peak memory are measured as
MRPT's programs' are (the child's own rusage: user + system time, maximum resident set size).

The parent pickles the scans (with their odometry) and the config; the child
(``python benchmarks/slam_child.py INPUT OUTPUT``) runs ``run_slam`` and
writes the poses, the loop-closure count and the wall and CPU seconds of
``run_slam`` alone (without interpreter start and imports) to an ``.npz``.
"""

from __future__ import annotations

import pickle
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from child_process import run_measured

from workbench.mapping import SlamConfig, run_slam
from workbench.mapping.scan import Scan

HERE = Path(__file__).resolve()


@dataclass
class WorkbenchRun:
    """One SLAM run in a child process.

    Attributes:
        poses: Estimated sensor poses ``(N, 3)`` (m, rad).
        loop_closures: Accepted loop closures.
        slam_wall_s: Wall seconds of ``run_slam`` alone.
        slam_cpu_s: CPU seconds of ``run_slam`` alone.
        cpu_s: CPU seconds of the whole child process (user + system).
        peak_mb: The child's maximum resident set size (MB).
    """

    poses: np.ndarray
    loop_closures: int
    slam_wall_s: float
    slam_cpu_s: float
    cpu_s: float
    peak_mb: float


def run_workbench(
    scans: list[Scan], config: SlamConfig, workdir: Path, timeout: float
) -> WorkbenchRun:
    """Run ``run_slam(scans, config)`` in a child process in ``workdir``.

    Raises:
        RuntimeError: The child failed or ran out of time (its last stderr line says why).
    """
    workdir.mkdir(parents=True, exist_ok=True)
    source, result = workdir / "input.pickle", workdir / "result.npz"
    source.write_bytes(pickle.dumps((scans, config)))
    done = run_measured([sys.executable, str(HERE), str(source), str(result)], workdir, timeout)
    if done.timed_out or done.returncode != 0 or not result.is_file():
        lines = (workdir / "stderr.txt").read_text(errors="replace").strip().splitlines()
        why = f"timeout after {timeout:g} s" if done.timed_out else f"exit code {done.returncode}"
        raise RuntimeError(f"workbench SLAM child: {why}: {lines[-1] if lines else 'no message'}")
    with np.load(result) as data:
        return WorkbenchRun(
            poses=data["poses"],
            loop_closures=int(data["loop_closures"]),
            slam_wall_s=float(data["wall"]),
            slam_cpu_s=float(data["cpu"]),
            cpu_s=done.cpu_s,
            peak_mb=done.peak_mb,
        )


def main(argv: list[str]) -> int:
    """The child: ``INPUT`` (pickled scans and config) to ``OUTPUT`` (``.npz``)."""
    source, result = (Path(a) for a in argv)
    scans, config = pickle.loads(source.read_bytes())
    wall, cpu = time.perf_counter(), time.process_time()
    slam = run_slam(scans, config)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    with open(result, "wb") as out:
        np.savez(out, poses=slam.poses, loop_closures=len(slam.loop_closures), wall=wall, cpu=cpu)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
