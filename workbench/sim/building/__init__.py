"""The building editor: floor plans (YAML/JSON or an image) to Gazebo-style SDF buildings.

From a notebook::

    from workbench.sim.building import load_plan, plan_from_image

    plan = load_plan("mapping/plans/house.yaml")
    print(plan.summary())
    plan.save("house.world")              # or plan.to_sdf() / plan.to_sdf("model")
    traced = plan_from_image("mapping/demo_rooms.yaml")   # a map_server map
    traced = plan_from_image("drawing.png", resolution=0.02, height=2.0)

``workbench world build PLAN -o WORLD.world`` does the same from the command line.
"""

from __future__ import annotations

from workbench.sim.building.image import plan_from_image
from workbench.sim.building.plan import (
    BuildingPlan,
    Floor,
    Item,
    Level,
    Opening,
    Piece,
    PlanError,
    Stairs,
    Wall,
)
from workbench.sim.building.plan_file import load_plan, parse_colour, plan_from_dict
from workbench.sim.building.raster import blocked_cells

__all__ = [
    "blocked_cells",
    "BuildingPlan",
    "Floor",
    "Item",
    "Level",
    "Opening",
    "Piece",
    "PlanError",
    "Stairs",
    "Wall",
    "load_plan",
    "parse_colour",
    "plan_from_dict",
    "plan_from_image",
]
