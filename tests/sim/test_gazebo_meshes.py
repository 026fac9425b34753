"""Gazebo models with meshes: model:// meshes in COLLADA, STL and OBJ, as Gazebo reads them.

The world has the shape of turtlebot3_gazebo's ``turtlebot3_world.world``: ``model://sun``,
``model://ground_plane`` and ``model://walls``, a static model whose collisions are
meshes found through ``GAZEBO_MODEL_PATH``, one of them a closed wall round the robot
(concave, like ``turtlebot3_world/meshes/wall.dae``) drawn in inches with
``<unit meter="0.0254">`` and ``<up_axis>Y_UP</up_axis>`` as SketchUp writes it, others
in a mesh-only folder without model.config (like ``turtlebot3_common_meshes``). What is
matched (gazebo 11): ColladaLoader scales vertices by ``<unit meter>`` and ignores
``<up_axis>``; ``model://NAME/PATH`` of a mesh is the file PATH under the first
GAZEBO_MODEL_PATH folder holding NAME; ODE collides with a mesh's triangles, so the
laser and the physics see the concave wall where it is drawn, not its hull.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from gazebo_model_files import model_folder, prism, square_ring, write_dae, write_obj, write_stl
from sensor_helpers import laser_xml, sdf_model, sensor_robot_sdf

from workbench.bus import Bus, Node
from workbench.errors import SimulationError
from workbench.sim.gzserver import ServerOptions, build_server

INCH = 0.0254
#: The wall: inner and outer half sizes and height, m.
INNER, OUTER, HEIGHT = 1.8, 2.0, 0.5
#: Pillars (name, mesh, centre x, y, half size): a binary STL drawn in mm and scaled by
#: <scale>0.001</scale> (as turtlebot3's lds.dae), an ASCII STL, an OBJ.
PILLARS = [
    ("pillar_stl", "pillar.stl", 1.0, 0.9, 0.15),
    ("pillar_ascii", "pillar_ascii.stl", -1.1, 0.7, 0.1),
    ("post_obj", "post.obj", 0.9, -1.0, 0.12),
]
LASER_AT = (0.3, -0.2, 0.25)
LASER_PLUGIN = (
    '<plugin name="laser" filename="libgazebo_ros_laser.so">'
    "<topicName>/scan</topicName><frameName>base_scan</frameName></plugin>"
)


def _square(half: float) -> np.ndarray:
    return np.array([[-half, -half], [half, -half], [half, half], [-half, half]])


def write_models(root: Path) -> Path:
    """The model folders; returns the GAZEBO_MODEL_PATH folder."""
    models = root / "models"
    common = models / "common_meshes"  # no model.config: meshes only
    vertices, faces = prism(_square(PILLARS[0][4]) * 1000.0, HEIGHT * 1000.0)
    write_stl(common / "pillar.stl", vertices, faces)
    vertices, faces = prism(_square(PILLARS[1][4]), HEIGHT)
    write_stl(common / "pillar_ascii.stl", vertices, faces, binary=False)
    vertices, faces = prism(_square(PILLARS[2][4]), HEIGHT)
    write_obj(common / "post.obj", vertices, faces)
    vertices, faces = square_ring(INNER / INCH, OUTER / INCH, HEIGHT / INCH)
    walls = model_folder(models, "walls", "", versions={"1.4": "model-1_4.sdf", "1.5": "model.sdf"})
    write_dae(
        walls / "meshes" / "wall.dae", vertices, faces, meter=INCH, unit="inch", up_axis="Y_UP"
    )
    pillars = ""
    for name, mesh, x, y, _ in PILLARS:
        scale = "<scale>0.001 0.001 0.001</scale>" if mesh == "pillar.stl" else ""
        geometry = (
            f"<geometry><mesh><uri>model://common_meshes/{mesh}</uri>{scale}</mesh></geometry>"
        )
        pillars += (
            f"<collision name='{name}'><pose>{x} {y} 0 0 0 0</pose>{geometry}<max_contacts>10"
            f"</max_contacts></collision><visual name='{name}'><pose>{x} {y} 0 0 0 0</pose>"
            f"{geometry}</visual>"
        )
    wall = "<geometry><mesh><uri>model://walls/meshes/wall.dae</uri></mesh></geometry>"
    (walls / "model.sdf").write_text(
        f"""<sdf version='1.5'>
  <model name='walls'>
    <static>1</static>
    <link name='walls'>
      <collision name='wall'>{wall}<surface><friction><ode/></friction></surface></collision>
      <visual name='wall'>{wall}<material><script>
        <uri>file://media/materials/scripts/gazebo.material</uri><name>Gazebo/Grey</name>
      </script></material></visual>
      {pillars}
    </link>
  </model>
