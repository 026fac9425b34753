"""Seeded fuzzing of planning scenes: a scene or one clean error, and Drake takes every scene.

The shipped scenes and one with a mesh are mutated (values replaced by NaN,
infinities, strings, lists, nesting and huge numbers; keys dropped; objects
multiplied; mesh files pointed at directories, devices, pipes, text and
missing files; bytes cut, flipped and nested) and each mutant is read with
``load_scene``. A scene that loads is then registered in a Drake plant as
``plan`` does, which must not fail either. A few mutants also go through
``workbench plan``. See :mod:`model_fuzz_helpers` for what is asserted.
"""

from __future__ import annotations

import os
import random
from pathlib import Path

import pytest
import yaml
from model_fuzz_helpers import HOSTILE_NAMES, hang_guard, outside_writes, run_workbench, watched
from model_hostile_corpus import REPO, snapshot

from workbench.errors import WorkbenchError

SCENES = sorted((REPO / "planning" / "scenes").glob("*.yaml"))
MUTANTS = 300
SEED = 13
CUBE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
VALUES = [float("nan"), float("inf"), -1.0, 0, 1e308, "x", [], {}, None, True, [1, 2]]
VALUES += [[float("nan")] * 3, [1e308] * 3, ["a", "b", "c"], [[1, 2, 3]] * 3, "0.1" * 10000]


def _seed_scenes(folder: Path) -> list[dict]:
    scenes = [yaml.safe_load(path.read_text()) for path in SCENES]
    (folder / "cube.obj").write_text(CUBE)
    (folder / "flat.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n")
    (folder / "text.obj").write_text("not a mesh\n")
    (folder / "folder.obj").mkdir()
    os.mkfifo(folder / "pipe.obj")
    mesh = {"name": "part", "type": "mesh", "filename": "cube.obj", "scale": 0.1}
    mesh["pose"] = {"xyz": [0.5, 0, 0.3], "rpy": [0, 0, 1]}
    scenes.append({"objects": [mesh]})
    return scenes


def _leaves(node, path=()):
    if isinstance(node, dict):
        for key, value in node.items():
            yield from _leaves(value, (*path, key))
    elif isinstance(node, list):
        for index, value in enumerate(node):
            yield from _leaves(value, (*path, index))
    yield path


def _set(node, path, value):
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value


def _mutate(scene: dict, rng: random.Random) -> tuple[str, str]:
    """A mutant's YAML text and what was done."""
    kind = rng.choice(["value", "value", "drop", "many", "mesh", "name", "text"])
    objects = scene.get("objects") or []
    if kind == "value":
        path = rng.choice([p for p in _leaves(scene) if p])
        value = rng.choice(VALUES)
        _set(scene, path, value)
        what = f"{'/'.join(map(str, path))} = {str(value)[:30]}"
    elif kind == "drop" and objects:
        obj = rng.choice(objects)
        key = rng.choice(list(obj))
        del obj[key]
        what = f"dropped {key}"
    elif kind == "many" and objects:
        count = rng.choice([10, 499, 501, 2000])
        scene["objects"] = [dict(objects[0], name=f"o{i}") for i in range(count)]
        what = f"{count} objects"
    elif kind == "mesh":
        target = rng.choice(["folder.obj", "pipe.obj", "text.obj", "flat.obj", "missing.obj"])
        target = rng.choice([target, "/dev/zero", "/etc/passwd", "/proc/self/mem", "."])
        scene["objects"] = [{"name": "m", "type": "mesh", "filename": target}]
        what = f"mesh {target}"
    elif kind == "name" and objects:
        objects[0]["name"] = rng.choice(HOSTILE_NAMES)
        what = "hostile name"
    else:
        text = yaml.safe_dump(scene)
        choice = rng.choice(["cut", "bytes", "deep", "alias", "tabs"])
        if choice == "cut":
            return text[: rng.randrange(len(text) + 1)], "cut"
        if choice == "bytes":
            return text + "\x00\x7f\ufeff" * 3, "control characters"
        if choice == "deep":
            depth = rng.choice([100, 3000, 30000])
            return "objects: " + "[" * depth + "]" * depth, f"nested {depth}"
        if choice == "alias":
            levels = "".join(
                f"l{i}: &l{i} [" + ", ".join([f"*l{i - 1}"] * 9 if i else ["1"] * 9) + "]\n"
                for i in range(9)
            )
            return levels + "objects: *l8\n", "alias bomb"
        return text.replace("  ", "\t"), "tabs"
    return yaml.safe_dump(scene, allow_unicode=True), what


def _register(scene) -> None:
    """Put the scene into a Drake plant as the planner does."""
    from pydrake.multibody.plant import AddMultibodyPlantSceneGraph
    from pydrake.systems.framework import DiagramBuilder

    from workbench.planning.collision import add_scene_to_plant

    builder = DiagramBuilder()  # owns the plant: keep it alive while the plant is used
    plant, _ = AddMultibodyPlantSceneGraph(builder, 0.0)
    add_scene_to_plant(plant, scene)
    plant.Finalize()


def test_scene_mutants_end_cleanly(tmp_path, monkeypatch):
    from workbench.planning.scene import load_scene

    monkeypatch.chdir(tmp_path)
    rng = random.Random(SEED)
    seeds = _seed_scenes(tmp_path)
    before = snapshot(watched())
    failures, loaded = [], 0
    for index in range(MUTANTS):
        scene = yaml.safe_load(yaml.safe_dump(rng.choice(seeds)))
        text, what = _mutate(scene, rng)
        path = tmp_path / f"mutant{index}.yaml"
        path.write_text(text, encoding="utf-8", errors="surrogateescape")
        label = f"mutant {index} ({what})"
        try:
            with hang_guard(label):
                try:
                    _register(load_scene(path))
                    loaded += 1
                except WorkbenchError as error:
                    assert "\n" not in error.one_line()
        except (Exception, SystemExit) as error:  # anything but a WorkbenchError is a bug
            failures.append(f"{label}: {type(error).__name__}: {str(error)[:300]}")
        path.unlink()
    assert not failures, "\n".join(failures[:20])
    assert loaded > MUTANTS // 10  # the mutants are not all refused at the first byte
    assert outside_writes(before, []) == []


@pytest.mark.parametrize("index", range(2))
def test_scene_mutants_through_plan(tmp_path, index):
    """A few mutants through ``workbench plan`` in a fresh process."""
    rng = random.Random(SEED * 100 + index)
    seeds = _seed_scenes(tmp_path)
    text, what = _mutate(yaml.safe_load(yaml.safe_dump(rng.choice(seeds))), rng)
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    command = ["plan", "arm3", "--to", "home", "--from", "random", "--seed", "1", "--scene"]
    run_workbench([*command, str(path)], tmp_path, what)
