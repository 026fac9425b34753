"""Finding the link a gazebo_ros model plugin names, and reading its motion."""

from __future__ import annotations

import zlib
from typing import Any

import numpy as np

from workbench.sim.plugins import PluginSetupError


def find_link(model: Any, name: str, plugin: str, tag: str, *, other_models: bool = False) -> str:
    """The scoped name (``model::link``) of the link ``name`` that ``<tag>`` gives.

    The model's own link of that name comes first; with ``other_models`` (Gazebo's
    ``World::EntityByName``) a ``model::link`` name or a link name unique in the world
    is taken too.

    Raises:
        PluginSetupError: No such link (one line naming model, plugin, tag and links).
    """
    if "::" not in name and name in model.link_names:
        return f"{model.name}::{name}"
    if (
        "::" in name
        and name.partition("::")[0] == model.name
        and name.partition("::")[2] in model.link_names
    ):
        return name
    if other_models:
        from workbench.errors import SimulationError

        world = model.server.world
        try:
            body = world.body(name)
        except SimulationError:
            body = None
        if body is not None:
            owner = world.plant.GetModelInstanceName(body.model_instance())
            return f"{owner}::{body.name()}"
    raise PluginSetupError(
        f"model '{model.name}': plugin '{plugin}': <{tag}> '{name}' is not a link of the model",
        hint="links: " + (", ".join(model.link_names) or "none"),
    )


def link_state(world: Any, scoped: str) -> tuple[Any, np.ndarray, np.ndarray]:
    """``(X_WL, v_W, w_W)`` of a link now: its pose, its origin's velocity and its angular velocity."""
    body = world.body(scoped)
    plant = world.plant
    context = plant.GetMyContextFromRoot(world.context)
    V = plant.EvalBodySpatialVelocityInWorld(context, body)
    return (
        plant.EvalBodyPoseInWorld(context, body),
        np.array(V.translational()),
        np.array(V.rotational()),
    )


def noise_seed(model: str, plugin: str) -> int:
    """A seed of the plugin's noise generator that stays the same from run to run."""
    return zlib.crc32(f"{model}::{plugin}".encode())


def vector(text: str | None, default: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> np.ndarray:
    """Three numbers from ``"x y z"`` (``default`` when missing or malformed)."""
    try:
        values = [float(v) for v in (text or "").split()]
    except ValueError:
        values = []
    return np.array(values if len(values) == 3 else default, dtype=float)
