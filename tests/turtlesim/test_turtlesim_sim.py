"""The pure turtlesim simulation against ROS Noetic's turtlesim.

What is matched, and where it comes from (ros/ros_tutorials, noetic-devel):
- turtle_frame.cpp: a 500x500 canvas, ``meter_`` = the turtle image height (45 px),
  ``width_in_meters_ = (width() - 1) / meter_``; turtle1 spawned at the centre;
  the QTimer interval of 16 ms and ``update(0.001 * interval)``; default background
  0x45 0x56 0xff, re-read from ``~background_r/g/b`` in ``clear()``; ``spawnTurtle``
  names ``turtle<++id_counter_>`` skipping taken names; the error lines
  "A turtled named [%s] already exists" and "Tried to kill turtle [%s], which does not exist";
  ``reset`` respawns turtle1 and resets the counter.
- turtle.cpp: teleports are applied first; the 1 s (wall) command timeout; the heading
  is integrated and wrapped with ``orient -= 2pi*floor((orient+pi)/2pi)`` before the
  position moves; the clamp and "Oh no! I hit the wall! (Clamping from [x=%f, y=%f])"
  in canvas coordinates; default pen 0xb3 0xb8 0xff, 3 px; ``set_pen`` with off=1
  only lifts the pen; the colour sensor reads the path image under the turtle.
"""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest

from workbench.turtlesim import (
    CANVAS_PX,
    DEFAULT_BACKGROUND,
    DEFAULT_PEN,
    UPDATE_PERIOD,
    UPDATE_RATE,
    WORLD_SIZE,
    TurtleError,
    TurtleSim,
)


@pytest.fixture
def logs():
    return []


@pytest.fixture
def sim(logs):
    return TurtleSim(log=lambda level, text: logs.append((level, text)))


def test_world_geometry_and_rate():
    assert CANVAS_PX == 500
    assert pytest.approx(11.088889, abs=1e-6) == WORLD_SIZE
    assert UPDATE_PERIOD == 0.016
    assert UPDATE_RATE == 62.5


def test_startup_log_lines_match_the_manual(sim, logs):
    assert logs[0] == (logging.INFO, "Starting turtlesim with node name /turtlesim")
    # the manual's Experiment 2 output, digit for digit
    assert logs[1] == (
        logging.INFO,
        "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]",
    )
    pose = sim.turtle("turtle1").pose
    assert (pose.x, pose.y, pose.theta) == pytest.approx((5.544445, 5.544445, 0.0), abs=1e-6)


def test_straight_motion_integrates_dt(sim):
    t = sim.turtle("turtle1")
    t.command_velocity(2.0, 0.0, sim.time)
    for _ in range(10):
        sim.step()
    assert t.pose.x == pytest.approx(5.544445 + 2.0 * 10 * 0.016, abs=1e-5)
    assert t.pose.y == pytest.approx(5.544445, abs=1e-6)
    assert t.pose.linear_velocity == 2.0


def test_heading_is_updated_before_position(sim):
    t = sim.turtle("turtle1")
    t.command_velocity(1.0, math.pi / 2, sim.time)
    x0, y0 = t.pose.x, t.pose.y
    sim.step()
    theta = math.pi / 2 * UPDATE_PERIOD
    assert t.pose.theta == pytest.approx(theta)
    assert t.pose.x - x0 == pytest.approx(math.cos(theta) * 0.016)
    assert t.pose.y - y0 == pytest.approx(math.sin(theta) * 0.016)


def test_heading_wraps_into_minus_pi_pi(sim):
    t = sim.turtle("turtle1")
    t.teleport_absolute(5.0, 5.0, math.pi - 0.001)
    sim.step()
    t.command_velocity(0.0, 1.0, sim.time)
    sim.step()
    assert t.pose.theta == pytest.approx(math.pi - 0.001 + 0.016 - 2 * math.pi, abs=1e-6)


def test_command_times_out_after_one_second(sim):
    t = sim.turtle("turtle1")
    t.command_velocity(2.0, 1.8, sim.time)
    steps = 0
    while t.pose.linear_velocity != 0.0:
        sim.step()
        steps += 1
    # moving while (now - last_command) <= 1.0 s
    assert steps == int(1.0 / UPDATE_PERIOD) + 1
    x = t.pose.x
    sim.step()
    assert t.pose.x == x


def test_wall_clamps_and_warns_in_canvas_coordinates(sim, logs):
    t = sim.turtle("turtle1")
    t.teleport_absolute(WORLD_SIZE - 0.01, 3.0, 0.0)
    sim.step()
    t.command_velocity(2.0, 0.0, sim.time)
    sim.step()
    assert t.pose.x == pytest.approx(WORLD_SIZE)
    level, text = logs[-1]
    assert level == logging.WARNING
    canvas_y = WORLD_SIZE - 3.0
    assert text == (
        f"Oh no! I hit the wall! (Clamping from [x={WORLD_SIZE - 0.01 + 0.032:f}, y={canvas_y:f}])"
    )


