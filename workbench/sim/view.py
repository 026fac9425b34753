"""The running simulation in Meshcat: models in their colours, play/pause/step, speed, recording.

:class:`LiveView` draws a :class:`~workbench.sim.server.SimServer`'s world in a
Meshcat (Drake's ``MeshcatVisualizer``, illustration geometry with the models'
colours), optionally with contact forces (Drake's ``ContactVisualizer``). It
adds **Pause**, **Play** and **Step** buttons to the Meshcat panel (Step
advances 10 ms of simulated time while paused) and shows the measured
real-time factor in Meshcat's realtime-rate display. While live it redraws at
most 30 times a wall-clock second, however fast the simulation runs. With
``record=True`` every 1/32 s of simulated time is kept as an animation frame;
:meth:`save_html` writes the animation as one self-contained HTML file.
"""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import Any

from workbench.errors import SimulationError

FRAME_RATE = 32.0
REDRAW_PERIOD = 1.0 / 30.0
STEP_SECONDS = 0.01
_BUTTONS = ("Pause", "Play", "Step")


class LiveView:
    """Attach before the world is built: ``view = LiveView(world, meshcat); SimServer(world)``.

    Args:
        world: The (not yet built) :class:`~workbench.sim.World`.
        meshcat: The pydrake ``Meshcat`` (``workbench.viz.Viewer.instance().meshcat``).
        contacts: Draw contact forces as arrows.
        record: Keep an animation of the run for :meth:`save_html`.
    """

    def __init__(
        self, world: Any, meshcat: Any, *, contacts: bool = False, record: bool = False
    ) -> None:
        if world.diagram is not None:
            raise SimulationError("create the LiveView before the world is built")
        self.world = world
        self.meshcat = meshcat
        self.record = record
        world.meshcat = meshcat
        world.show_contacts = contacts
        # Live drawing is driven by the wall clock below; a recording needs sim-time frames.
        world.visual_period = 1.0 / FRAME_RATE if record else 1e6
        if record:
            meshcat.StartRecording(FRAME_RATE, set_visualizations_while_recording=True)
        self._clicks = {name: 0 for name in _BUTTONS}
        for name in _BUTTONS:
            meshcat.AddButton(name)
        self._last_draw = 0.0
        self._last_rate = 0.0

    def attach(self, server: Any) -> None:
        """Follow ``server``: redraw, react to the buttons, show the speed."""
        server.hooks.append(self.update)

    def update(self, server: Any) -> None:
        """One look at the buttons and, when due, a redraw (runs on the loop's thread)."""
        now = time.perf_counter()
        if now - self._last_draw < REDRAW_PERIOD:
            return
        self._last_draw = now
        for name in _BUTTONS:
            clicks = self.meshcat.GetButtonClicks(name)
            if clicks > self._clicks[name]:
                self._clicks[name] = clicks
                if name == "Pause":
                    server.paused = True
                elif name == "Play":
                    server.paused = False
                    server.wake()
                else:
                    server.request_step(STEP_SECONDS)
        if not self.record:
            self.draw()
        if now - self._last_rate >= 1.0:
            self._last_rate = now
            self.meshcat.SetRealtimeRate(0.0 if server.paused else server.measured_rtf)

    def draw(self) -> None:
        """Send the current poses (and contact forces) to Meshcat now."""
        world = self.world
        for system in (world.visualizer, world.contact_visualizer):
            if system is not None:
                system.ForcedPublish(system.GetMyContextFromRoot(world.context))

    def save_html(self, path: str | os.PathLike[str]) -> Path:
        """Write the recording (or, without one, the current scene) as self-contained HTML."""
        self.draw()
        if self.record:
            self.meshcat.StopRecording()
            self.meshcat.PublishRecording()
        target = Path(path)
        target.parent.mkdir(parents=True, exist_ok=True)
        partial = target.with_name(target.name + ".partial")
        partial.write_text(self.meshcat.StaticHtml(), encoding="utf-8")
        partial.replace(target)
        return target

    def close(self) -> None:
        """Remove the buttons."""
        present = set(self.meshcat.GetButtonNames())
        for name in _BUTTONS:
            if name in present:
                self.meshcat.DeleteButton(name)
