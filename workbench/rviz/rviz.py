"""RViz in the browser: displays that listen to the bus and draw in one Meshcat.

Example (in a notebook or a script)::

    from workbench.rviz import RViz, displays

    rviz = RViz(bus, fixed_frame="map", displays=[displays.GridDisplay(), "Marker"])
    rviz.spin(2.0)                  # redraw 30 times a second for 2 s
    print(rviz.url)                 # open it in a browser
    rviz.save_html("view.html")

Displays are given as objects or by RViz's class names (``"Marker"``,
``"MarkerArray"``, ``"LaserScan"``, ``"Map"``, ``"TF"`` ...). Each draws in
the fixed frame through tf at the message's stamp. A message tf cannot place
waits up to a second (RViz's message filter), then its display's status says
``No transform from [frame] to fixed frame [map]: ...``; nothing stops.
Without a fixed frame, ``map`` is used when tf knows it, else the root of the
first tf tree (``world`` when tf is empty).
"""

from __future__ import annotations

import threading
import time
from pathlib import Path
from typing import Any

from workbench.rviz import displays as stock
from workbench.rviz.display import Context, Display
from workbench.rviz.interactive_display import InteractiveMarkerDisplay
from workbench.rviz.marker_display import MarkerArrayDisplay, MarkerDisplay
from workbench.rviz.polygon_display import PolygonDisplay
from workbench.rviz.pose_tools import PoseTools, ToolSettings

#: RViz display class names -> workbench displays.
DISPLAY_CLASSES: dict[str, type[Display]] = {
    "Grid": stock.GridDisplay,
    "Axes": stock.AxesDisplay,
    "TF": stock.TFDisplay,
    "RobotModel": stock.RobotModelDisplay,
    "Marker": MarkerDisplay,
    "MarkerArray": MarkerArrayDisplay,
    "InteractiveMarkers": InteractiveMarkerDisplay,
    "LaserScan": stock.LaserScanDisplay,
    "PointCloud2": stock.PointCloud2Display,
    "Map": stock.MapDisplay,
    "Path": stock.PathDisplay,
    "Pose": stock.PoseDisplay,
    "PoseArray": stock.PoseArrayDisplay,
    "Polygon": PolygonDisplay,
    "Odometry": stock.OdometryDisplay,
}

PREFIX = "/rviz"