</sdf>
"""
    )
    return models


def write_world(root: Path) -> Path:
    world = root / "walls.world"
    world.write_text(
        """<sdf version='1.4'>
  <world name='default'>
    <include><uri>model://sun</uri></include>
    <include><uri>model://ground_plane</uri></include>
    <physics type="ode"><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor></physics>
    <include><uri>model://walls</uri></include>
  </world>
</sdf>
"""
    )
    return world


@pytest.fixture
def walls_world(tmp_path, monkeypatch) -> Path:
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(write_models(tmp_path)))
    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / "cache"))
    return write_world(tmp_path)


def expected_range(origin: np.ndarray, angle: float) -> float:
    """Distance along a horizontal beam to the inner wall or a pillar (2D, exact)."""
    d = np.array([math.cos(angle), math.sin(angle)])
    best = math.inf
    for axis in (0, 1):
        for side in (-INNER, INNER):
            if abs(d[axis]) > 1e-12:
                t = (side - origin[axis]) / d[axis]
                if t > 0:
                    best = min(best, t)
    for _, _, x, y, half in PILLARS:
        low = (np.array([x, y]) - half - origin) / np.where(np.abs(d) < 1e-15, 1e-15, d)
        high = (np.array([x, y]) + half - origin) / np.where(np.abs(d) < 1e-15, 1e-15, d)
        t_in, t_out = np.minimum(low, high).max(), np.maximum(low, high).min()
        if t_in <= t_out and t_in > 0:
            best = min(best, float(t_in))
    return best


def test_model_meshes_in_collada_stl_and_obj_run_in_sim_and_pass_check(walls_world, run_cli):
    done = run_cli("sim", walls_world, "--headless", "--fast", "--until", "0.1", timeout=600)
    assert done.returncode == 0, done.stderr
    assert "walls" in done.stdout and "Traceback" not in done.stderr
    model = walls_world.parent / "models" / "walls" / "model.sdf"
    checked = run_cli("check", model, timeout=600)
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "0 error(s)" in checked.stdout or "no problems" in checked.stdout


def test_collada_units_scale_the_wall_and_the_concave_wall_becomes_prisms(walls_world):
    world, _, _ = build_server(ServerOptions(world=str(walls_world), view=False), Bus())
    world.build()
    from pydrake.geometry import Role

    inspector = world.scene_graph.model_inspector()
    shapes = {
        inspector.GetName(g): inspector.GetShape(g)
        for g in inspector.GetAllGeometryIds(Role.kProximity)
    }
    wall = [shape for name, shape in shapes.items() if name.startswith("walls::wall_piece_")]
    # each of the 8 upright faces is one prism; top and bottom (square rings, not convex)
    # one prism per triangle
    assert len(wall) == 8 + 2 * 8
    corners = np.array(
        [
            hull.vertex(i)
            for shape in wall
            for hull in [shape.GetConvexHull()]
            for i in range(hull.num_vertices())
        ]
    )
    assert np.abs(corners[:, :2]).max() == pytest.approx(OUTER, abs=1e-6)  # metres, not inches
    assert corners[:, 2].max() == pytest.approx(HEIGHT, abs=1e-6)  # and Y_UP is not turned
    for name, _, _, _, half in PILLARS:  # convex meshes stay one hull each
        hull = shapes[f"walls::{name}"].GetConvexHull()
        extent = np.ptp([hull.vertex(i) for i in range(hull.num_vertices())], axis=0)
        assert extent == pytest.approx([2 * half, 2 * half, HEIGHT], abs=1e-6)


def test_the_burger_shaped_robots_laser_sees_the_mesh_world_where_it_is_drawn(walls_world):
    bus = Bus(threaded=False)
    scans: list = []
    Node("listener", bus=bus).create_subscription(
        "/scan", "sensor_msgs/LaserScan", scans.append, queue_size=100
    )
    world, server, _ = build_server(
        ServerOptions(world=str(walls_world), view=False, fast=True), bus
    )
    laser = laser_xml(samples=360, min_angle=0.0, max_angle=6.28, range_max=3.5, rate=10.0)
    robot = sensor_robot_sdf(
        "burger", laser.replace("</sensor>", LASER_PLUGIN + "</sensor>"), size=0.1
    )
    server.spawn(sdf_model(robot), [LASER_AT[0], LASER_AT[1], LASER_AT[2] - 0.1])
    server.run(until=0.25)
    while bus.spin_once(0.0):
        pass
    assert scans, "no scan was published"
    scan = scans[-1]
    angles = np.linspace(0.0, 6.28, 360)
    expected = np.array([expected_range(np.array(LASER_AT[:2]), a) for a in angles])
    expected[expected >= 3.5] = np.inf
    ranges = np.array(scan.ranges)
    assert np.array_equal(np.isfinite(ranges), np.isfinite(expected))
    assert np.isfinite(expected).all()  # every beam meets the wall or a pillar
    assert np.max(np.abs(ranges - expected)) < 1e-5
    server.stop()


def test_a_box_inside_the_concave_wall_rests_where_it_was_put(walls_world):
    from sim_helpers import box_model

    world, server, _ = build_server(
        ServerOptions(world=str(walls_world), view=False, fast=True), Bus()
    )
    server.spawn(box_model("crate", size=0.2), [0.0, 0.0, 0.1])
    server.run(until=0.5)
    position = world.get_model_pose("crate").translation()
    # Taken as its hull the wall would fill the room and throw the crate out.
    assert np.linalg.norm(position - np.array([0.0, 0.0, 0.1])) < 0.01
    server.stop()


def test_a_missing_mesh_and_an_unknown_model_folder_are_one_line_errors(walls_world):
    sdf = walls_world.parent / "models" / "walls" / "model.sdf"
    sdf.write_text(sdf.read_text().replace("common_meshes/post.obj", "common_meshes/gone.obj"))
    with pytest.raises(SimulationError) as caught:
        build_server(ServerOptions(world=str(walls_world), view=False), Bus())
    text = str(caught.value)
    assert (
        "model://common_meshes/gone.obj" in text
        and "model folder 'common_meshes' has no gone.obj" in text
    )
    assert f"{sdf}:" in text and "\n" not in text
    sdf.write_text(sdf.read_text().replace("common_meshes/gone.obj", "no_such_folder/post.obj"))
    with pytest.raises(SimulationError, match="no model folder 'no_such_folder'"):
        build_server(ServerOptions(world=str(walls_world), view=False), Bus())


def test_a_collada_file_with_an_image_that_names_no_file_is_read_as_gazebo_reads_it(tmp_path):
    from workbench.model.mesh_pieces import load_triangles
    from workbench.model.meshes import prepare_mesh

    vertices, faces = prism(_square(100.0), 70.0)  # mm, as gazebo_models' arm_part
    dae = write_dae(
        tmp_path / "arm.dae",
        vertices,
        faces,
        meter=0.001,
        unit="millimeter",
        image_without_file=True,
    )
    mesh = load_triangles(prepare_mesh(dae))
    assert len(mesh.faces) == len(faces)
    np.testing.assert_allclose(mesh.bounds, [[-0.1, -0.1, 0.0], [0.1, 0.1, 0.07]], atol=1e-9)


def test_a_plane_collision_is_a_box_whose_top_is_the_plane(tmp_path, monkeypatch):
    """turtlebot3_autorace's course: a static model whose collision is a <plane> 4 m wide."""
    from sim_helpers import box_model

    from workbench.sim import World
    from workbench.sim.gazebo_sdf import sim_model_from_sdf
    from workbench.sim.server import SERVER_PHYSICS, SimServer

    plane = "<geometry><plane><normal>0 0 1</normal><size>4 4</size></plane></geometry>"
    course = sim_model_from_sdf(
        f"<sdf version='1.5'><model name='course'><static>1</static><pose>0 0 0.3 0 0 -3.14</pose>"
        f"<link name='link'><collision name='collision'>{plane}</collision>"
        f"<visual name='visual'><cast_shadows>false</cast_shadows>{plane}</visual></link></model></sdf>",
        name=None,
        source="course.sdf",
    )
    world = World(**SERVER_PHYSICS)
    server = SimServer(world, real_time_factor=0)
    server.spawn(course, [0.0, 0.0, 0.0])
    server.spawn(box_model("crate", size=0.2), [1.0, 0.5, 0.45])
    server.run(until=0.5)
    z = world.get_model_pose("crate").translation()[2]
    assert z == pytest.approx(0.4, abs=2e-3)  # resting on the plane at 0.3, not the ground
    server.stop()


