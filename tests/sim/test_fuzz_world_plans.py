"""Seeded fuzzing of ``world build`` plans: a world, or one clean error, always.

The shipped plans (``mapping/plans/``) and a plan with levels, stairs and every kind of
furniture are mutated, as parsed values (numbers made NaN, infinite, huge, negative or
garbage; names made long, empty, multi-line or numbers; keys deleted; lists repeated
thousands of times or nested deeply) and as bytes (cut, flipped, spliced with hostile
YAML), written as YAML or JSON, and built as ``workbench world build`` does: read, checked,
turned into SDF and written. Each mutant must give a world whose SDF is well-formed with
finite numbers and that the simulator's world reader loads, or one :class:`~workbench.errors.WorkbenchError` line, within the hang
bound, writing nothing outside its folder. A few mutants also go through the real command
line.
"""

from __future__ import annotations

import copy
import json
import math
import random
import re
from pathlib import Path
from typing import Any
from xml.etree import ElementTree

import pytest
import yaml
from fuzz_helpers import (
    TEXT_TOKENS,
    Mutator,
    WriteWatch,
    bounded,
    check_one_line,
    fuzz_runs,
    fuzz_seed,
    report,
    run_cli_checked,
)

from workbench.errors import WorkbenchError
from workbench.sim.building import load_plan
from workbench.sim.world_file import load_world

REPO = Path(__file__).resolve().parents[2]
PLANS = sorted((REPO / "mapping" / "plans").glob("*.yaml"))

#: A plan with what the shipped ones lack: levels, slabs, stairs, tables, windows.
STOREYS = {
    "name": "storeys",
    "levels": [
        {
            "name": "ground",
            "walls": [
                {
                    "name": "outer",
                    "points": [[0, 0], [6, 0], [6, 4], [0, 4]],
                    "closed": True,
                    "doors": [{"name": "front", "at": 3, "width": 1.0}],
                    "windows": [{"name": "east", "at": 8, "width": 1.0, "sill": 0.9}],
                }
            ],
        },
        {
            "name": "first",
            "elevation": 2.7,
            "floor": True,
            "walls": [{"name": "upper", "start": [0, 0], "end": [6, 0], "thickness": 0.2}],
        },
    ],
    "stairs": [
        {"name": "flight", "from": "ground", "to": "first", "start": [1, 1], "length": 3,
         "steps": 14, "direction": 0, "width": 0.9}
    ],
    "furniture": [
        {"name": "table", "type": "table", "at": [4, 2], "size": [1.2, 0.8, 0.75], "yaw": 30},
        {"name": "bin", "type": "cylinder", "at": [5, 3], "radius": 0.2, "height": 0.6},
        {"name": "shelf", "type": "box", "at": [5, 1], "size": [0.4, 1.6, 1.8],
         "level": "first", "colour": "Wood"},
    ],
}  # fmt: skip

HOSTILE_NUMBERS: list[Any] = [
    math.nan, math.inf, -math.inf, 1e308, -1e308, 1e-300, 0, -1, 2**70, 10**400,
    "1e308", "x", True, None, [], {}, [1, 2, 3],
]  # fmt: skip
HOSTILE_NAMES: list[Any] = [
    "x" * 5000, "", " ", "a/b", "a::b", "::", "line\nbreak", "tab\tname", "\x00", "ground_plane",
    12345, 10**400, None, [], {"a": 1}, "'\"<&>", "é" * 300,
]  # fmt: skip
#: Marks a value to be replaced by lists nested N deep once the plan is text.
NEST = "nested-lists-"
#: Seconds one mutant may take: a hang detector, far above a 5,000-wall plan.
HANG_SECONDS = 60


def _seeds() -> list[tuple[str, Any]]:
    seeds = [(path.name, yaml.safe_load(path.read_text())) for path in PLANS]
    return [*seeds, ("storeys", STOREYS)]


def _places(value: Any, path: tuple = ()) -> list[tuple[tuple, Any]]:
    """Every (path, value) in the parsed plan, containers included."""
    found = [(path, value)]
    if isinstance(value, dict):
        for key, child in value.items():
            found += _places(child, (*path, key))
    elif isinstance(value, list):
        for index, child in enumerate(value):
            found += _places(child, (*path, index))
    return found


def _set(doc: Any, path: tuple, value: Any) -> Any:
    if not path:
        return value
    parent = doc
    for key in path[:-1]:
        parent = parent[key]
    parent[path[-1]] = value
    return doc


