"""Outputs of a plan: the summary table, JSON and CSV trajectories, and a plot against the limits.

JSON layout (SI units, radians for revolute joints)::

    {"joint_names": [...], "t": [...], "q": [[...], ...], "qd": [[...]], "qdd": [[...]]}

CSV: one row per sample, columns ``t``, then ``q_<joint>``, ``qd_<joint>``, ``qdd_<joint>``.
"""

from __future__ import annotations

import csv
import io
import json
import os
from pathlib import Path

import numpy as np

from workbench.errors import PlanningError
from workbench.output_files import check_output, write_output
from workbench.planning.pipeline import PlanResult
from workbench.planning.timing import TimedTrajectory

#: Time between samples written to JSON/CSV and plotted, seconds.
OUTPUT_DT = 0.01


def trajectory_samples(trajectory: TimedTrajectory, dt: float = OUTPUT_DT) -> dict[str, list]:
    """The trajectory sampled every ``dt`` seconds in the JSON layout."""
    t = trajectory.times(dt)
    q, qd, qdd = trajectory.sample(t)
    return {
        "joint_names": list(trajectory.joint_names),
        "t": [float(v) for v in t],
        "q": q.tolist(),
        "qd": qd.tolist(),
        "qdd": qdd.tolist(),
    }


def write_json(
    trajectory: TimedTrajectory, path: str | os.PathLike[str], dt: float = OUTPUT_DT
) -> Path:
    """Write the trajectory as JSON; returns the path.

    Raises:
        PlanningError: The folder is missing, the file is someone else's, or the write failed.
    """
    path = check_output(path, "trajectory-json", error=PlanningError)
    return write_output(path, json.dumps(trajectory_samples(trajectory, dt)), error=PlanningError)


def write_csv(
    trajectory: TimedTrajectory, path: str | os.PathLike[str], dt: float = OUTPUT_DT
) -> Path:
    """Write the trajectory as CSV (see the module docstring); returns the path.

    Raises:
        PlanningError: The folder is missing, the file is someone else's, or the write failed.
    """
    path = check_output(path, "trajectory-csv", error=PlanningError)
    data = trajectory_samples(trajectory, dt)
    names = data["joint_names"]
    header = ["t"] + [f"{kind}_{n}" for kind in ("q", "qd", "qdd") for n in names]
    text = io.StringIO(newline="")
    writer = csv.writer(text)
    writer.writerow(header)
    for i, t in enumerate(data["t"]):
        writer.writerow([f"{t:.6f}"] + [f"{v:.9g}" for k in ("q", "qd", "qdd") for v in data[k][i]])
    return write_output(path, text.getvalue(), error=PlanningError)


