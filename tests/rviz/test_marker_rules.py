"""RViz's marker checks and bookkeeping (rviz noetic: marker_utils.cpp checkMarkerMsg,
marker_display.cpp processMessage/processAdd/deleteAllMarkers, marker_base.cpp expired)."""

from __future__ import annotations

import pytest
from rviz_helpers import marker

from workbench.msgs.geometry_msgs import Point
from workbench.msgs.std_msgs import ColorRGBA
from workbench.msgs.visualization_msgs import Marker
from workbench.rviz.marker_check import check_marker
from workbench.rviz.marker_store import MarkerStore


@pytest.mark.parametrize("kind", range(12))
def test_a_well_formed_marker_of_every_type_passes(kind):
    m = (
        marker(kind, mesh_resource="package://x/y.stl")
        if kind == Marker.MESH_RESOURCE
        else marker(kind)
    )
    assert check_marker(m) is None


@pytest.mark.parametrize(
    "change, level, text",
    [
        (
            {"pose.position.x": float("nan")},
            "error",
            "Position contains invalid floating point values (nans or infs)",
        ),
        ({"pose.orientation.w": 0.0}, "info", "Uninitialized quaternion, assuming identity."),
        ({"pose.orientation.w": 2.0}, "warn", "Unnormalized quaternion in marker message."),
        ({"scale.y": 0.0}, "warn", "Scale contains 0.0 in x, y or z."),
        ({"scale.z": -0.5}, "warn", "Scale contains a negative value; its absolute value is used."),
        ({"color.a": 0.0}, "info", "Marker is fully transparent (color.a is 0.0)."),
        ({"text": "ignored"}, "info", "Non-empty text is ignored."),
        ({"type": 42}, "error", "Unknown marker type: 42."),
    ],
)
def test_checks_of_a_cube_give_rviz_words_and_levels(change, level, text):
    m = marker(Marker.CUBE)
    for dotted, value in change.items():
        target = m
        *path, last = dotted.split(".")
        for part in path:
            target = getattr(target, part)
        setattr(target, last, value)
    status = check_marker(m)
    assert status is not None and status.level == level and text in status.text.split("\n")


def test_type_specific_rules():
    arrow = marker(Marker.ARROW, points=[Point()])
    assert (
        "Number of points for an ARROW marker should be either 0 or 2." in check_marker(arrow).text
    )
    flat_arrow = marker(Marker.ARROW)
    flat_arrow.scale.z = 0.0  # an arrow's scale.z is its optional head length
    assert check_marker(flat_arrow) is None
    strip = marker(Marker.LINE_STRIP, points=[Point()])
    assert check_marker(strip).text == "At least two points are required for a LINE_STRIP marker."
    line_list = marker(Marker.LINE_LIST, points=[Point(), Point(), Point()])
    assert check_marker(line_list).fatal
    triangles = marker(Marker.TRIANGLE_LIST, points=[Point(), Point()])
    assert "multiple of 3" in check_marker(triangles).text
    coloured = marker(Marker.POINTS, colors=[ColorRGBA(r=1.0, a=1.0)])
    assert check_marker(coloured).text == "Number of colors doesn't match number of points."
    text = marker(Marker.TEXT_VIEW_FACING, text="  ")
    assert check_marker(text).text == "Text is empty or only consists of whitespace."
    mesh = marker(Marker.MESH_RESOURCE)
    assert check_marker(mesh).text == "Empty mesh_resource path."
    deleting = marker(Marker.CUBE, action=Marker.DELETE)
    deleting.pose.position.x = float("nan")
    assert check_marker(deleting) is None  # only ADD is checked


def test_same_ns_and_id_replace_delete_removes_deleteall_clears():
    store = MarkerStore()
    assert store.process(marker(Marker.CUBE, 1), 0.0) == ([("test", 1)], [])
    store.process(marker(Marker.SPHERE, 1), 0.1)  # replaces: same ns/id
    assert store.markers[("test", 1)].message.type == Marker.SPHERE
    store.process(marker(Marker.CUBE, 1, ns="other"), 0.1)
    assert len(store.markers) == 2
    assert store.process(marker(Marker.CUBE, 1, action=Marker.DELETE), 0.2) == ([], [("test", 1)])
    assert store.process(marker(Marker.CUBE, 7, action=Marker.DELETE), 0.2) == ([], [])
    store.process(marker(Marker.CUBE, 2), 0.3)
    drawn, erased = store.process(marker(Marker.CUBE, 0, action=Marker.DELETEALL), 0.4)
    assert drawn == [] and sorted(erased) == [("other", 1), ("test", 2)] and store.markers == {}


def test_lifetime_expires_and_fatal_markers_are_not_shown():
    store = MarkerStore()
    timed = marker(Marker.CUBE, 1)
    timed.lifetime.sec, timed.lifetime.nanosec = 1, 500_000_000
    store.process(timed, 10.0)
    store.process(marker(Marker.CUBE, 2), 10.0)  # lifetime 0: forever
    assert store.expire(11.4) == []
    assert store.expire(11.5) == [("test", 1)]
    assert list(store.markers) == [("test", 2)]
    bad = marker(Marker.CUBE, 2)
    bad.pose.position.y = float("inf")
    assert store.process(bad, 12.0) == ([], [("test", 2)])  # an invalid update removes it
    assert store.statuses["test/2"].fatal
    assert store.process(marker(Marker.CUBE, 3, action=9), 12.0) == ([], [])
    assert store.statuses["test/3"].text == "Unknown marker action: 9"


def test_frame_locked_markers_are_listed_for_re_posing():
    store = MarkerStore()
    store.process(marker(Marker.CUBE, 1, frame_locked=True), 0.0)
    store.process(marker(Marker.CUBE, 2), 0.0)
    assert store.frame_locked() == [("test", 1)]
