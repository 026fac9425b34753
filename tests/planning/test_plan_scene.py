from __future__ import annotations

import numpy as np
import pytest
from plan_core_helpers import DATA, SCENES

from workbench.planning.errors import SceneError
from workbench.planning.scene import PlanningScene, load_scene


def test_shipped_scenes_load():
    for path in sorted(SCENES.glob("*.yaml")):
        scene = load_scene(path)
        assert len(scene) >= 3, path
    scene = load_scene(SCENES / "arm3_table.yaml")
    table = scene.objects[scene.names().index("table")]
    assert table.type == "box"
    np.testing.assert_allclose(table.size, [0.3, 0.6, 0.04])
    np.testing.assert_allclose(table.X_WO[:3, 3], [0.4, 0.0, 0.12])


def test_python_scene_and_round_trip(tmp_path):
    import yaml

    scene = PlanningScene()
    scene.add_box("b", [0.1, 0.2, 0.3], xyz=[1, 2, 3], rpy=[0, 0, np.pi / 2])
    scene.add_sphere("s", 0.1, xyz=[0, 0, 1])
    scene.add_cylinder("c", 0.05, 0.4)
    path = tmp_path / "scene.yaml"
    path.write_text(yaml.safe_dump(scene.to_dict()))
    again = load_scene(path)
    assert again.names() == ["b", "s", "c"]
    np.testing.assert_allclose(again.objects[0].X_WO, scene.objects[0].X_WO, atol=1e-12)
    # rpy is fixed-axis roll-pitch-yaw: yaw of 90 degrees maps x onto y
    np.testing.assert_allclose(scene.objects[0].X_WO[:3, 0], [0, 1, 0], atol=1e-12)
    with pytest.raises(SceneError, match="already has an object named 'b'"):
        scene.add_sphere("b", 0.1)
    with pytest.raises(SceneError, match="positive radius"):
        scene.add_sphere("neg", -1.0)


def test_mesh_object_relative_to_file(tmp_path):
    import trimesh

    trimesh.creation.box([0.1, 0.1, 0.1]).export(tmp_path / "cube.obj")
    (tmp_path / "scene.yaml").write_text(
        "- name: cube\n  type: mesh\n  filename: cube.obj\n  pose: {xyz: [0.5, 0, 0]}\n"
    )
    scene = load_scene(tmp_path / "scene.yaml")
    assert scene.objects[0].filename == tmp_path / "cube.obj"
    np.testing.assert_allclose(scene.objects[0].half_extents(), [0.05, 0.05, 0.05])


@pytest.mark.parametrize(
    ("name", "message", "line"),
    [
        ("bad_type.yaml", "unknown type 'cone'", 5),
        ("missing_radius.yaml", "cylinder 'post' needs the field(s) radius", 6),
        ("bad_yaml.yaml", "not valid YAML", 5),
        ("bad_pose.yaml", "unknown pose field(s) ['xyzz']", 2),
        ("missing_mesh.yaml", "file", 2),
    ],
)
def test_malformed_scene_names_file_and_line(name, message, line):
    with pytest.raises(SceneError) as info:
        load_scene(DATA / name)
    text = info.value.one_line()
    assert f"{name}:{line}:" in text, text
    assert message in text, text
    assert "\n" not in text


def test_missing_scene_file(tmp_path):
    with pytest.raises(SceneError, match="not found"):
        load_scene(tmp_path / "none.yaml")