def test_material_scripts_by_name_and_a_second_mesh_uri_load_as_in_gazebo(tmp_path, monkeypatch):
    """gazebo_models' husky and pr2 name material scripts without a <uri> (libsdformat 12
    refuses them, Gazebo 11 loads them); pr2_gripper's meshes carry a second, "__default__"
    <uri> (libsdformat reads the first)."""
    from workbench.sim import World
    from workbench.sim.gazebo_sdf import sim_model_from_sdf
    from workbench.sim.server import SERVER_PHYSICS

    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / "cache"))
    vertices, faces = prism(_square(0.1), 0.2)
    mesh = write_stl(tmp_path / "meshes" / "wrist_roll.stl", vertices, faces)
    geometry = (
        f"<geometry><mesh><uri>{mesh.as_uri()}</uri><scale>1 1 1</scale>"
        "<uri>__default__</uri></mesh></geometry>"
    )
    model = sim_model_from_sdf(
        "<sdf version='1.5'><model name='pr2'><link name='wrist'>"
        "<inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>"
        f"<collision name='c'>{geometry}</collision><visual name='v'>{geometry}"
        "<material><script><name>Gazebo/Red</name></script></material></visual>"
        "</link></model></sdf>",
        name=None,
        source=str(tmp_path / "model.sdf"),
        base_dir=tmp_path,
    )
    assert "<script>" not in model.text and "__default__" not in model.text
    world = World(**SERVER_PHYSICS)
    world.add_model(model, [0.0, 0.0, 0.1])
    world.build()
    from pydrake.geometry import Role

    inspector = world.scene_graph.model_inspector()
    (visual,) = inspector.GetAllGeometryIds(Role.kIllustration)[-1:]
    rgba = inspector.GetIllustrationProperties(visual).GetProperty("phong", "diffuse")
    assert [rgba.r(), rgba.g(), rgba.b()] == [1.0, 0.0, 0.0]  # Gazebo/Red


