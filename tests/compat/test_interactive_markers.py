"""The interactive marker server against a client that plays RViz's part over the bus.

Protocol of ROS 1 interactive_markers (noetic): updates on <ns>/update (UPDATE with
markers/poses/erases, KEEP_ALIVE every 0.5 s), the full state latched on
<ns>/update_full, feedback on <ns>/feedback.
"""

from __future__ import annotations

import time

import pytest

from workbench.bus import Bus, Node
from workbench.compat.interactive_markers.interactive_marker_server import InteractiveMarkerServer
from workbench.compat.interactive_markers.menu_handler import MenuHandler
from workbench.errors import BusError
from workbench.msgs.visualization_msgs import (
    InteractiveMarker,
    InteractiveMarkerControl,
    InteractiveMarkerFeedback,
    InteractiveMarkerInit,
    InteractiveMarkerUpdate,
)


def _wait(predicate, seconds=10.0):
    deadline = time.monotonic() + seconds
    while not predicate() and time.monotonic() < deadline:
        time.sleep(0.01)
    return predicate()


@pytest.fixture
def setup():
    bus = Bus()
    server = InteractiveMarkerServer("simple_marker", node=Node("simple_marker", bus=bus))
    client = Node("rviz_client", bus=bus)
    updates, inits = [], []
    client.create_subscription("simple_marker/update", InteractiveMarkerUpdate, updates.append)
    feedback = client.create_publisher("simple_marker/feedback", InteractiveMarkerFeedback)
    yield bus, server, client, updates, inits, feedback
    server.shutdown()
    bus.shutdown()


def _box_marker(name="my_marker"):
    marker = InteractiveMarker(name=name, description="Simple 1-DOF Control")
    marker.header.frame_id = "base_link"
    marker.pose.orientation.w = 1.0
    control = InteractiveMarkerControl(
        name="move_x", interaction_mode=InteractiveMarkerControl.MOVE_AXIS
    )
    control.orientation.w = 1.0
    control.orientation.x = 1.0
    marker.controls.append(control)
    return marker


def test_insert_apply_feedback_and_the_pose_update_that_follows(setup):
    bus, server, client, updates, _, feedback = setup
    heard = []

    def on_feedback(message):
        heard.append(message)
        server.applyChanges()

    server.insert(_box_marker(), on_feedback)
    server.applyChanges()
    assert _wait(lambda: any(u.type == InteractiveMarkerUpdate.UPDATE for u in updates))
    first = next(u for u in updates if u.type == InteractiveMarkerUpdate.UPDATE)
    assert first.server_id == "/simple_marker" and first.seq_num == 1
    assert [m.name for m in first.markers] == ["my_marker"]
    # a late-joining client gets the full state from the latched update_full
    full = []
    client.create_subscription("simple_marker/update_full", InteractiveMarkerInit, full.append)
    assert _wait(lambda: full and full[-1].markers)
    assert full[-1].seq_num == 1 and full[-1].markers[0].name == "my_marker"
    move = InteractiveMarkerFeedback(
        client_id="/rviz/InteractiveMarkers", marker_name="my_marker", control_name="move_x",
        event_type=InteractiveMarkerFeedback.POSE_UPDATE,
    )  # fmt: skip
    move.header.frame_id = "base_link"
    move.pose.position.x = 1.5
    move.pose.orientation.w = 1.0
    feedback.publish(move)
    assert _wait(lambda: heard)
    assert heard[0].control_name == "move_x" and heard[0].pose.position.x == 1.5
    assert _wait(lambda: any(u.poses for u in updates))
    pose_update = next(u for u in updates if u.poses)
    assert pose_update.seq_num == 2 and pose_update.poses[0].name == "my_marker"
    assert pose_update.poses[0].pose.position.x == 1.5
    assert server.get("my_marker").pose.position.x == 1.5
    assert _wait(lambda: any(u.type == InteractiveMarkerUpdate.KEEP_ALIVE for u in updates), 3.0)


def test_menu_selection_calls_the_entry_with_its_id(setup):
    bus, server, client, updates, _, feedback = setup
    chosen = []
    menu = MenuHandler()
    first = menu.insert("First Entry", callback=chosen.append)
    sub = menu.insert("Submenu")
    deep = menu.insert("Second Entry", parent=sub, callback=chosen.append)
    menu.setCheckState(first, MenuHandler.CHECKED)
    server.insert(_box_marker())
    menu.apply(server, "my_marker")
    server.applyChanges()
    assert _wait(lambda: any(u.markers for u in updates))
    entries = next(u for u in updates if u.markers).markers[0].menu_entries
    assert [(e.id, e.parent_id, e.title) for e in entries] == [
        (first, 0, "[x] First Entry"),
        (sub, 0, "Submenu"),
        (deep, sub, "Second Entry"),
    ]
    select = InteractiveMarkerFeedback(
        client_id="/rviz", marker_name="my_marker", event_type=InteractiveMarkerFeedback.MENU_SELECT,
        menu_entry_id=deep,
    )  # fmt: skip
    feedback.publish(select)
    assert _wait(lambda: chosen)
    assert chosen[0].menu_entry_id == deep and len(chosen) == 1


def test_erase_clear_and_bad_input(setup, capsys):
    bus, server, client, updates, _, feedback = setup
    server.insert(_box_marker("a"))
    server.insert(_box_marker("b"))
    server.applyChanges()
    assert server.size() == 2
    server.erase("a")
    server.applyChanges()
    assert _wait(lambda: any(u.erases == ["a"] for u in updates))
    server.clear()
    server.applyChanges()
    assert server.empty()
    assert not server.setPose("ghost", _box_marker().pose)
    with pytest.raises(BusError, match="an interactive marker needs a name"):
        server.insert(InteractiveMarker())
    feedback.publish(InteractiveMarkerFeedback(marker_name="ghost", client_id="/rviz"))
    printed: list[str] = []

    def warned() -> bool:
        printed.append(capsys.readouterr().err)
        return "feedback for unknown marker 'ghost' ignored" in "".join(printed)

    assert _wait(warned)
