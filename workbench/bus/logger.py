"""Node logging: ``[INFO] [secs.usecs]: text`` on the terminal and ``rosgraph_msgs/Log`` on ``/rosout``."""

from __future__ import annotations

import contextlib
import inspect
import sys
import time
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from workbench.bus.node import Node

#: rosgraph_msgs/Log levels
LEVELS = {"debug": 1, "info": 2, "warn": 4, "error": 8, "fatal": 16}
_NAMES = {1: "DEBUG", 2: "INFO", 4: "WARN", 8: "ERROR", 16: "FATAL"}


class Logger:
    """The logger of one node (``node.get_logger().info(...)``)."""

    def __init__(self, node: Node, level: str = "info") -> None:
        self.node = node
        self.level = LEVELS.get(str(level).lower().replace("warning", "warn"), 2)

    def set_level(self, level: str) -> None:
        self.level = LEVELS[level.lower().replace("warning", "warn")]

    def log(self, level: int, text: Any, *args: Any) -> None:
        """Print (if at or above the node's level) and publish on ``/rosout``.

        ``text % args`` is applied when ``args`` are given, as rospy's ``loginfo`` does.
        """
        message = str(text) % args if args else str(text)
        if level >= self.level:
            stream = sys.stdout if level <= 2 else sys.stderr
            with contextlib.suppress(ValueError, OSError):  # a stream closed at exit
                print(f"[{_NAMES[level]}] [{time.time():.6f}]: {message}", file=stream, flush=True)
        pub = getattr(self.node, "_rosout", None)
        if pub is None or pub.closed or level < self.level:
            return
        try:
            from workbench.msgs import get_type

            frame = inspect.currentframe()
            caller = frame.f_back.f_back if frame and frame.f_back else None
            log = get_type("rosgraph_msgs/Log")(
                level=level,
                name=self.node.name,
                msg=message,
                file=caller.f_code.co_filename if caller else "",
                function=caller.f_code.co_name if caller else "",
                line=caller.f_lineno if caller else 0,
                topics=[p.topic for p in self.node.endpoints()[0]],
            )
            log.header.stamp = self.node.now()
            pub.publish(log)
        except Exception as error:  # logging must never raise into user code
            with contextlib.suppress(ValueError, OSError):  # a stream closed at exit
                print(
                    f"[ERROR] node {self.node.name}: cannot publish a log line on /rosout: "
                    f"{type(error).__name__}: {error}",
                    file=sys.stderr,
                    flush=True,
                )

    def debug(self, text: Any, *args: Any) -> None:
        self.log(1, text, *args)

    def info(self, text: Any, *args: Any) -> None:
        self.log(2, text, *args)

    def warn(self, text: Any, *args: Any) -> None:
        self.log(4, text, *args)

    warning = warn

    def error(self, text: Any, *args: Any) -> None:
        self.log(8, text, *args)

    def fatal(self, text: Any, *args: Any) -> None:
        self.log(16, text, *args)
