"""The viewer as an interactive marker client: draws the server's markers, sliders send feedback."""

from __future__ import annotations

import time

import numpy as np
from rviz_helpers import recording_meshcat

from workbench.bus import Bus, Node
from workbench.compat.interactive_markers.interactive_marker_server import InteractiveMarkerServer
from workbench.compat.interactive_markers.menu_handler import MenuHandler
from workbench.msgs.visualization_msgs import InteractiveMarker, InteractiveMarkerControl
from workbench.rviz import RViz


def _wait(rviz, predicate, seconds=10.0):
    deadline = time.monotonic() + seconds
    while not predicate() and time.monotonic() < deadline:
        rviz.update()
        time.sleep(0.02)
    return predicate()


def test_a_slider_moves_the_marker_through_the_server_and_back():
    bus = Bus()
    meshcat = recording_meshcat()
    server = InteractiveMarkerServer("simple_marker", node=Node("simple_marker", bus=bus))
    heard = []

    def on_feedback(feedback):
        heard.append(feedback)
        server.applyChanges()

    marker = InteractiveMarker(name="my_marker", scale=1.0)
    marker.header.frame_id = "base_link"
    marker.pose.orientation.w = 1.0
    control = InteractiveMarkerControl(
        name="move_x", interaction_mode=InteractiveMarkerControl.MOVE_AXIS
    )
    control.orientation.w = control.orientation.x = 0.7071068
    marker.controls.append(control)
    button = InteractiveMarkerControl(
        name="press", interaction_mode=InteractiveMarkerControl.BUTTON
    )
    marker.controls.append(button)
    server.insert(marker, on_feedback)
    menu = MenuHandler()
    menu.insert("First Entry")
    menu.apply(server, "my_marker")
    server.applyChanges()

    rviz = RViz(bus, fixed_frame="base_link", displays=[], meshcat=meshcat)
    display = rviz.add_display("InteractiveMarkers", topic="simple_marker")
    assert _wait(rviz, lambda: "my_marker" in display.markers)
    assert "my_marker: move_x" in meshcat.GetSliderNames()
    assert {"my_marker: press", "my_marker: First Entry"} <= set(meshcat.GetButtonNames())
    assert meshcat.HasPath("/rviz/InteractiveMarkers/my_marker/0/arrows")

    meshcat.SetSliderValue("my_marker: move_x", 1.25)  # as a user dragging the slider
    assert _wait(rviz, lambda: [f.event_type for f in heard] == [4, 1, 5])  # down, pose, up
    assert heard[1].control_name == "move_x" and heard[1].client_id == "/rviz/InteractiveMarkers"
    assert abs(heard[1].pose.position.x - 1.25) < 1e-6
    # the server's pose update comes back: the marker is drawn there
    assert _wait(rviz, lambda: abs(display.markers["my_marker"].base_pose.position.x - 1.25) < 1e-6)
    rviz.update()
    path = "/rviz/InteractiveMarkers/my_marker"
    np.testing.assert_allclose(meshcat.transforms[path][:3, 3], [1.25, 0.0, 0.0], atol=1e-6)
    assert meshcat.GetSliderValue("my_marker: move_x") == 0.0  # measured from the new pose

    server.erase("my_marker")
    server.applyChanges()
    assert _wait(rviz, lambda: "my_marker" not in display.markers)
    assert "my_marker: move_x" not in meshcat.GetSliderNames()
    rviz.close()
    server.shutdown()
    bus.shutdown()
