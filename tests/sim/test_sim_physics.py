"""The server's physics against analytic answers (benchmarks/sim.py reports the same numbers)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sim_helpers import box_model

from workbench.sim import World
from workbench.sim.loading import load_sim_model
from workbench.sim.server import SERVER_PHYSICS

G = 9.81


def test_free_fall_before_contact_follows_z0_minus_half_g_t_squared():
    world = World(**SERVER_PHYSICS)
    world.add_model(box_model("box"), [0, 0, 2.0])
    world.build()
    world.advance_to(0.5)
    z = world.get_model_pose("box").translation()[2]
    # the discrete plant's symplectic Euler lags by g t dt / 2 = 2.45 mm at 0.5 s
    assert z == pytest.approx(2.0 - 0.5 * G * 0.25, abs=3e-3)


def test_a_box_rests_flat_without_drifting():
    world = World(**SERVER_PHYSICS)
    world.add_model(box_model("box", size=(0.3, 0.2, 0.1)), [0, 0, 0.05])
    world.build()
    world.advance_to(1.0)
    start = world.get_model_pose("box")
    world.advance_to(6.0)
    end = world.get_model_pose("box")
    assert end.translation()[2] == pytest.approx(0.05, abs=1e-4)
    assert np.linalg.norm(end.translation() - start.translation()) < 1e-5
    assert np.allclose(end.rotation().matrix(), np.eye(3), atol=1e-4)


def test_a_sliding_box_stops_after_v_squared_over_two_mu_g():
    world = World(**SERVER_PHYSICS)
    world.add_model(box_model("box", size=(0.2, 0.2, 0.05)), [0, 0, 0.025])
    world.build()
    world.advance_to(0.2)
    start = world.get_model_pose("box").translation()
    world.set_model_state("box", start, linear=[2.0, 0.0, 0.0])
    while world.get_model_twist("box")[0][0] > 1e-3 and world.time < 3.0:
        world.advance_to(world.time + 0.005)
    distance = world.get_model_pose("box").translation()[0] - start[0]
    assert distance == pytest.approx(2.0**2 / (2 * 1.0 * G), rel=0.03)  # mu 1 on mu 1


def test_the_spinning_top_precesses_at_the_gyroscopic_rate():
    from pydrake.math import RigidTransform, RollPitchYaw

    world = World(**SERVER_PHYSICS)
    X = RigidTransform(RollPitchYaw(0.2, 0.0, 0.0), [0.0, 0.0, 0.001])
    world.add_model(load_sim_model("spinning_top", name="top"), X)
    world.build()
    omega = 150.0
    world.set_model_state("top", X, angular=omega * X.rotation().col(2))
    times, azimuth = [], []
    for k in range(1, 201):
        world.advance_to(k * 0.01)
        axis = world.get_model_pose("top").rotation().col(2)
        times.append(world.time)
        azimuth.append(math.atan2(axis[1], axis[0]))
    rate = np.polyfit(times, np.unwrap(azimuth), 1)[0]
    predicted = 0.21 * G * 0.05 / (0.00026 * omega)  # m g l / (I3 w) = 2.64 rad/s
    assert rate == pytest.approx(predicted, rel=0.05)
