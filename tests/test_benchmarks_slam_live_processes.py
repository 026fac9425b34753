"""benchmarks/slam_live_processes.py writes a launch file the launcher reads as intended.

The ten-minute run itself is a benchmark (minutes of wall time); here its launch file is
loaded for real (the URDF and slam_gmapping's parameter file are read) and checked node by
node, with and without SLAM.
"""

from __future__ import annotations

from pathlib import Path

from benchmark_modules import benchmark_modules

from workbench.bus.launch import load_launch


def test_the_launch_file_starts_the_simulator_robot_and_slam(tmp_path: Path) -> None:
    with benchmark_modules("slam_live_processes") as (bench,):
        urdf = tmp_path / "robot.urdf"
        urdf.write_text(bench.encoder_urdf())
        for slam in (True, False):
            launch = tmp_path / f"run_{slam}.launch"
            launch.write_text(bench.launch_text(urdf, slam=slam, seed=3))
            plan = load_launch(launch)
            nodes = {(n.pkg, n.type): n for n in plan.nodes}
            expected = {
                ("gazebo_ros", "gzserver"),
                ("gazebo_ros", "spawn_model"),
                ("robot_state_publisher", "robot_state_publisher"),
            }
            if slam:
                expected.add(("gmapping", "slam_gmapping"))
            assert set(nodes) == expected
            server = nodes[("gazebo_ros", "gzserver")]
            assert server.args == ["--fast", "--headless", "--seed", "3", "house"]
            assert "<odometrySource>encoder</odometrySource>" in plan.params["/robot_description"]
            assert plan.params["/use_sim_time"] is True
            if slam:
                assert plan.params["/slam_gmapping/temporalUpdate"] == 0.5
                assert plan.params["/slam_gmapping/maxUrange"] == 3.0
