"""rqt_plot with matplotlib: numeric fields of topics against time.

Field paths are ``/topic/field/sub`` as rqt_plot takes them
(``/turtle1/pose/x``). :class:`FieldSeries` collects samples;
:func:`plot_series` draws them (to a PNG without a display).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workbench.errors import BusError
from workbench.introspect.echo import get_field


@dataclass
class FieldSeries:
    """Samples of one numeric field over time.

    Attributes:
        path: The full path as typed (``/turtle1/pose/x``).
        topic: The topic part.
        fields: The field part (``["x"]``).
        times: Receive times, seconds.
        values: Field values.
    """

    path: str
    topic: str
    fields: list[str]
    times: list[float] = field(default_factory=list)
    values: list[float] = field(default_factory=list)

    def add(self, t: float, msg: Any) -> None:
        """Take the field out of ``msg`` (received at ``t``).

        Raises:
            BusError: the field is missing or not a number.
        """
        value = get_field(msg, self.fields, topic=self.topic)
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise BusError(
                f"{self.path} is not a number (it is {type(value).__name__})",
                hint="plot a numeric field, e.g. /turtle1/pose/x",
            ) from None
        self.times.append(t)
        self.values.append(number)


def plot_series(
    series: list[FieldSeries], png: str | os.PathLike[str] | None = None, *, title: str = ""
) -> Path | None:
    """Draw the series against time since the first sample; write ``png`` if given.

    Returns:
        The PNG path, or None when shown on screen instead.
    """
    import matplotlib

    if png is not None:
        matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    starts = [s.times[0] for s in series if s.times]
    t0 = min(starts) if starts else 0.0
    for s in series:
        ax.plot([t - t0 for t in s.times], s.values, label=s.path)
    ax.set_xlabel("time (s)")
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title)
    if series:
        ax.legend(loc="upper right")
    fig.tight_layout()
    if png is None:
        plt.show()
        return None
    path = Path(png)
    try:
        fig.savefig(path)
    except OSError as error:
        raise BusError(f"cannot write the plot: {error.strerror or error}", path=path) from None
    finally:
        plt.close(fig)
    return path
