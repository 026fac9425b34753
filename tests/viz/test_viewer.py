"""The Meshcat viewer: robots drawn with their links, sliders, snapshots and PNGs."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.model import load_robot
from workbench.viz import Viewer
from workbench.viz.snapshot import snapshot_paths


@pytest.fixture(scope="module")
def arm3():
    return load_robot("arm3")


@pytest.fixture(scope="module")
def viewer():
    viewer = Viewer.instance()
    yield viewer
    viewer.clear()


def test_viewer_is_one_per_process_on_localhost(viewer):
    assert Viewer.instance() is viewer
    assert viewer.url.startswith("http://127.0.0.1:")


def test_snapshot_contains_every_link(viewer, arm3, tmp_path):
    viewer.clear()
    prefix = viewer.show_robot(arm3)
    assert prefix == "/robots/arm3"
    paths = set(snapshot_paths(viewer.save_html(tmp_path / "arm3.html")))
    for link in arm3.links:
        assert f"{prefix}/{link.name}" in paths
        assert f"{prefix}/{link.name}/visual_0" in paths


def test_set_positions_moves_links(viewer, arm3):
    viewer.clear()
    viewer.show_robot(arm3)
    q = arm3.positions_from({"shoulder_pitch_joint": 1.0})
    viewer.set_positions(arm3, q)
    viewer.frame_robot(arm3, q)
    assert viewer.meshcat.HasPath("/robots/arm3/tool_link")


def test_sliders_follow_the_joints(viewer, arm3):
    viewer.clear()
    viewer.show_robot(arm3)
    names = viewer.add_joint_sliders(arm3)
    assert names == arm3.joint_names
    viewer.meshcat.SetSliderValue("elbow_pitch_joint", 0.5)
    values = viewer.poll_sliders()
    assert values["elbow_pitch_joint"] == pytest.approx(0.5)
    assert values["base_yaw_joint"] == 0.0
    assert viewer.add_joint_sliders(arm3) == names  # again: replaced, not duplicated
    assert sorted(viewer.meshcat.GetSliderNames()) == sorted(names)


def test_frame_camera_looks_at_the_box_centre(viewer, tmp_path):
    from workbench.viz.snapshot import command_paths

    viewer.frame_camera(np.array([[0, 0, 0], [1, 1, 1.0]]))
    html = viewer.meshcat.StaticHtml()
    assert "/Cameras/default/rotated/<object>" in command_paths(html)


@pytest.mark.browser
def test_png_of_a_robot_differs_from_an_empty_scene(require_program, arm3, tmp_path):
    from PIL import Image, ImageChops

    require_program("chromium")
    # A Meshcat of its own: the process-wide viewer may hold other tests' objects or animations.
    viewer = Viewer()
    points = viewer.robot_points(arm3)
    viewer.frame_camera(points)
    empty_png = viewer.render_png(
        viewer.save_html(tmp_path / "empty.html"), tmp_path / "empty.png", width=320, height=240
    )
    viewer.show_robot(arm3)
    viewer.frame_camera(points)
    robot_png = viewer.render_png(
        viewer.save_html(tmp_path / "arm.html"), tmp_path / "arm.png", width=320, height=240
    )
    empty = Image.open(empty_png).convert("RGB")
    robot = Image.open(robot_png).convert("RGB")
    assert empty.size == robot.size == (320, 240)
    difference = np.asarray(ImageChops.difference(empty, robot)).max(axis=2)
    changed = float((difference > 40).mean())
    assert changed > 0.02, f"only {changed:.1%} of the pixels changed"
    # The robot's orange links show up as orange pixels.
    pixels = np.asarray(robot).astype(int)
    orange = (
        (pixels[..., 0] > 180)
        & (pixels[..., 1] > 60)
        & (pixels[..., 1] < 160)
        & (pixels[..., 2] < 80)
    )
    assert orange.sum() > 50


def test_a_description_is_drawn_from_a_plant_of_its_own(viewer, arm3):
    from workbench.errors import ViewerError
    from workbench.model import RobotDescription

    viewer.clear()
    description = RobotDescription.load("arm3")
    prefix = viewer.show_robot(description, prefix="/robots/from_description")
    robot = viewer.robot_at(prefix)
    assert robot.description is description and robot.plant is not arm3.plant
    assert robot.joint_names == arm3.joint_names
    q = robot.positions_from({"elbow_pitch_joint": 0.5})
    viewer.set_positions(robot, q, prefix)
    assert viewer.meshcat.HasPath(f"{prefix}/tool_link")
    with pytest.raises(ViewerError, match="no robot is shown at /nowhere"):
        viewer.robot_at("/nowhere")


def test_the_tf_display_frames_every_frame_it_draws(viewer):
    """The turtles of the tf lab sit near x = 8 m; the view must reach them (issue 14, item 13)."""
    from workbench.msgs.geometry_msgs import TransformStamped
    from workbench.tf import Buffer
    from workbench.viz.frames import TfDisplay

    buffer = Buffer()
    for child, x, y in (("turtle1", 8.0, 5.5), ("turtle2", 2.0, 1.0)):
        st = TransformStamped()
        st.header.frame_id, st.child_frame_id = "world", child
        st.transform.translation.x, st.transform.translation.y = x, y
        st.transform.rotation.w = 1.0
        buffer.set_transform_static(st, "test")
    display = TfDisplay(buffer, viewer, fixed_frame="world", scale=0.2)
    assert display.update() == {}
    eye, target = viewer.camera_pose
    # world at the origin, the turtles, each with its triad's reach (0.2 m): the box's centre
    assert target == pytest.approx([4.0, 2.75, 0.0], abs=1e-9)
    # far enough back to see the whole 8 m x 5.5 m spread
    assert np.linalg.norm(eye - target) > 8.0
    display.clear()


@pytest.mark.parametrize("port", [-1, 80, 65536, 10**20])
def test_a_port_drake_would_abort_on_is_refused_first(port):
    from workbench.errors import ViewerError

    with pytest.raises(ViewerError, match=r"--port must be 0 \(any free port\) or 1024..65535"):
        Viewer(port=port)
