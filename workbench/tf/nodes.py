"""tf's runnable nodes for ``workbench run`` and launch files.

* ``tf/static_transform_publisher`` and ``tf2_ros/static_transform_publisher``:
  ``x y z yaw pitch roll frame_id child_frame_id`` or ``x y z qx qy qz qw frame_id
  child_frame_id`` (tf's form takes a trailing period in ms, ignored: the
  transform is latched on ``/tf_static``).

They are declared as entry points of the ``workbench.nodes`` group in
``pyproject.toml``; the robot's nodes (``robot_state_publisher``,
``joint_state_publisher``) live in :mod:`workbench.robot_state.nodes`.

The manual's own scripts (``learning_tf``, ``robot_setup_tf``) are not declared:
the launcher finds them as scripts beside the launch file (``examples/tf``), so a
student's edited copy next to their own launch file is the one that runs.
:func:`run_lab_script` runs the shipped copies by name.
"""

from __future__ import annotations

import math
import runpy
import sys
from collections.abc import Sequence
from pathlib import Path

from workbench.tf.exceptions import InvalidArgumentException

#: learning_tf/robot_setup_tf node type -> script under examples/tf.
LAB_SCRIPTS = {
    "learning_tf/turtle_tf_broadcaster": "turtle_tf_broadcaster.py",
    "learning_tf/turtle_tf_listener": "turtle_tf_listener.py",
    "learning_tf/turtle_tf_listener_carrot": "turtle_tf_listener_carrot.py",
    "learning_tf/turtle_tf_listener_time_travel": "turtle_tf_listener_time_travel.py",
    "learning_tf/turtle_tf_listener_time_travel_full": "turtle_tf_listener_time_travel_full.py",
    "learning_tf/fixed_tf_broadcaster": "fixed_tf_broadcaster.py",
    "learning_tf/dynamic_tf_broadcaster": "dynamic_tf_broadcaster.py",
    "robot_setup_tf/tf_broadcaster": "robot_setup_tf/tf_broadcaster.py",
    "robot_setup_tf/tf_listener": "robot_setup_tf/tf_listener.py",
}


def examples_dir() -> Path:
    """``examples/tf`` of the checkout."""
    from workbench.paths import project_root

    return project_root() / "examples" / "tf"


def run_lab_script(node_type: str, argv: Sequence[str]) -> int:
    """Run one of the manual's scripts as ``__main__`` with ``argv`` as its arguments."""
    path = examples_dir() / LAB_SCRIPTS[node_type]
    if not path.is_file():
        raise InvalidArgumentException(
            f"the lab script {path} is missing",
            hint="run from a workbench checkout, or set WORKBENCH_HOME to one",
        )
    saved = sys.argv
    sys.argv = [str(path), *argv]
    try:
        runpy.run_path(str(path), run_name="__main__")
    finally:
        sys.argv = saved
    return 0


#: Largest translation static_transform_publisher takes, m (past any Earth coordinate).
MAX_STATIC_TRANSLATION = 1e9
#: Longest frame id it takes (as long as a graph name).
MAX_FRAME_LENGTH = 512


def parse_static_args(args: Sequence[str]) -> tuple[str, str, tuple[float, ...], tuple[float, ...]]:
    """``(frame_id, child, translation, quaternion)`` from static_transform_publisher's arguments."""
    from workbench.tf.transformations import quaternion_from_euler

    values = list(args)
    if len(values) in (9, 10) and _is_number(values[-1]) and not _is_number(values[-2]):
        values = values[:-1]  # tf's period in ms
    try:
        if len(values) == 8:
            x, y, z, yaw, pitch, roll = (float(v) for v in values[:6])
            q = tuple(float(v) for v in quaternion_from_euler(roll, pitch, yaw))
        elif len(values) == 9:
            x, y, z, *qs = (float(v) for v in values[:7])
            norm = math.sqrt(sum(v * v for v in qs))
            if norm == 0:
                raise ValueError("zero quaternion")
            q = tuple(v / norm for v in qs)
        else:
            raise ValueError(f"{len(values)} arguments")
        if not all(math.isfinite(v) for v in (x, y, z, *q)):
            raise ValueError("every number must be finite (no nan or inf)")
        if not all(abs(v) <= MAX_STATIC_TRANSLATION for v in (x, y, z)):
            raise ValueError(f"x, y and z must be within {MAX_STATIC_TRANSLATION:g} m")
        for frame in values[-2:]:
            if not frame.strip() or len(frame) > MAX_FRAME_LENGTH:
                raise ValueError(
                    f"a frame id has 1 to {MAX_FRAME_LENGTH} characters, got {len(frame):,}"
                )
    except ValueError as error:
        raise InvalidArgumentException(
            f"static_transform_publisher: bad arguments ({error})",
            hint="give x y z yaw pitch roll frame_id child_frame_id, or "
            "x y z qx qy qz qw frame_id child_frame_id",
        ) from None
    return values[-2], values[-1], (x, y, z), q


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def static_transform_publisher(argv: Sequence[str] = ()) -> int:
    """Publish one static transform on latched ``/tf_static`` until interrupted.

    Args:
        argv: The node's command line: the transform's arguments plus remappings
            (``__name:=``, ``__ns:=``, ``from:=to``).
    """
    from workbench.bus import Node
    from workbench.bus.names import myargv
    from workbench.tf.broadcaster import StaticTransformBroadcaster, make_transform

    parent, child, xyz, q = parse_static_args(myargv(list(argv)))
    node = Node("static_transform_publisher", argv=list(argv))
    StaticTransformBroadcaster(node).send_transform(make_transform(parent, child, xyz, q))
    node.bus.spin()
    return 0
