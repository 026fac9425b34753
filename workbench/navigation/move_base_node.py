"""``move_base/move_base``: the navigation executive on the bus, as ROS Noetic's move_base.

``workbench run move_base move_base [_param:=value ...]``; parameters as loaded by a launch
file's ``<rosparam>`` lines (``global_costmap/...``, ``local_costmap/...``,
``TrajectoryPlannerROS/...``). See :mod:`workbench.navigation.move_base` for what it does.
A bad parameter stops it at start with one line naming the parameter; bad goals end ABORTED
and the node keeps running. SIGINT and SIGTERM stop it cleanly.
"""

from __future__ import annotations

from collections.abc import Sequence


def main(argv: Sequence[str] = ()) -> int:
    """Run move_base until interrupted."""
    from workbench.bus import Node
    from workbench.navigation.move_base import MoveBase
    from workbench.tf import Buffer, TransformListener

    node = Node("move_base", argv=list(argv))
    move_base = None
    try:
        buffer = Buffer(cache_time=10.0)
        TransformListener(buffer, node)
        move_base = MoveBase(node, buffer)
        node.bus.spin()
    finally:
        if move_base is not None:
            move_base.shutdown()
        node.shutdown()
    return 0


__all__ = ["main"]