def test_a_loop_of_joints_is_refused_in_one_line_naming_the_joint(tmp_path):
    """gazebo_models' polaris_ranger_ev closes a loop through its differential (Gazebo's ODE
    simulates loops; Drake builds trees of links)."""
    from workbench.sim import World
    from workbench.sim.gazebo_sdf import sim_model_from_sdf
    from workbench.sim.server import SERVER_PHYSICS

    inertial = "<inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>"
    links = "".join(
        f"<link name='{n}'>{inertial}</link>" for n in ("chassis", "left", "right", "diff")
    )
    joints = "".join(
        f"<joint name='{n}' type='revolute'><parent>{p}</parent><child>{c}</child>"
        "<axis><xyz>0 1 0</xyz></axis></joint>"
        for n, p, c in (
            ("left_joint", "chassis", "left"),
            ("right_joint", "chassis", "right"),
            ("diff_left", "left", "diff"),
            ("rear_differential_joint", "right", "diff"),
        )
    )
    model = sim_model_from_sdf(
        f"<sdf version='1.5'><model name='cart'>{links}{joints}</model></sdf>",
        name=None,
        source="cart.sdf",
    )
    with pytest.raises(SimulationError) as caught:
        World(**SERVER_PHYSICS).add_model(model, [0.0, 0.0, 0.5])
    text = str(caught.value)
    assert "joint 'rear_differential_joint' closes a loop of links" in text and "\n" not in text
