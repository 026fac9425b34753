"""A spawn request's ``robot_namespace``, handed to the model's plugins.

gazebo_ros' spawn service (noetic, ``walkChildAddRobotNamespace``) adds
``<robotNamespace>NS</robotNamespace>`` to every ``<plugin>`` of the spawned
model that has none, when the request's ``robot_namespace`` is not empty.
``spawn_model`` sends its own namespace (``/`` at top level), so the drive of a
robot spawned from the command line listens on ``/cmd_vel``; a model from a
world file keeps its plugins' defaults (the model's name for most).
"""

from __future__ import annotations

import dataclasses

from lxml import etree

from workbench.sim.model_spec import PluginSpec, SimModel


def with_robot_namespace(model: SimModel, namespace: str) -> SimModel:
    """``model`` with ``<robotNamespace>namespace</robotNamespace>`` in plugins that lack it."""
    if not namespace:
        return model
    return dataclasses.replace(
        model, plugins=[_with_namespace(spec, namespace) for spec in model.plugins]
    )


def _with_namespace(spec: PluginSpec, namespace: str) -> PluginSpec:
    if not spec.element.strip():
        return spec
    element = etree.fromstring(spec.element.encode())
    if element.find("robotNamespace") is not None:
        return spec
    etree.SubElement(element, "robotNamespace").text = namespace
    return dataclasses.replace(spec, element=etree.tostring(element, encoding="unicode"))