def _mutate_value(doc: Any, rng: random.Random) -> tuple[Any, str]:
    """One change to the parsed plan; returns the plan and what was done."""
    doc = copy.deepcopy(doc)
    places = _places(doc)
    path, value = rng.choice(places)
    kind = rng.choice(
        ["jitter", "jitter", "number", "number", "name", "delete", "repeat", "nest", "swap", "key"]
    )
    numbers = [(p, v) for p, v in places if isinstance(v, int | float) and not isinstance(v, bool)]
    names = [(p, v) for p, v in places if p and p[-1] in ("name", "from", "to", "level", "type")]
    if kind == "jitter" and numbers:  # a plausible change: most still build
        path, old = rng.choice(numbers)
        new = old * rng.uniform(0.5, 1.5) + rng.uniform(-0.5, 0.5)
        return _set(doc, path, new), f"jitter {path} = {new:.3g}"
    if kind == "number" and numbers:
        path, _ = rng.choice(numbers)
        new = rng.choice(HOSTILE_NUMBERS)
        return _set(doc, path, new), f"number {path} = {new!r:.30}"
    if kind == "name" and names:
        path, _ = rng.choice(names)
        new = rng.choice(HOSTILE_NAMES)
        return _set(doc, path, new), f"name {path} = {new!r:.30}"
    if kind == "delete" and path:
        parent = doc
        for key in path[:-1]:
            parent = parent[key]
        del parent[path[-1]]
        return doc, f"delete {path}"
    lists = [(p, v) for p, v in places if isinstance(v, list) and v]
    if kind == "repeat" and lists:
        path, items = rng.choice(lists)
        times = rng.choice([2, 50, 1000, 6000])
        return _set(doc, path, items * times), f"repeat {path} x{times}"
    if kind == "nest":  # spliced into the text (dumpers recurse): see _text
        depth = rng.choice([5, 40, 5000])
        return _set(doc, path, f"{NEST}{depth}"), f"nest {path} {depth} deep"
    if kind == "key" and isinstance(value, dict):
        value[rng.choice(["x" * 300, "walls", "levels", "colour", "", "steps"])] = rng.choice(
            HOSTILE_NUMBERS + HOSTILE_NAMES
        )
        return doc, f"key added at {path}"
    new = rng.choice(HOSTILE_NUMBERS + HOSTILE_NAMES)
    return _set(doc, path, new), f"swap {path} = {new!r:.30}"


def _text(doc: Any, suffix: str) -> str:
    if suffix == ".json":
        text = json.dumps(doc, allow_nan=True)
    else:
        text = yaml.safe_dump(doc, sort_keys=False, allow_unicode=True, width=1_000_000)
    return re.sub(
        rf"[\"']?{NEST}(\d+)[\"']?", lambda m: "[" * int(m[1]) + "1" + "]" * int(m[1]), text
    )


def _check_world(text: str, what: str) -> None:
    """The SDF is well-formed XML and every number in it is finite."""
    root = ElementTree.fromstring(text)
    assert root.tag == "sdf", what
    for element in root.iter():
        if element.tag in ("pose", "size", "radius", "length", "ambient", "diffuse"):
            numbers = [float(word) for word in (element.text or "").split()]
            assert numbers and all(math.isfinite(n) for n in numbers), f"{what}: {element.tag}"


def _mutants(seed: int, runs: int) -> list[tuple[str, str, bytes]]:
    """(what, suffix, file bytes) for ``runs`` mutants."""
    rng = random.Random(seed)
    mutator = Mutator(seed, TEXT_TOKENS)
    seeds = _seeds()
    mutants = []
    for index in range(runs):
        name, doc = seeds[index % len(seeds)]
        suffix = rng.choice([".yaml", ".json"])
        if rng.random() < 0.7:
            for _ in range(rng.choice([1, 1, 2])):
                doc, what = _mutate_value(doc, rng)
            data = _text(doc, suffix).encode("utf-8", "surrogatepass")
        else:
            data = mutator.mutate(_text(doc, suffix).encode())
            what = "bytes mutated"
        mutants.append((f"mutant {index} of {name} ({what})", suffix, data))
    return mutants


def _build(path: Path, out: Path) -> str:
    plan = load_plan(path)
    files = plan.save(out)
    return files[0].read_text()


def test_mutated_plans_build_a_world_or_give_one_line(tmp_path):
    runs = fuzz_runs(150)
    watch = WriteWatch(tmp_path)
    built = refused = 0
    for index, (what, suffix, data) in enumerate(_mutants(fuzz_seed(28), runs)):
        folder = tmp_path / str(index)
        folder.mkdir()
        path = folder / f"plan{suffix}"
        path.write_bytes(data)
        with bounded(what, HANG_SECONDS):
            try:
                text = _build(path, folder / "out.world")
            except WorkbenchError as error:
                check_one_line(error, what)
                assert len(error.one_line()) < 2000, f"{what}: a message of {len(error.one_line())}"
                refused += 1
                continue
            except Exception as error:  # noqa: BLE001 - the failure names the mutant
                pytest.fail(f"{what}: {type(error).__name__}: {str(error)[:300]}")
        _check_world(text, what)
        with bounded(what, HANG_SECONDS):
            world = load_world(folder / "out.world")  # the simulator reads it as it is
        assert world.models, what
        built += 1
    watch.check()
    assert built and refused, (built, refused)  # the mutants reach both outcomes
    report("world build plans", runs, built=built, refused=refused)


def test_mutated_plans_through_the_command_line(tmp_path):
    mutants = _mutants(fuzz_seed(2828), fuzz_runs(150))[:: max(1, fuzz_runs(150) // 3)][:3]
    for index, (what, suffix, data) in enumerate(mutants):
        path = tmp_path / f"plan{index}{suffix}"
        path.write_bytes(data)
        done = run_cli_checked(["world", "build", str(path), "-o", f"out{index}.world"], tmp_path)
        assert done.returncode in (0, 1), f"{what}: {done.returncode}\n{done.stderr}"
