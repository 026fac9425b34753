"""Builds notebooks/03_rviz_markers.ipynb (run: python notebooks/builders/build_03_rviz_markers.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 3: RViz, markers and interactive markers\n\n"
        "RViz draws what is published: markers, tf frames, robot models, laser scans, maps. "
        "workbench's RViz runs in the browser (Drake's Meshcat) and reads the same topics and "
        "message types. In a terminal: `workbench rviz --fixed-frame my_frame` next to "
        "`workbench run using_markers basic_shapes.py`. Here everything runs in this notebook "
        "on one in-process bus.\n\n"
        "| RViz | here |\n|---|---|\n"
        "| Fixed Frame | `RViz(fixed_frame=...)` |\n"
        "| Add → Marker / InteractiveMarkers | `displays=['Marker', ...]`, `rviz.add_display(...)` |\n"
        "| the status tree | `rviz.statuses()` |\n"
        "| File → Save image | `rviz.save_html(...)` (and `workbench rviz --png`) |\n\n"
        "The snapshot it writes goes to the output folder printed by the first cell, "
        "not next to the notebook."
    ),
    new_code_cell(
        "import math\n"
        "import os\n\n"
        "from workbench.bus import Bus, Node\n"
        "from workbench.msgs.geometry_msgs import Point\n"
        "from workbench.msgs.visualization_msgs import Marker\n"
        "from workbench.paths import notebook_output\n"
        "from workbench.rviz import RViz\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        'OUT = notebook_output("03_rviz_markers")\n'
        'print("files go to", OUT)\n'
        "bus = Bus()\n"
        'rviz = RViz(bus, fixed_frame="my_frame", displays=["Grid", "Marker"])\n'
        'node = Node("notebook", bus=bus)\n'
        'publisher = node.create_publisher("visualization_marker", Marker)\n'
        "rviz  # the live view (open the URL in a browser if the frame stays empty)"
    ),
    new_markdown_cell(
        "## 1. Sending basic shapes\n\n"
        "One marker, `ns` = basic_shapes, `id` = 0: each new message with the same pair "
        "replaces the shape, cube → sphere → arrow → cylinder."
    ),
    new_code_cell(
        "for shape in [Marker.CUBE, Marker.SPHERE, Marker.ARROW, Marker.CYLINDER]:\n"
        '    marker = Marker(ns="basic_shapes", id=0, type=shape, action=Marker.ADD)\n'
        '    marker.header.frame_id = "my_frame"\n'
        "    marker.pose.orientation.w = 1.0\n"
        "    marker.scale.x = marker.scale.y = marker.scale.z = 1.0\n"
        "    marker.color.g = marker.color.a = 1.0\n"
        "    publisher.publish(marker)\n"
        "    rviz.spin(0.2 if SHORT else 1.0)\n"
        "    shown = rviz.displays[1].store.markers\n"
        "    print(\n"
        '        "showing", [m.message.type for m in shown.values()], "statuses", rviz.statuses()["Marker"]\n'
        "    )"
    ),
    new_markdown_cell(
        "## 2. Points and lines\n\n"
        "POINTS, LINE_STRIP and LINE_LIST share one list of points (a sine wave); "
        "`scale.x` is the point size or line width."
    ),
    new_code_cell(
        "def wave(marker_id, kind, r, g, b, phase):\n"
        '    marker = Marker(ns="points_and_lines", id=marker_id, type=kind, action=Marker.ADD)\n'
        '    marker.header.frame_id = "my_frame"\n'
        "    marker.pose.orientation.w = 1.0\n"
        "    marker.scale.x = marker.scale.y = 0.2 if kind == Marker.POINTS else 0.1\n"
        "    marker.color.r, marker.color.g, marker.color.b, marker.color.a = r, g, b, 1.0\n"
        "    for i in range(100):\n"
        "        a = phase + i / 100.0 * 2 * math.pi\n"
        "        p = Point(x=(i - 50) / 10.0, y=0.5 * math.sin(a), z=0.5 * math.cos(a))\n"
        "        marker.points.append(p)\n"
        "        if kind == Marker.LINE_LIST:\n"
        "            marker.points.append(Point(x=p.x, y=p.y, z=p.z + 0.3))\n"
        "    return marker\n\n\n"
        "for step in range(3 if SHORT else 30):\n"
        "    for marker in (\n"
        "        wave(0, Marker.POINTS, 0, 1, 0, step * 0.1),\n"
        "        wave(1, Marker.LINE_STRIP, 0, 0, 1, step * 0.1),\n"
        "        wave(2, Marker.LINE_LIST, 1, 0, 0, step * 0.1),\n"
        "    ):\n"
        "        publisher.publish(marker)\n"
        "    rviz.spin(0.05)\n"
        'print("markers shown:", sorted(rviz.displays[1].store.markers))'
    ),
    new_markdown_cell(
        "## 3. An interactive marker, moved from here\n\n"
        "`InteractiveMarkerServer` speaks the interactive markers protocol on the bus; the "
        "InteractiveMarkers display is its client. In the browser, the slider "
        "`my_marker: move_x` drags the box; here we move the same slider from Python, and the "
        "server's callback prints the feedback RViz would send."
    ),
    new_code_cell(
        "from workbench.compat.interactive_markers.interactive_marker_server import InteractiveMarkerServer\n"
        "from workbench.msgs.visualization_msgs import InteractiveMarker, InteractiveMarkerControl\n\n"
        'server = InteractiveMarkerServer("simple_marker", node=Node("simple_marker", bus=bus))\n'
        'events = {1: "POSE_UPDATE", 4: "MOUSE_DOWN", 5: "MOUSE_UP"}\n\n\n'
        "def process_feedback(feedback):\n"
        "    p = feedback.pose.position\n"
        "    print(\n"
        '        f"{feedback.marker_name} {events.get(feedback.event_type)} ({feedback.control_name}): now at {p.x:.2f}, {p.y:.2f}, {p.z:.2f}"\n'
        "    )\n"
        "    server.applyChanges()\n\n\n"
        'int_marker = InteractiveMarker(name="my_marker", description="Simple 1-DOF Control", scale=1.0)\n'
        'int_marker.header.frame_id = "my_frame"\n'
        "int_marker.pose.orientation.w = 1.0\n"
        "box = Marker(type=Marker.CUBE)\n"
        "box.scale.x = box.scale.y = box.scale.z = 0.45\n"
        "box.color.r = box.color.g = box.color.b = 0.5\n"
        "box.color.a = 1.0\n"
        "box.pose.orientation.w = 1.0\n"
        "int_marker.controls.append(InteractiveMarkerControl(always_visible=True, markers=[box]))\n"
        "move_x = InteractiveMarkerControl(\n"
        '    name="move_x", interaction_mode=InteractiveMarkerControl.MOVE_AXIS\n'
        ")\n"
        "move_x.orientation.w = move_x.orientation.x = 0.7071068\n"
        "int_marker.controls.append(move_x)\n"
        "server.insert(int_marker, process_feedback)\n"
        "server.applyChanges()\n"
        'display = rviz.add_display("InteractiveMarkers", topic="simple_marker")\n'
        "rviz.spin(0.5)\n"
        'rviz.meshcat.SetSliderValue("my_marker: move_x", 1.5)  # what dragging the slider does\n'
        "rviz.spin(0.5)\n"
        "print(f\"the server now has the marker at x = {server.get('my_marker').pose.position.x:.2f}\")"
    ),
    new_markdown_cell(
        "## 4. A snapshot\n\nA self-contained HTML file of the view, for a report: "
        "`rviz_markers.html` in the output folder."
    ),
    new_code_cell(
        'print("snapshot:", rviz.save_html(OUT / "rviz_markers.html"))\n'
        'print("statuses:", rviz.statuses())\n'
        "server.shutdown()\n"
        "rviz.close()\n"
        "bus.shutdown()"
    ),
]

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "name": "python3",
    "display_name": "Python 3",
    "language": "python",
}
out = Path(__file__).resolve().parents[1] / "03_rviz_markers.ipynb"
nbformat.write(notebook, out)
print(f"wrote {out}")
