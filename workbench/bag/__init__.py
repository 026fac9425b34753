"""ROS 1 bags (v2.0): write (as rosbag lays them out), read, summarize, replay and recover.

Use::

    from workbench.bag import BagWriter, read_messages, summarize, format_info, play

    with BagWriter("run.bag") as bag:
        bag.write("/turtle1/cmd_vel", twist, t=1.5)
    for topic, time, msg, *_ in read_messages("run.bag"):
        ...
"""

from __future__ import annotations

from workbench.bag.errors import (
    BagDamagedError,
    BagFormatError,
    BagNotFoundError,
    BagWarning,
    BagWriteError,
)
from workbench.bag.info import format_info
from workbench.bag.play import PlayReport, play
from workbench.bag.reader import (
    BagConnection,
    BagMessage,
    BagSummary,
    iter_raw,
    read_messages,
    summarize,
)
from workbench.bag.writer import BagWriter, default_bag_name

__all__ = [
    "BagConnection",
    "BagDamagedError",
    "BagFormatError",
    "BagMessage",
    "BagNotFoundError",
    "BagSummary",
    "BagWarning",
    "BagWriteError",
    "BagWriter",
    "PlayReport",
    "default_bag_name",
    "format_info",
    "iter_raw",
    "play",
    "read_messages",
    "summarize",
]
