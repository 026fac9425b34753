"""A keyboard node in a pseudo-terminal and the Twists it published (importable by name from
the teleop tests: ``from teleop_helpers import TeleopProcess``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from process_helpers import wait_for


@dataclass
class TeleopProcess:
    """A node in a pseudo-terminal (``child``, pexpect) and the Twists seen on /cmd_vel."""

    child: Any
    twists: list[Any] = field(default_factory=list)

    def type(self, keys: str) -> None:
        """Type ``keys`` once the node reads in raw mode (Ctrl-C is then a key, not SIGINT).

        Between reads the node restores the terminal, as the originals do; a Ctrl-C typed
        then is a signal (a clean stop too, but with exit status 130).
        """
        import termios

        def raw() -> bool:
            return not termios.tcgetattr(self.child.child_fd)[3] & (termios.ICANON | termios.ISIG)

        assert wait_for(raw), "the node never read the keyboard in raw mode"
        self.child.send(keys)

    def pairs(self) -> list[tuple[float, float]]:
        """(linear.x, angular.z) of every Twist so far."""
        return [(t.linear.x, t.angular.z) for t in list(self.twists)]

    def wait_twists(self, count: int) -> list[tuple[float, float]]:
        assert wait_for(lambda: len(self.twists) >= count), self.pairs()
        return self.pairs()