def test_teleports(sim):
    t = sim.turtle("turtle1")
    t.teleport_absolute(1.0, 1.0, 0.0)
    sim.step()
    assert (t.pose.x, t.pose.y, t.pose.theta) == pytest.approx((1.0, 1.0, 0.0))
    t.teleport_relative(1.0, math.pi / 2)
    sim.step()
    assert (t.pose.x, t.pose.y) == pytest.approx((1.0, 2.0), abs=1e-6)
    assert t.pose.theta == pytest.approx(math.pi / 2, abs=1e-6)


def _pixel(sim, x, y):
    return sim.path_image.getpixel((round(x * 45), round((WORLD_SIZE - y) * 45)))


def test_pen_draws_trails_and_set_pen(sim):
    t = sim.turtle("turtle1")
    t.teleport_absolute(3.0, 3.0, 0.0)
    sim.step()
    assert _pixel(sim, 4.0, 5.0) == DEFAULT_BACKGROUND
    assert _pixel(sim, 4.27, 4.27) == DEFAULT_PEN  # on the teleport line
    t.set_pen(255, 0, 255, 3, off=False)
    t.teleport_absolute(3.0, 8.0, 0.0)
    sim.step()
    assert _pixel(sim, 3.0, 6.0) == (255, 0, 255)
    t.set_pen(0, 255, 0, 3, off=True)
    t.teleport_absolute(8.0, 8.0, 0.0)
    sim.step()
    assert _pixel(sim, 6.0, 8.0) == DEFAULT_BACKGROUND
    # lifting the pen keeps its colour: the next line is magenta again
    t.set_pen(0, 0, 0, 0, off=False)  # width 0 -> a 1 px pen
    assert t.pen_width == 1


def test_color_sensor_reads_the_canvas(sim):
    poses = sim.step()
    pose, colour = poses["turtle1"]
    # the start position has the pen trail of nothing yet: the background
    assert colour == DEFAULT_BACKGROUND
    t = sim.turtle("turtle1")
    t.set_pen(10, 20, 30, 5, off=False)
    t.command_velocity(1.0, 0.0, sim.time)
    _, colour = sim.step()["turtle1"]
    assert colour == (10, 20, 30)


def test_clear_rereads_background_parameters(sim, logs):
    sim.params["background_r"] = 150
    assert sim.background == DEFAULT_BACKGROUND  # not until clear
    sim.clear()
    assert logs[-1] == (logging.INFO, "Clearing turtlesim.")
    assert sim.background == (150, 0x56, 0xFF)
    assert sim.path_image.getpixel((10, 10)) == (150, 0x56, 0xFF)


def test_spawn_auto_names_and_errors(sim, logs):
    assert sim.spawn("", 2, 2, 0.2) == "turtle2"
    assert (
        logs[-1][1] == "Spawning turtle [turtle2] at x=[2.000000], y=[2.000000], theta=[0.200000]"
    )
    assert sim.spawn("turtle3", 1, 1, 0) == "turtle3"
    assert sim.spawn("", 1, 1, 0) == "turtle4"  # turtle3 is taken, so the counter skips it
    with pytest.raises(TurtleError, match="already exists"):
        sim.spawn("turtle2", 1, 1, 0)
    assert logs[-1] == (logging.ERROR, "A turtled named [turtle2] already exists")


def test_kill_and_reset(sim, logs):
    sim.spawn("leo", 2, 2, 0)
    sim.kill("leo")
    assert "leo" not in sim.turtles
    with pytest.raises(TurtleError, match="no turtle named 'leo'"):
        sim.kill("leo")
    assert logs[-1] == (logging.ERROR, "Tried to kill turtle [leo], which does not exist")
    sim.spawn("", 1, 1, 0)
    sim.params["background_g"] = 0
    sim.reset()
    assert list(sim.turtles) == ["turtle1"]
    assert sim.background == (0x45, 0, 0xFF)
    assert (logging.INFO, "Resetting turtlesim.") in logs


def test_render_draws_turtles_and_png(sim, tmp_path):
    sim.spawn("", 2, 2, 0.2)
    image = sim.render_array()
    assert image.shape == (500, 500, 3)
    centre = image[245:255, 245:255]
    assert not np.all(centre == np.array(DEFAULT_BACKGROUND, dtype=np.uint8))
    # the path image itself is untouched by drawing turtles
    assert sim.path_image.getpixel((250, 250)) == DEFAULT_BACKGROUND
    path = tmp_path / "snap.png"
    sim.save_png(path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_snapshot_to_unwritable_path_is_one_line_error(sim, tmp_path):
    from workbench.errors import SimulationError

    with pytest.raises(SimulationError, match="cannot write"):
        sim.save_png(tmp_path / "missing" / "dir" / "snap.png")


def test_ten_turtles_step_in_name_order(sim):
    for i in range(9):
        sim.spawn("", 1 + i, 1, 0)
    out = sim.step()
    assert list(out) == sorted(out)
    assert len(out) == 10


def test_canvas_server_serves_page_and_png(sim):
    import urllib.request

    from workbench.turtlesim.view import CanvasServer

    server = CanvasServer(sim)
    server.start()
    try:
        page = urllib.request.urlopen(server.url, timeout=5).read()
        assert b"canvas.png" in page
        png = urllib.request.urlopen(server.url + "canvas.png", timeout=5).read()
        assert png[:8] == b"\x89PNG\r\n\x1a\n"
    finally:
        server.stop()
