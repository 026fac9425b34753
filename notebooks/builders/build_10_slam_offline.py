"""Write notebooks/10_slam_offline.ipynb (run: python notebooks/builders/build_10_slam_offline.py)."""

from __future__ import annotations

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

CELLS = [
    (
        "md",
        """# Experiment 10 (mapping half): 2-D lidar SLAM offline, and map_server maps

In the lab you drive a robot, run `rosrun gmapping slam_gmapping scan:=/scan` and save the
map with `rosrun map_server map_saver -f mymap`. Here the same happens offline on a real
laser log: the Intel Research Lab dataset (CARMEN format). The command-line equivalent is

```
workbench slam intel-corrected --out mymap
workbench map show mymap.yaml --png mymap_view.png
```

The log's poses are already corrected by a SLAM run, so we use them as the reference,
feed the SLAM odometry with realistic noise, and compare it with dead reckoning. The
saved map goes to the output folder printed by the first cell, not next to the notebook.""",
    ),
    (
        "code",
        """import os
import time

import matplotlib.pyplot as plt
import numpy as np

from workbench.mapping import build_map, load_map, read_log, resolve_log, run_slam, save_map
from workbench.mapping.evaluate import (
    NOISE_LEVELS,
    absolute_trajectory_error,
    noisy_odometry,
    relations,
    relative_error,
)
from workbench.paths import notebook_output, project_root

SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"
LOG = resolve_log("intel-corrected")  # shipped in mapping/logs/; any CARMEN log or bag works
print("log:", LOG.relative_to(project_root()))
OUT = notebook_output("10_slam_offline")
print("files go to", OUT)""",
    ),
    (
        "code",
        """log = read_log(LOG)
scans = log.scans[:120] if SHORT else log.scans
reference = np.array([s.reference for s in scans])
duration = scans[-1].stamp - scans[0].stamp
print(f"{len(scans)} scans of {len(scans[0].ranges)} beams over {duration:.0f} s")""",
    ),
    (
        "md",
        """## Noisy odometry
Wheel odometry drifts. We make it from the reference motion with the odometry motion model
of *Probabilistic Robotics* (rotation and translation noise grow with the motion); the
`middle` level has the parameters below (a1 rad/rad, a2 rad/m, a3 m/m, a4 m/rad).""",
    ),
    (
        "code",
        """alphas = NOISE_LEVELS["middle"]
print("a1, a2, a3, a4 =", alphas)
odometry = noisy_odometry(reference, alphas, seed=0)
for scan, pose in zip(scans, odometry, strict=True):
    scan.odom = pose""",
    ),
    (
        "code",
        """start = time.perf_counter()
result = run_slam(scans)
seconds = time.perf_counter() - start
print(
    f"{len(result.keyframes)} keyframes, {len(result.loop_closures)} loop closures, "
    f"{seconds:.1f} s = {duration / seconds:.0f}x faster than real time"
)""",
    ),
    (
        "code",
        """pairs = relations(reference, 1.0)
print(f"{'':16} {'ATE (m)':>8} {'relative 1 m: trans (m)':>24} {'rot (deg)':>10}")
for name, poses in [("dead reckoning", odometry), ("workbench SLAM", result.poses)]:
    rel = relative_error(poses, reference, pairs)
    print(
        f"{name:16} {absolute_trajectory_error(poses, reference):8.3f} "
        f"{rel['trans_mean']:14.3f} ± {rel['trans_std']:.3f} {rel['rot_mean']:10.2f}"
    )""",
    ),
    (
        "code",
        """fig, ax = plt.subplots(figsize=(6, 6))
ax.plot(*reference[:, :2].T, "k-", lw=1, label="reference (corrected log)")
ax.plot(*odometry[:, :2].T, "-", color="tab:orange", lw=1, label="dead reckoning")
ax.plot(*result.poses[:, :2].T, "-", color="tab:red", lw=1, label="SLAM")
ax.set_aspect("equal")
ax.set_xlabel("x (m)")
ax.set_ylabel("y (m)")
ax.legend()
plt.show()""",
    ),
    (
        "md",
        """## Save the map as map_saver does, and load it as map_server does
`save_map(grid, OUT / "mymap")` writes `mymap.pgm` (free 254, occupied 0, unknown 205) and
`mymap.yaml` into the output folder; `load_map(yaml_path)` reads it back with map_server's thresholds. The
reloaded map equals the grid reduced to free / occupied / unknown.""",
    ),
    (
        "code",
        """grid = build_map(scans, result.poses, resolution=0.05).to_map()
pgm, yaml_path = save_map(grid, OUT / "mymap")
print("saved", pgm.name, "and", yaml_path.name, "in", yaml_path.parent)
print(yaml_path.read_text())
reloaded = load_map(yaml_path)
print(
    "reloaded equals the saved grid's trinary form:",
    np.array_equal(reloaded.data, grid.trinary().data),
)""",
    ),
    (
        "code",
        """dead_reckoning_map = build_map(scans, odometry, resolution=0.05).to_map()


def show(ax, m, title):
    grey = np.where(m.data < 0, 0.8, 1.0 - m.data / 100.0)
    extent = [
        m.origin[0],
        m.origin[0] + m.width * m.resolution,
        m.origin[1],
        m.origin[1] + m.height * m.resolution,
    ]
    ax.imshow(grey, cmap="gray", origin="lower", extent=extent, vmin=0, vmax=1)
    ax.set_title(title)
    ax.set_xlabel("x (m)")


fig, axes = plt.subplots(1, 3, figsize=(15, 5))
show(axes[0], dead_reckoning_map, "dead reckoning")
show(axes[1], grid, "SLAM")
show(axes[2], reloaded, "SLAM map reloaded (map_server)")
axes[1].plot(*result.poses[:, :2].T, "r-", lw=0.8)
plt.show()""",
    ),
]


def build(path: Path) -> None:
    """Write the notebook with cleared outputs."""
    notebook = new_notebook()
    notebook.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    for kind, text in CELLS:
        notebook.cells.append(new_markdown_cell(text) if kind == "md" else new_code_cell(text))
    nbformat.write(notebook, path)


if __name__ == "__main__":
    build(Path(__file__).resolve().parents[2] / "notebooks" / "10_slam_offline.ipynb")
