"""clear_costmap_recovery and rotate_recovery against a costmap stand-in.

From ``clear_costmap_recovery.cpp`` (Noetic): ``reset_distance`` is the side of the kept
square, only layers whose name's last part is in ``layer_names`` are cleared, a wrong
``affected_maps`` is warned about and taken as ``both``. From ``rotate_recovery.cpp``: a full
turn at ``sqrt(2 acc_lim_th remaining)`` clamped to [min_in_place_rotational_vel,
max_rotational_vel], refused with "Rotate recovery can't rotate in place because there is
a potential collision." when the footprint would meet a lethal cell.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pytest
from move_base_setup import GridSnapshot, param_node

from workbench.navigation.costs import LETHAL_OBSTACLE
from workbench.navigation.recovery import ClearCostmapRecovery, RotateRecovery


@dataclass
class _Layer:
    name: str


@dataclass
class _Layered:
    layers: list


@dataclass
class FakeCostmap:
    """The CostmapROS calls the recoveries make, recorded."""

    pose: tuple = (0.0, 0.0, 0.0)
    costs: np.ndarray = field(default_factory=lambda: np.zeros((80, 80), dtype=np.uint8))
    cleared: list = field(default_factory=list)
    footprint: list = field(
        default_factory=lambda: [(0.3, 0.1), (-0.1, 0.1), (-0.1, -0.1), (0.3, -0.1)]
    )
    layered: _Layered = field(
        default_factory=lambda: _Layered(
            [_Layer("obstacles"), _Layer("obstacle_layer"), _Layer("inflation_layer")]
        )
    )

    def robot_pose(self):
        return self.pose

    def costmap(self):
        return GridSnapshot(self.costs)

    def clear_outside(self, radius, layers):
        self.cleared.append((radius, list(layers)))

    def update(self):
        self.cleared.append("update")


def test_clear_costmap_clears_the_named_layers_of_both_maps() -> None:
    glob, loc = FakeCostmap(), FakeCostmap()
    node = param_node(**{"conservative_reset/reset_distance": 3.0})
    rec = ClearCostmapRecovery(node, "conservative_reset", glob, loc)
    rec.start()
    assert rec.step() == (True, None)
    assert glob.cleared == [(1.5, ["obstacles"])] and loc.cleared == [(1.5, ["obstacles"])]


def test_clear_costmap_options() -> None:
    glob, loc = FakeCostmap(), FakeCostmap()
    node = param_node(
        **{
            "r/affected_maps": "local",
            "r/layer_names": ["obstacle_layer"],
            "r/force_updating": True,
            "r/reset_distance": 1.0,
        }
    )
    ClearCostmapRecovery(node, "r", glob, loc).start()
    assert glob.cleared == [] and loc.cleared == [(0.5, ["obstacle_layer"]), "update"]
    lines = []
    node2 = param_node(**{"r/affected_maps": "everything"})
    node2.create_subscription("/rosout", "rosgraph_msgs/Log", lambda m: lines.append(m.msg), 0)
    assert ClearCostmapRecovery(node2, "r", glob, loc).affected_maps == "both"
    node2.bus.spin_once(0.0)
    assert any("Wrong value for affected_maps parameter: 'everything'" in m for m in lines)


def test_rotate_recovery_turns_a_full_circle() -> None:
    local = FakeCostmap()
    node = param_node(
        **{"TrajectoryPlannerROS/max_rotational_vel": 1.0, "TrajectoryPlannerROS/acc_lim_th": 3.2}
    )
    rec = RotateRecovery(node, "rotate_recovery", local, local)
    rec.start()
    yaw, dt, commands = 0.0, 0.05, []
    for _ in range(1000):
        local.pose = (0.0, 0.0, math.remainder(yaw, 2 * math.pi))
        done, cmd = rec.step()
        commands.append(cmd[2])
        if done:
            break
        yaw += cmd[2] * dt
    assert done and yaw == pytest.approx(2 * math.pi, abs=0.1)
    assert max(commands) == 1.0 and min(c for c in commands if c > 0) >= 0.4
    assert commands[-1] == 0.0


def test_rotate_recovery_refuses_a_collision() -> None:
    local = FakeCostmap()
    local.costs[44:46, 40:42] = (
        LETHAL_OBSTACLE  # beside the long robot: turning sweeps its nose into it
    )
    lines = []
    node = param_node()
    node.create_subscription("/rosout", "rosgraph_msgs/Log", lambda m: lines.append(m.msg), 0)
    rec = RotateRecovery(node, "rotate_recovery", local, local)
    rec.start()
    assert rec.step() == (True, (0.0, 0.0, 0.0))
    node.bus.spin_once(0.0)
    node.bus.spin_once(0.0)
    assert any(
        "Rotate recovery can't rotate in place because there is a potential collision. Cost: -1.00"
        in m
        for m in lines
    )
