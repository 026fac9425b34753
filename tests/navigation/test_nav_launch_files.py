"""The navigation launch files and their parameter files: Experiment 7.2's bot_model.launch with
move_base (manual, around line 5559, paths changed only) and its four YAML files for custom_bot,
and the turtlebot3_navigation package (ROBOTIS turtlebot3, noetic-devel: launch/*.launch,
param/*.yaml, rviz/turtlebot3_navigation.rviz). Checked with the launcher's dry run (nodes,
which files load where) and by reading them (the parameter values move_base and amcl get)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from workbench.bus.launch import find_package, load_launch
from workbench.paths import mapping_dir, urdf_dir

LAB_BOTS = find_package("lab_bots")
NAV = find_package("turtlebot3_navigation")


def test_bot_model_launch_starts_move_base_as_the_manual_writes_it():
    plan = load_launch(LAB_BOTS / "launch" / "bot_model.launch", dry_run=True)
    move_base = next(n for n in plan.nodes if n.name == "move_base")
    assert (move_base.pkg, move_base.type, move_base.output) == ("move_base", "move_base", "screen")
    assert [n.name for n in plan.nodes][-2:] == ["gmapping", "move_base"]
    assert plan.params["/move_base/controller_frequency"] == 10.0
    config = LAB_BOTS / "config"
    assert [(ns, Path(f)) for ns, f in plan.rosparam_files] == [
        ("/move_base/global_costmap", config / "costmap_common_params.yaml"),
        ("/move_base/local_costmap", config / "costmap_common_params.yaml"),
        ("/move_base", config / "local_costmap_params.yaml"),
        ("/move_base", config / "global_costmap_params.yaml"),
        ("/move_base", config / "trajectory_planner.yaml"),
    ]
    assert all(Path(f).is_file() for _, f in plan.rosparam_files)


def test_bot_model_launch_gives_move_base_the_tutorials_parameters_for_custom_bot():
    params = load_launch(LAB_BOTS / "launch" / "bot_model.launch").params
    for costmap in ("global_costmap", "local_costmap"):  # the common file in both
        ns = f"/move_base/{costmap}"
        assert params[f"{ns}/obstacle_range"] == 2.5
        assert params[f"{ns}/raytrace_range"] == 3.0
        assert params[f"{ns}/inflation_radius"] == 0.55
        assert params[f"{ns}/observation_sources"] == "laser_scan_sensor"
        sensor = f"{ns}/laser_scan_sensor"
        assert params[f"{sensor}/sensor_frame"] == "laser_scanner"  # custom_bot's laser link
        assert params[f"{sensor}/topic"] == "/scan"
        assert params[f"{sensor}/data_type"] == "LaserScan"
        assert params[f"{sensor}/marking"] is True and params[f"{sensor}/clearing"] is True
    assert params["/move_base/global_costmap/global_frame"] == "map"
    assert params["/move_base/global_costmap/robot_base_frame"] == "base_link"
    assert params["/move_base/global_costmap/static_map"] is True
    assert params["/move_base/global_costmap/update_frequency"] == 5.0
    local = {k.rsplit("/", 1)[1]: v for k, v in params.items() if k.count("/") == 3}
    assert {k: local[k] for k in ("width", "height", "resolution", "rolling_window")} == {
        "width": 6.0, "height": 6.0, "resolution": 0.05, "rolling_window": True,
    }  # fmt: skip
    assert params["/move_base/local_costmap/global_frame"] == "odom"
    planner = {
        k.removeprefix("/move_base/TrajectoryPlannerROS/"): v
        for k, v in params.items()
        if k.startswith("/move_base/TrajectoryPlannerROS/")
    }
    assert planner == {
        "max_vel_x": 0.45, "min_vel_x": 0.1, "max_vel_theta": 1.0,
        "min_in_place_vel_theta": 0.4, "acc_lim_theta": 3.2, "acc_lim_x": 2.5,
        "acc_lim_y": 2.5, "holonomic_robot": False,
        # not the tutorial's: custom_bot turns about its rear axle (see the file's comment)
        "yaw_goal_tolerance": 3.2,
    }  # fmt: skip


def _link_boxes(urdf: Path) -> dict[str, np.ndarray]:
    """Each link's collision shapes' corners (3, 8k) in the root link, with joints at zero."""
    from scipy.spatial.transform import Rotation

    root = ET.parse(urdf).getroot()

    def origin(element):
        o = element.find("origin") if element is not None else None
        xyz = [float(v) for v in (o.get("xyz", "0 0 0") if o is not None else "0 0 0").split()]
        rpy = [float(v) for v in (o.get("rpy", "0 0 0") if o is not None else "0 0 0").split()]
        return Rotation.from_euler("xyz", rpy).as_matrix(), np.array(xyz)

    parent_of = {j.find("child").get("link"): j for j in root.findall("joint")}

    def pose(link):
        if link not in parent_of:
            return np.eye(3), np.zeros(3)
        joint = parent_of[link]
        R_p, p_p = pose(joint.find("parent").get("link"))
        R_j, p_j = origin(joint)
        return R_p @ R_j, R_p @ p_j + p_p

    corners = {}
    for link in root.findall("link"):
        R_l, p_l = pose(link.get("name"))
        points = []
        for collision in link.findall("collision"):
            R_c, p_c = origin(collision)
            shape = collision.find("geometry")[0]
            if shape.tag == "box":
                half = np.array([float(v) for v in shape.get("size").split()]) / 2
            else:  # cylinder along z
                r, h = float(shape.get("radius")), float(shape.get("length"))
                half = np.array([r, r, h / 2])
            signs = np.array(np.meshgrid([-1, 1], [-1, 1], [-1, 1])).reshape(3, -1)
            local = R_c @ (signs * half[:, None]) + p_c[:, None]
            points.append(R_l @ local + p_l[:, None])
        if points:
            corners[link.get("name")] = np.concatenate(points, axis=1)
    return corners


def test_custom_bots_footprint_encloses_every_link_and_the_laser_frame_exists():
    params = load_launch(LAB_BOTS / "launch" / "bot_model.launch").params
    footprint = np.array(params["/move_base/global_costmap/footprint"])
    lo, hi = footprint.min(axis=0), footprint.max(axis=0)
    urdf = urdf_dir() / "custom_bot.urdf"
    boxes = _link_boxes(urdf)
    assert "laser_scanner" in boxes  # the sensor_frame is a link of the robot
    every = np.concatenate(list(boxes.values()), axis=1)[:2]
    assert np.all(every.min(axis=1) >= lo - 1e-6) and np.all(
        every.max(axis=1) <= hi + 1e-6
    )  # rpy 1.5708
    # ... and hugs it: no side more than 1 cm out
    assert np.all(lo > every.min(axis=1) - 0.01) and np.all(hi < every.max(axis=1) + 0.01)
    scan = ET.parse(urdf).getroot().find(".//sensor/plugin/topicName").text
    assert scan == params["/move_base/local_costmap/laser_scan_sensor/topic"]


def test_turtlebot3_navigation_dry_run_starts_the_navigation_nodes():
    plan = load_launch(NAV / "launch" / "turtlebot3_navigation.launch", dry_run=True)
    nodes = {n.name: n for n in plan.nodes}
    assert list(nodes) == ["robot_state_publisher", "map_server", "amcl", "move_base", "rviz"]
    assert nodes["map_server"].args == [str(mapping_dir() / "house.yaml")]
    assert find_package("workbench_maps") == mapping_dir()
    assert nodes["rviz"].args == ["-d", str(NAV / "rviz" / "turtlebot3_navigation.rviz")]
    assert nodes["rviz"].required
    assert nodes["move_base"].remaps == {"cmd_vel": "/cmd_vel", "odom": "odom"}
    assert nodes["amcl"].remaps == {"scan": "scan"}
    assert plan.params["/move_base/base_local_planner"] == "dwa_local_planner/DWAPlannerROS"
    param = NAV / "param"
    assert [(ns, Path(f).name) for ns, f in plan.rosparam_files] == [
        ("/move_base/global_costmap", "costmap_common_params_burger.yaml"),
        ("/move_base/local_costmap", "costmap_common_params_burger.yaml"),
        ("/move_base", "local_costmap_params.yaml"),
        ("/move_base", "global_costmap_params.yaml"),
        ("/move_base", "move_base_params.yaml"),
        ("/move_base", "dwa_local_planner_params_burger.yaml"),
    ]
    assert all((param / Path(f).name).is_file() for _, f in plan.rosparam_files)
    quiet = load_launch(
        NAV / "launch" / "turtlebot3_navigation.launch",
        {"open_rviz": "false", "map_file": "/maps/office.yaml"},
        dry_run=True,
    )
    assert [n.name for n in quiet.nodes] == [
        "robot_state_publisher",
        "map_server",
        "amcl",
        "move_base",
    ]
    assert quiet.nodes[1].args == ["/maps/office.yaml"]


def test_amcl_gets_the_turtlebot3_parameters():
    params = load_launch(NAV / "launch" / "amcl.launch", {"initial_pose_x": "1.5"}).params
    expected = {
        "min_particles": 500, "max_particles": 3000, "kld_err": 0.02, "update_min_d": 0.2,
        "update_min_a": 0.2, "resample_interval": 1, "transform_tolerance": 0.5,
        "recovery_alpha_slow": 0.0, "recovery_alpha_fast": 0.0, "initial_pose_x": 1.5,
        "initial_pose_y": 0.0, "initial_pose_a": 0.0, "gui_publish_rate": 50.0,
        "laser_max_range": 3.5, "laser_max_beams": 180, "laser_z_hit": 0.5,
        "laser_z_short": 0.05, "laser_z_max": 0.05, "laser_z_rand": 0.5, "laser_sigma_hit": 0.2,
        "laser_lambda_short": 0.1, "laser_likelihood_max_dist": 2.0,
        "laser_model_type": "likelihood_field", "odom_model_type": "diff", "odom_alpha1": 0.1,
        "odom_alpha2": 0.1, "odom_alpha3": 0.1, "odom_alpha4": 0.1, "odom_frame_id": "odom",
        "base_frame_id": "base_footprint",
    }  # fmt: skip
    assert params == {f"/amcl/{k}": v for k, v in expected.items()}


@pytest.mark.parametrize(("forward_only", "min_vel_x"), [("false", -0.22), ("true", 0.0)])
def test_move_base_gets_the_burgers_costmaps_and_dwa_parameters(forward_only, min_vel_x):
    params = load_launch(
        NAV / "launch" / "turtlebot3_navigation.launch", {"move_forward_only": forward_only}
    ).params
    for costmap in ("global_costmap", "local_costmap"):
        ns = f"/move_base/{costmap}"
        assert params[f"{ns}/footprint"] == [
            [-0.105, -0.105], [-0.105, 0.105], [0.041, 0.105], [0.041, -0.105],
        ]  # fmt: skip
        assert (params[f"{ns}/inflation_radius"], params[f"{ns}/cost_scaling_factor"]) == (1.0, 3.0)
        assert (params[f"{ns}/obstacle_range"], params[f"{ns}/raytrace_range"]) == (3.0, 3.5)
        assert params[f"{ns}/scan/sensor_frame"] == "base_scan"
        assert params[f"{ns}/robot_base_frame"] == "base_footprint"
        assert params[f"{ns}/update_frequency"] == params[f"{ns}/publish_frequency"] == 10.0
    assert params["/move_base/global_costmap/global_frame"] == "map"
    assert params["/move_base/global_costmap/static_map"] is True
    assert params["/move_base/local_costmap/global_frame"] == "odom"
    assert params["/move_base/local_costmap/rolling_window"] is True
    assert (
        params["/move_base/local_costmap/width"] == params["/move_base/local_costmap/height"] == 3
    )
    assert params["/move_base/controller_frequency"] == 10.0
    assert params["/move_base/planner_frequency"] == 5.0
    assert params["/move_base/oscillation_timeout"] == 10.0
    assert params["/move_base/conservative_reset_dist"] == 3.0
    dwa = "/move_base/DWAPlannerROS"
    assert params[f"{dwa}/min_vel_x"] == min_vel_x  # move_forward_only sets it to 0
    assert (params[f"{dwa}/max_vel_x"], params[f"{dwa}/max_vel_trans"]) == (0.22, 0.22)
    assert (params[f"{dwa}/max_vel_theta"], params[f"{dwa}/min_vel_theta"]) == (2.75, 1.37)
    assert (params[f"{dwa}/sim_time"], params[f"{dwa}/vth_samples"]) == (1.5, 40)
    assert (params[f"{dwa}/path_distance_bias"], params[f"{dwa}/goal_distance_bias"]) == (
        32.0,
        20.0,
    )
    assert (params[f"{dwa}/xy_goal_tolerance"], params[f"{dwa}/yaw_goal_tolerance"]) == (0.05, 0.17)


def test_the_trajectory_planner_file_has_robotis_values():
    import yaml

    data = yaml.safe_load((NAV / "param" / "base_local_planner_params.yaml").read_text())
    planner = data["TrajectoryPlannerROS"]
    assert (planner["max_vel_x"], planner["min_vel_x"], planner["min_in_place_vel_theta"]) == (
        0.18, 0.08, 1.0,
    )  # fmt: skip
    assert (planner["acc_lim_x"], planner["acc_lim_theta"], planner["holonomic_robot"]) == (
        1.0, 0.6, False,
    )  # fmt: skip


def test_the_navigation_view_parses_into_its_displays_and_tools():
    from workbench.rviz.config import load_config

    config = load_config(NAV / "rviz" / "turtlebot3_navigation.rviz")
    assert config.fixed_frame == "map"
    shown = [(d.class_name, d.options.get("topic")) for d in config.displays]
    assert shown == [
        ("Grid", None),
        ("RobotModel", None),
        ("TF", None),
        ("LaserScan", "/scan"),
        ("Map", "/map"),
        ("Path", "/move_base/NavfnROS/plan"),
        ("Map", "/move_base/global_costmap/costmap"),
        ("Path", "/move_base/DWAPlannerROS/global_plan"),
        ("Polygon", "/move_base/local_costmap/footprint"),
        ("Map", "/move_base/local_costmap/costmap"),
        ("Path", "/move_base/DWAPlannerROS/local_plan"),
        ("PoseArray", "/particlecloud"),
        ("Pose", "/move_base_simple/goal"),
    ]
    schemes = [d.options["color_scheme"] for d in config.displays if d.class_name == "Map"]
    assert schemes == ["map", "costmap", "costmap"]
    assert config.unknown == []
    tools = config.tools
    assert tools.tools == ("SetInitialPose", "SetGoal")
    assert (tools.initial_pose_topic, tools.goal_topic) == (
        "/initialpose",
        "/move_base_simple/goal",
    )
    assert (tools.std_dev_x, tools.std_dev_y) == (0.5, 0.5)
    assert tools.std_dev_theta == pytest.approx(math.pi / 12)