class RViz:
    """A set of displays drawing the bus's topics in a Meshcat.

    Args:
        bus: The ``workbench.bus.Bus`` (default: the process-wide one).
        fixed_frame: RViz's Fixed Frame (None: ``map`` if known, else the tf root).
        displays: Display objects or RViz class names (default: Grid, TF, Marker,
            MarkerArray).
        meshcat: A pydrake ``Meshcat`` (default: the process viewer's).
        name: The node name (anonymous, as rviz's).
        tools: The "2D Pose Estimate" and "2D Nav Goal" tools' settings (default: both,
            with RViz's topics); their buttons and sliders appear in Meshcat's panel.
            ``ToolSettings(tools=())`` leaves the panel alone (the Python calls
            :meth:`set_pose_estimate` and :meth:`send_goal` still work).
    """

    def __init__(
        self,
        bus: Any = None,
        *,
        fixed_frame: str | None = None,
        displays: list[Display | str] | None = None,
        meshcat: Any = None,
        name: str = "rviz",
        tools: ToolSettings | None = None,
    ) -> None:
        from workbench.bus import Node
        from workbench.tf import Buffer, TransformListener

        if meshcat is None:
            from workbench.viz import Viewer

            meshcat = Viewer.instance().meshcat
        self.meshcat = meshcat
        self.node = Node(name, bus=bus, anonymous=True)
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self.node)
        self.requested_frame = fixed_frame
        self.tools = PoseTools(self.node, tools)
        self.displays: list[Display] = []
        chosen = displays if displays is not None else ["Grid", "TF", "Marker", "MarkerArray"]
        for display in chosen:
            self.add_display(display)
        # RViz's default view: an orbit camera 10 m from the origin, 45 degrees up
        # and 45 degrees round; Meshcat's own grid gives way to the Grid display.
        meshcat.SetCameraPose([5.0, 5.0, 7.07], [0.0, 0.0, 0.0])
        meshcat.SetProperty("/Grid", "visible", False)
        self._lock = threading.Lock()
        self.updates = 0

    # --- displays ----------------------------------------------------------------------

    def add_display(
        self, display: Display | str, *, name: str | None = None, **options: Any
    ) -> Display:
        """Add a display (an object, or an RViz class name with its options) and subscribe it.

        A name already taken gets `` (2)``, `` (3)`` ... appended (each display draws under
        its own name in Meshcat).
        """
        if isinstance(display, str):
            from workbench.errors import ViewerError

            cls = DISPLAY_CLASSES.get(display.split("/")[-1])
            if cls is None:
                raise ViewerError(
                    f"unknown display class '{display}'",
                    hint="one of: " + ", ".join(DISPLAY_CLASSES),
                )
            display = cls(**options)
        if name:
            display.name = name
        names = {d.name for d in self.displays}
        base, index = display.name, 2
        while display.name in names:
            display.name = f"{base} ({index})"
            index += 1
        if isinstance(display, stock.MapDisplay):  # later maps are drawn above earlier ones
            display.layer = sum(isinstance(d, stock.MapDisplay) for d in self.displays)
        display.attach(self.node)
        self.displays.append(display)
        return display

    # --- tools -------------------------------------------------------------------------

    def set_pose_estimate(self, x: float, y: float, yaw: float) -> Any:
        """RViz's "2D Pose Estimate": publish ``(x, y)`` m facing ``yaw`` rad in the fixed
        frame as a ``PoseWithCovarianceStamped`` on the tool's topic (``/initialpose``).

        Returns:
            The message sent.

        Raises:
            ViewerError: A coordinate that is not a finite number.
        """
        return self.tools.set_pose_estimate(x, y, yaw, self.fixed_frame)

    def send_goal(self, x: float, y: float, yaw: float) -> Any:
        """RViz's "2D Nav Goal": publish ``(x, y)`` m facing ``yaw`` rad in the fixed frame
        as a ``PoseStamped`` on the tool's topic (``/move_base_simple/goal``).

        Returns:
            The message sent.

        Raises:
            ViewerError: A coordinate that is not a finite number.
        """
        return self.tools.send_goal(x, y, yaw, self.fixed_frame)

    def map_extent(self) -> tuple[float, float, float, float] | None:
        """``(x_min, x_max, y_min, y_max)`` in the fixed frame of the first Map display that
        has drawn a map (one in the ``map`` colour scheme first), m."""
        maps = [d for d in self.displays if isinstance(d, stock.MapDisplay) and d.extent]
        maps.sort(key=lambda d: d.color_scheme != "map")
        return maps[0].extent if maps else None

    # --- drawing -----------------------------------------------------------------------

    @property
    def fixed_frame(self) -> str:
        """The frame everything is drawn in (see the module docstring)."""
        if self.requested_frame:
            return self.requested_frame
        with self.buffer._lock:
            frames = self.buffer.get_frame_strings()
            info = self.buffer.frames_info()
        if "map" in frames:
            return "map"
        parents = {entry["parent"] for entry in info.values()}
        roots = sorted(p for p in parents if p not in info)
        return roots[0] if roots else "world"

    def context(self) -> Context:
        return Context(
            meshcat=self.meshcat,
            buffer=self.buffer,
            fixed_frame=self.fixed_frame,
            node=self.node,
            prefix=PREFIX,
            resolve_mesh=resolve_mesh,
        )

    def update(self) -> None:
        """Draw what arrived since the last update (from one thread at a time)."""
        with self._lock:
            context = self.context()
            for display in self.displays:
                if display.enabled:
                    try:
                        display.update(context)
                    except Exception as error:  # noqa: BLE001 - a display fails alone, as in RViz
                        display.status["Error"] = f"{type(error).__name__}: {error}"
            self.tools.update(context, self.map_extent())
            self.updates += 1

    def spin(self, seconds: float, period: float = 1.0 / 30.0) -> None:
        """Update for ``seconds`` of wall time (a notebook's or a test's loop).

        Drake's Meshcat may only be called from the thread that created it, so the
        viewer is updated from that thread: here, or by calling :meth:`update`.
        """
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            self.update()
            time.sleep(period)
        self.update()

    def statuses(self) -> dict[str, dict[str, str]]:
        """Each display's status lines (RViz's status tree), problems only plus the topic."""
        return {d.name: dict(d.status) for d in self.displays}

    @property
    def url(self) -> str:
        return str(self.meshcat.web_url())

    def _repr_html_(self) -> str:
        """Jupyter shows the live view inline (the Meshcat page in an iframe)."""
        return f'<iframe src="{self.url}" width="100%" height="480" style="border:0"></iframe>'

    def save_html(self, path: str | Path) -> Path:
        """A self-contained HTML snapshot of the view now."""
        self.update()
        target = Path(path)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(self.meshcat.StaticHtml(), encoding="utf-8")
        return target

    def close(self) -> None:
        """Unsubscribe, remove the tools' controls and shut the node down."""
        for display in self.displays:
            display.close()
        self.tools.close()
        self.node.shutdown()


def resolve_mesh(uri: str) -> Path:
    """A mesh URI (``package://``, ``file://`` or a path) as a file Drake's Meshcat can read.

    Raises:
        ModelError: Unknown package, missing file or unsupported format.
    """
    from workbench.model.meshes import prepare_mesh
    from workbench.model.packages import PackageResolver

    resolved = PackageResolver(Path.cwd() / "marker").resolve(uri, Path.cwd())
    return prepare_mesh(resolved)
