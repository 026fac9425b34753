"""NavfnROS on move_base's node: plans on the global costmap published as ~NavfnROS/plan,
the make_plan service, and navfn's log lines for goals it cannot plan to."""

from __future__ import annotations

import pytest
from costmap_world import GLOBAL_PARAMS, World, set_params
from process_helpers import wait_for

from workbench.bus import Bus, Node
from workbench.msgs.geometry_msgs import PoseStamped
from workbench.msgs.nav_msgs import GetPlan, Path
from workbench.navigation.costmap_errors import CostmapError
from workbench.navigation.costmap_ros import CostmapROS
from workbench.navigation.navfn import OFF_MAP_GOAL, NavfnROS
from workbench.tf import Buffer, TransformListener


@pytest.fixture
def planner():
    bus = Bus()
    set_params(bus, "/move_base/global_costmap", GLOBAL_PARAMS)
    node = Node("move_base", bus=bus, disable_rosout=True)
    buffer = Buffer()
    TransformListener(buffer, node)
    world = World(bus)
    world.publish_static()
    world.publish_map()
    stamp = node.now()
    world.publish_pose(0.0, 0.0, 0.0, stamp)
    assert wait_for(lambda: buffer.can_transform("map", "base_link", stamp))
    costmap = CostmapROS(node, "global_costmap", buffer, start_timers=False)
    costmap.update()
    plans: list[Path] = []
    watcher = Node("watcher", bus=bus, disable_rosout=True)
    watcher.create_subscription("/move_base/NavfnROS/plan", Path, plans.append)
    yield NavfnROS(node, "NavfnROS", costmap), plans, bus
    bus.shutdown()


def pose(x: float, y: float, frame: str = "map") -> PoseStamped:
    p = PoseStamped()
    p.header.frame_id = frame
    p.pose.position.x, p.pose.position.y = x, y
    p.pose.orientation.w = 1.0
    return p


def test_a_plan_is_returned_and_published(planner):
    navfn, plans, _ = planner
    plan = navfn.make_plan(pose(-1.0, -0.5), pose(1.0, 1.0))
    assert len(plan) > 10
    assert all(p.header.frame_id == "map" for p in plan)
    assert (plan[-1].pose.position.x, plan[-1].pose.position.y) == (1.0, 1.0)
    assert abs(plan[0].pose.position.x + 1.0) < 0.05 and abs(plan[0].pose.position.y + 0.5) < 0.05
    assert wait_for(lambda: len(plans) == 1)
    assert len(plans[0].poses) == len(plan) and plans[0].header.frame_id == "map"


def test_goals_off_the_map_in_walls_or_in_other_frames_give_empty_plans(planner, capsys):
    navfn, plans, _ = planner
    assert navfn.make_plan(pose(0.0, 0.0), pose(5.0, 0.0)) == []
    assert OFF_MAP_GOAL in capsys.readouterr().err
    assert navfn.make_plan(pose(0.0, 0.0), pose(1.52, 0.0)) == []  # in the wall
    assert wait_for(lambda: len(plans) == 1)
    assert plans[-1].poses == [] and plans[-1].header.frame_id == "map"  # published empty
    assert navfn.make_plan(pose(0.0, 0.0), pose(1.0, 0.0, "odom")) == []
    err = capsys.readouterr().err
    assert (
        "The goal pose passed to this planner must be in the map frame.  It is instead in the "
        "odom frame." in err
    )
    assert navfn.make_plan(pose(-3.0, 0.0), pose(1.0, 0.0)) == []
    assert "The robot's start position is off the global costmap." in capsys.readouterr().err


def test_default_tolerance_plans_to_the_nearest_free_point(planner):
    navfn, _, bus = planner
    navfn.default_tolerance = 0.5
    plan = navfn.make_plan(pose(0.0, 0.0), pose(1.52, 0.0))
    end = plan[-1].pose.position
    # the wall's cells 66..69 (x 1.30 .. 1.50) are inscribed: the window's x steps are
    # 1.02, 1.07, ... 1.27, 1.32 ...; 1.27 is the nearest reachable one
    assert end.x == pytest.approx(1.27) and end.y == pytest.approx(0.0)


def test_the_make_plan_service(planner):
    navfn, _, bus = planner
    client = Node("caller", bus=bus, disable_rosout=True).create_client(
        "/move_base/NavfnROS/make_plan", GetPlan
    )
    response = client.call(GetPlan.Request(start=pose(-1.0, -0.5), goal=pose(1.0, 1.0)))
    assert response.plan.header.frame_id == "map" and len(response.plan.poses) > 10
    response = client.call(GetPlan.Request(start=pose(-1.0, -0.5), goal=pose(9.0, 1.0)))
    assert response.plan.poses == []


def test_wrong_parameter_types_name_the_parameter(planner):
    navfn, _, bus = planner
    bus.params.set("/move_base/planner/allow_unknown", "yes")
    with pytest.raises(CostmapError, match=r"^parameter /move_base/planner/allow_unknown must be"):
        NavfnROS(navfn.node, "planner", navfn.costmap_ros)
    bus.params.set("/move_base/other/default_tolerance", [0.5])
    with pytest.raises(CostmapError, match="parameter /move_base/other/default_tolerance must be"):
        NavfnROS(navfn.node, "other", navfn.costmap_ros)