def plot_png(
    trajectory: TimedTrajectory,
    path: str | os.PathLike[str],
    lower: np.ndarray | None = None,
    upper: np.ndarray | None = None,
) -> Path:
    """Plot position, velocity and acceleration per joint with dashed limit lines, as PNG.

    Raises:
        PlanningError: The folder is missing, the file is someone else's, or the write failed.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = check_output(path, "png", error=PlanningError)
    t = trajectory.times(OUTPUT_DT / 2)
    q, qd, qdd = trajectory.sample(t)
    names = trajectory.joint_names
    fig, axes = plt.subplots(3, 1, figsize=(9, 9), sharex=True)
    rows = [
        (q, "position (rad or m)", lower, upper),
        (qd, "velocity (/s)", -trajectory.velocity_limits, trajectory.velocity_limits),
        (
            qdd,
            "acceleration (/s²)",
            -trajectory.acceleration_limits,
            trajectory.acceleration_limits,
        ),
    ]
    for ax, (values, label, lo, hi) in zip(axes, rows, strict=True):
        for j, name in enumerate(names):
            (line,) = ax.plot(t, values[:, j], label=name)
            if lo is not None and hi is not None:
                for bound in (lo[j], hi[j]):
                    if np.isfinite(bound):
                        ax.axhline(bound, color=line.get_color(), linestyle="--", linewidth=0.8)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7, ncol=2, loc="best")
    axes[0].set_title("trajectory against its limits (dashed)")
    axes[-1].set_xlabel("time (s)")
    fig.tight_layout()
    image = io.BytesIO()
    fig.savefig(image, dpi=100, format="png")
    plt.close(fig)
    return write_output(path, image.getvalue(), error=PlanningError)


def summary_rows(result: PlanResult) -> list[tuple[str, str]]:
    """(label, value) rows of the summary table."""
    ms = {k: v * 1000 for k, v in result.times.items()}
    return [
        ("planner", result.planner),
        ("joints", ", ".join(result.joint_names)),
        ("goal (solve IK / sample)", f"{ms['goal']:.1f} ms"),
        ("solve", f"{ms['solve']:.1f} ms"),
        ("simplify", f"{ms['simplify']:.1f} ms"),
        ("time parameterization", f"{ms['timing']:.1f} ms"),
        ("path length", f"{result.path_length:.3f} (joint space), {len(result.path)} waypoints"),
        ("duration", f"{result.duration:.3f} s"),
        ("peak velocity", f"{result.peak_velocity * 100:.1f}% of the limit"),
        ("peak acceleration", f"{result.peak_acceleration * 100:.1f}% of the limit"),
        (
            "collision re-check",
            f"{'passed' if result.recheck_ok else 'FAILED'} ({result.recheck_samples} exact samples, "
            f"{ms['recheck']:.1f} ms)",
        ),
        ("total", f"{ms['total']:.1f} ms"),
    ]


def summary_table(result: PlanResult) -> str:
    """The summary as an aligned two-column table."""
    rows = summary_rows(result)
    width = max(len(label) for label, _ in rows)
    return "\n".join(f"{label:<{width}}  {value}" for label, value in rows)


def show_scene(viewer, scene, prefix: str = "/scene") -> None:
    """Draw a planning scene's obstacles in the viewer (translucent grey)."""
    from pydrake.geometry import Rgba

    from workbench.planning.collision import drake_shape
    from workbench.spatial import as_rigid_transform

    viewer.meshcat.Delete(prefix)
    for obj in scene:
        path = f"{prefix}/{obj.name}"
        viewer.meshcat.SetObject(path, drake_shape(obj), Rgba(0.55, 0.55, 0.6, 0.6))
        viewer.meshcat.SetTransform(path, as_rigid_transform(obj.X_WO))


def animate(
    viewer, robot, joints, trajectory: TimedTrajectory, *, prefix: str | None = None
) -> str:
    """Show ``robot`` and record the trajectory as a Meshcat animation (kept in snapshots).

    Args:
        viewer: A :class:`workbench.viz.Viewer`.
        robot: The :class:`workbench.model.Robot` planned for.
        joints: The group's :class:`~workbench.planning.collision.JointMap`.
        trajectory: The timed trajectory of the group.
        prefix: Meshcat path of the robot (default ``/robots/<name>``).

    Returns:
        The robot's Meshcat prefix.
    """
    fps = 30.0
    times = trajectory.times(1.0 / fps)
    q, _, _ = trajectory.sample(times)
    return animate_samples(viewer, robot, joints, times, q, prefix=prefix)


def animate_samples(
    viewer,
    robot,
    joints,
    times: np.ndarray,
    q: np.ndarray,
    *,
    prefix: str | None = None,
    fps: float = 30.0,
) -> str:
    """Record group positions ``q`` (M, n) at ``times`` (M,) as a Meshcat animation, and
    frame the camera on everything the robot sweeps through (as ``workbench show`` frames).

    Returns:
        The robot's Meshcat prefix.
    """
    times = np.asarray(times, dtype=float)
    q = np.atleast_2d(np.asarray(q, dtype=float))
    prefix = viewer.show_robot(robot, joints.full(q[0]), prefix)
    meshcat = viewer.meshcat
    meshcat.StartRecording(frames_per_second=fps, set_visualizations_while_recording=False)
    frame_times = np.arange(0.0, float(times[-1]) + 0.5 / fps, 1.0 / fps)
    picks = np.minimum(np.searchsorted(times, frame_times), len(times) - 1)
    for t, k in zip(frame_times, picks, strict=True):
        for link, X_WL in robot.forward_kinematics(joints.full(q[k])).items():
            meshcat.SetTransform(f"{prefix}/{link}", X_WL, time_in_recording=float(t))
    meshcat.StopRecording()
    meshcat.PublishRecording()
    viewer.set_positions(robot, joints.full(q[-1]), prefix)
    poses = np.unique(np.linspace(0, len(q) - 1, 5).round().astype(int))
    viewer.frame_camera(np.vstack([viewer.robot_points(robot, joints.full(q[k])) for k in poses]))
    return prefix
