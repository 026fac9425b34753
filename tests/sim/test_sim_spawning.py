"""Models spawned into and deleted from a running World: the others keep their state."""

from __future__ import annotations

import numpy as np
import pytest
from sim_helpers import box_model, spinner_model

from workbench.errors import SimulationError
from workbench.sim import World
from workbench.sim.server import SERVER_PHYSICS


def _world() -> World:
    return World(**SERVER_PHYSICS)


def _state(world: World, name: str) -> np.ndarray:
    plant = world.plant
    context = plant.GetMyContextFromRoot(world.context)
    instance = world.model_instance(name)
    return np.concatenate(
        [plant.GetPositions(context, instance), plant.GetVelocities(context, instance)]
    )


def test_a_spawn_while_running_keeps_every_other_state_and_the_time():
    world = _world()
    world.add_model(box_model("falling"), [0.0, 0.0, 2.0])
    world.add_model(spinner_model("spinner"), [2.0, 0.0, 0.0], joint_positions={"spin": 0.3})
    world.build()
    world.set_joint_positions("spinner", {"spin": 0.3})
    world.advance_to(0.25)
    before = {name: _state(world, name) for name in ("falling", "spinner")}
    assert before["falling"][-1] < -1.0  # it is falling fast
    world.add_model(box_model("newcomer"), [-2.0, 0.0, 0.5])
    assert world.rebuilds == 1
    assert world.time == pytest.approx(0.25)
    for name, state in before.items():
        np.testing.assert_array_equal(_state(world, name), state)
    assert world.model_names() == ["ground_plane", "falling", "spinner", "newcomer"]
    np.testing.assert_allclose(world.get_model_pose("newcomer").translation(), [-2.0, 0.0, 0.5])


def test_models_far_apart_move_exactly_as_if_nothing_was_spawned_or_deleted():
    reference = _world()
    reference.add_model(box_model("falling"), [0.0, 0.0, 1.0])
    reference.build()
    reference.advance_to(1.0)

    world = _world()
    world.add_model(box_model("falling"), [0.0, 0.0, 1.0])
    world.add_model(box_model("doomed"), [5.0, 5.0, 1.0])
    world.build()
    world.advance_to(0.2)
    world.add_model(box_model("late"), [-5.0, 5.0, 0.3])
    world.advance_to(0.5)
    world.remove_model("doomed")
    world.advance_to(1.0)
    # Contacts of all models are solved together, to the solver's tolerance (~1e-8 m/s).
    np.testing.assert_allclose(_state(world, "falling"), _state(reference, "falling"), atol=1e-7)
    assert "doomed" not in world.model_names()
    rest = world.get_model_pose("late").translation()
    assert rest[2] == pytest.approx(0.05, abs=2e-3)  # fell and rests on the ground


def test_a_name_in_use_is_refused_and_the_world_is_unchanged():
    world = _world()
    world.add_model(box_model("box"), [0.0, 0.0, 0.05])
    world.build()
    world.advance_to(0.1)
    with pytest.raises(SimulationError, match="'box' is already in use"):
        world.add_model(box_model("box"), [1.0, 0.0, 1.0])
    with pytest.raises(SimulationError, match="already in use"):
        world.add_model(box_model("ground_plane"))
    assert world.model_names() == ["ground_plane", "box"]
    assert world.rebuilds == 0


def test_bad_poses_and_unknown_models_are_one_line_errors():
    world = _world()
    world.add_model(box_model("box"), [0.0, 0.0, 0.05])
    world.build()
    with pytest.raises(SimulationError, match="not finite"):
        world.add_model(box_model("nan"), [float("nan"), 0.0, 1.0])
    with pytest.raises(SimulationError, match="no model named 'ghost'"):
        world.remove_model("ghost")
    with pytest.raises(SimulationError, match="no model named 'ghost'"):
        world.get_model_pose("ghost")
    with pytest.raises(SimulationError, match="not finite"):
        world.set_model_state("box", [0.0, 0.0, float("inf")])
    with pytest.raises(SimulationError, match="angular velocity is not finite"):
        world.set_model_state("box", [0.0, 0.0, 1.0], angular=[0.0, float("nan"), 0.0])
    with pytest.raises(SimulationError, match="has no joint 'spin'"):
        world.set_joint_positions("box", {"spin": 1.0})
    assert world.model_names() == ["ground_plane", "box"]


def test_set_model_state_teleports_with_a_velocity_and_reset_returns_to_the_spawn_pose():
    world = _world()
    world.add_model(box_model("box"), [0.0, 0.0, 0.05])
    world.build()
    world.set_model_state("box", [1.0, 2.0, 3.0], linear=[0.5, 0.0, 0.0], angular=[0, 0, 2.0])
    v, w = world.get_model_twist("box")
    np.testing.assert_allclose(v, [0.5, 0.0, 0.0])
    np.testing.assert_allclose(w, [0.0, 0.0, 2.0])
    world.advance_to(0.2)
    z = world.get_model_pose("box").translation()[2]
    assert z == pytest.approx(3.0 - 0.5 * 9.81 * 0.2**2, abs=2e-3)  # free fall
    world.reset(time=False)
    assert world.time == pytest.approx(0.2)
    np.testing.assert_allclose(world.get_model_pose("box").translation(), [0.0, 0.0, 0.05])
    world.reset()
    assert world.time == 0.0


def test_a_static_model_is_welded_and_moved_by_rebuilding():
    world = _world()
    world.add_model(box_model("shelf", size=0.4, static=True), [0.0, 0.0, 1.0])
    world.add_model(box_model("box"), [3.0, 0.0, 0.05])
    world.build()
    world.advance_to(0.5)
    np.testing.assert_allclose(world.get_model_pose("shelf").translation(), [0.0, 0.0, 1.0])
    world.set_model_state("shelf", [0.0, 1.0, 1.0])
    assert world.rebuilds == 1
    world.advance_to(0.6)
    np.testing.assert_allclose(world.get_model_pose("shelf").translation(), [0.0, 1.0, 1.0])


def test_joint_efforts_and_body_wrenches_act_until_changed():
    world = _world()
    world.add_model(spinner_model("spinner"), [0.0, 0.0, 0.0])
    world.add_model(box_model("box", mass=1.0), [2.0, 0.0, 0.05])
    world.build()
    world.set_joint_efforts({("spinner", "spin"): 0.004})  # I_zz 0.0004: 10 rad/s^2
    world.set_body_wrenches([(world.body("box::body"), [0.0, 0.0, 9.81 * 1.0 * 2.0], [0, 0, 0])])
    world.advance_to(0.5)
    spin = world.joint("spinner", "spin")
    plant_context = world.plant.GetMyContextFromRoot(world.context)
    assert world.plant.GetVelocities(plant_context)[spin.velocity_start()] == pytest.approx(
        5.0, rel=0.02
    )
    assert world.get_model_pose("box").translation()[2] > 0.05 + 0.5 * 9.81 * 0.25 * 0.9
    world.set_joint_efforts({})
    world.set_body_wrenches([])
    with pytest.raises(SimulationError, match="several models|no link"):
        world.body("nope")
