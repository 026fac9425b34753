"""Seeded fuzzing of world files, their includes and model folders: a world or one line.

A small world (the ground, a two-link model written inline, physics settings and
two ``<include>``s of a model folder, ``model.config`` and ``model.sdf``, whose model
includes another folder's on a joint) is
mutated: numbers made NaN, infinite, huge, tiny or garbage; names and include URIs
made long, multi-line or path-like; elements deleted, duplicated (up to past the
simulator's bounds) and moved; bytes cut, flipped and spliced. Each mutant is loaded
and built as ``workbench sim`` does and stepped for 20 ms in this process (or until
its physics fails, which pauses the server), within a hang bound; a few run as
``workbench sim --until`` in a fresh process, where a Drake
abort or a segfault would show as a signal. Every mutant must run or be refused with
one :class:`~workbench.errors.WorkbenchError` line, and nothing may be written outside
the test's folder.

A campaign: ``WORKBENCH_FUZZ_SEED=7 WORKBENCH_FUZZ_RUNS=500 WORKBENCH_FUZZ_REPORT=f.jsonl
pytest tests/sim/test_fuzz_worlds.py``.
"""

from __future__ import annotations

import copy
import random
import threading
from pathlib import Path

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
from lxml import etree

from workbench.errors import WorkbenchError

WORLD = """<?xml version="1.0"?>
<sdf version="1.6">
  <world name="fuzz">
    <physics type="ode"><max_step_size>0.001</max_step_size>
      <real_time_factor>1</real_time_factor></physics>
    <gravity>0 0 -9.8</gravity>
    <include><uri>model://ground_plane</uri></include>
    <include><uri>crate</uri><name>crate_a</name><pose>1 0 0.2 0 0 0</pose></include>
    <include><uri>model://crate</uri><name>crate_b</name><pose>-1 0 0.2 0 0 0.5</pose>
      <static>false</static></include>
    <model name="pendulum">
      <pose>0 1 0.5 0 0 0</pose>
      <link name="base">
        <inertial><mass>2</mass><inertia><ixx>0.02</ixx><iyy>0.02</iyy><izz>0.02</izz>
          </inertia></inertial>
        <collision name="base_c"><geometry><cylinder><radius>0.1</radius>
          <length>0.2</length></cylinder></geometry></collision>
        <visual name="base_v"><geometry><sphere><radius>0.1</radius></sphere></geometry></visual>
      </link>
      <link name="arm">
        <pose>0 0 0.3 0 0 0</pose>
        <inertial><mass>0.5</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.001</izz>
          </inertia></inertial>
        <collision name="arm_c"><geometry><box><size>0.05 0.05 0.3</size></box></geometry>
        </collision>
      </link>
      <joint name="hinge" type="revolute">
        <parent>base</parent><child>arm</child>
        <axis><xyz>1 0 0</xyz><limit><lower>-1</lower><upper>1</upper><effort>5</effort>
          <velocity>2</velocity></limit><dynamics><damping>0.1</damping></dynamics></axis>
      </joint>
    </model>
    <model name="wall">
      <static>true</static>
      <link name="link"><collision name="c"><geometry><plane><normal>1 0 0</normal>
        <size>2 2</size></plane></geometry></collision></link>
    </model>
  </world>
</sdf>
"""

CRATE_CONFIG = """<?xml version="1.0"?>
<model><name>crate</name><version>1.0</version><sdf version="1.6">model.sdf</sdf></model>
"""

CRATE = """<?xml version="1.0"?>
<sdf version="1.6">
  <model name="crate">
    <pose>0 0 0.1 0 0 0</pose>
    <link name="body">
      <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz>
        </inertia></inertial>
      <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry>
        <surface><friction><ode><mu>0.8</mu></ode></friction></surface></collision>
      <visual name="v"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></visual>
    </link>
    <include><uri>model://wheel</uri><name>wheel</name><pose>0.15 0 0 1.5708 0 0</pose>
    </include>
    <joint name="axle" type="revolute"><parent>body</parent><child>wheel::link</child>
      <axis><xyz>0 0 1</xyz></axis></joint>
  </model>
</sdf>
"""

WHEEL_CONFIG = """<?xml version="1.0"?>
<model><name>wheel</name><sdf version="1.6">model.sdf</sdf></model>
"""

WHEEL = """<?xml version="1.0"?>
<sdf version="1.6">
  <model name="wheel">
    <link name="link">
      <inertial><mass>0.2</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz>
        </inertia></inertial>
      <collision name="c"><geometry><cylinder><radius>0.05</radius><length>0.02</length>
        </cylinder></geometry></collision>
    </link>
  </model>
</sdf>
"""

FILES = {"fuzz.world": WORLD, "crate/model.config": CRATE_CONFIG, "crate/model.sdf": CRATE}
FILES |= {"wheel/model.config": WHEEL_CONFIG, "wheel/model.sdf": WHEEL}

NUMBERS = ["nan", "inf", "-inf", "1e308", "-1e308", "1e-300", "0", "-1", "1e400", "abc"]
NUMBERS += ["", "1 2", "0 0 0", "0 0 0 0 0 0", "9" * 400, "1e6", "1000001"]
NAMES = ["x" * 45_000, "n" * 5_000, "a\nb", "", "::", "<b>", "../../escaped", "a b", "ü" * 300]
URIS = ["model://" + "n" * 5_000, "model://../..", "/etc/passwd", "/dev/zero", "model://nope"]
URIS += ["crate/model.sdf", "file:///etc/hostname", "model://ground_plane", "", "n" * 300]
NUMERIC = {"pose", "size", "radius", "length", "mass", "ixx", "iyy", "izz", "lower", "upper"}
NUMERIC |= {"effort", "velocity", "damping", "mu", "normal", "max_step_size", "gravity", "xyz"}
NUMERIC |= {"real_time_factor"}

#: Mutants per run, and how many of them also run as a process.
RUNS, PROCESS_RUNS = 100, 3


def _mutate_tree(root, rng: random.Random) -> str:
    elements = [e for e in root.iter() if isinstance(e.tag, str)]
    kind = rng.choice(["number"] * 4 + ["name", "uri", "delete", "duplicate", "move", "text"])
    if kind == "number":
        targets = [e for e in elements if e.tag in NUMERIC] or elements
        target = rng.choice(targets)
        target.text = rng.choice(NUMBERS)
        return f"<{target.tag}> = {target.text[:20]!r}"
    if kind == "name":
        target = rng.choice(
            [e for e in elements if "name" in e.attrib or e.tag == "name"] or [root]
        )
        value = rng.choice(NAMES)
        if target.tag == "name":
            target.text = value
        else:
            target.set("name", value)
        return f"<{target.tag}> name {value[:20]!r} ({len(value)} characters)"
    if kind == "uri":
        uris = [e for e in elements if e.tag in ("uri", "sdf")]
        if uris:
            target = rng.choice(uris)
            target.text = rng.choice(URIS)
            return f"<{target.tag}> {target.text[:30]!r}"
    element = rng.choice([e for e in elements if e is not root] or elements)
    if kind == "delete" and element is not root:
        element.getparent().remove(element)
        return f"deleted <{element.tag}>"
    if kind == "duplicate" and element is not root:
        count = rng.choice([1, 3, 50, 250, 600])
        for _ in range(count):
            element.addnext(copy.deepcopy(element))
        return f"<{element.tag}> duplicated {count} times"
    if kind == "move" and element is not root:
        target = rng.choice(elements)
        if target is not element and element not in target.iterancestors():
            element.getparent().remove(element)
            target.append(element)
            return f"<{element.tag}> moved into <{target.tag}>"
    if len(element) == 0:
        element.text = rng.choice(NUMBERS + NAMES[3:])
        return f"<{element.tag}> text {element.text[:20]!r}"
    element.set("fuzz", "1")
    return f"<{element.tag}> extra attribute"


def _mutant(folder: Path, rng: random.Random, mutator: Mutator) -> str:
    """Write the world folder into ``folder`` with one of its files mutated."""
    for name, text in FILES.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text)
    name = rng.choice(["fuzz.world", "fuzz.world", *FILES])
    path = folder / name
    if rng.random() < 0.2:
        path.write_bytes(mutator.mutate(path.read_bytes()))
        return f"{name}: bytes mutated"
    root = etree.fromstring(path.read_bytes())
    done = [_mutate_tree(root, rng) for _ in range(rng.choice([1, 1, 2, 3]))]
    path.write_bytes(etree.tostring(root, xml_declaration=True, encoding="utf-8"))
    return f"{name}: " + "; ".join(done)


def _simulate(world: Path, what: str) -> str:
    """Load, build and step ``world`` as ``workbench sim`` does; how it ended."""
    from workbench.sim.gzserver import ServerOptions, build_server

    try:
        _, server, _ = build_server(ServerOptions(world=str(world), view=False, fast=True))
    except WorkbenchError as error:
        check_one_line(error, what)
        return "refused"
    failed = threading.Event()
    # a failed physics step pauses the server (Gazebo's way); for this test that is an end
    server.hooks.append(lambda s: failed.set() if s.error is not None else None)
    try:
        server.run(until=0.02, stop=failed)
    finally:
        server.stop()
    return "stopped" if server.error is not None else "ran"


def test_mutated_worlds_and_model_folders_run_or_give_one_line(tmp_path, monkeypatch):
    seed = fuzz_seed(28)
    runs = fuzz_runs(RUNS)
    rng = random.Random(seed)
    mutator = Mutator(seed, TEXT_TOKENS)
    watch = WriteWatch(tmp_path)
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("WORKBENCH_DEBUG", raising=False)
    outcomes = {"ran": 0, "stopped": 0, "refused": 0}
    processes = set(rng.sample(range(runs), min(PROCESS_RUNS, runs)))
    for run in range(runs):
        folder = tmp_path / f"run{run}"
        folder.mkdir()
        monkeypatch.setenv("GAZEBO_MODEL_PATH", str(folder))
        what = _mutant(folder, rng, mutator)
        label = f"mutant {run} (seed {seed}): {what}"
        with bounded(label):
            outcome = _simulate(folder / "fuzz.world", label)
        outcomes[outcome] += 1
        if run in processes and outcome != "stopped":  # a paused server runs on, as Gazebo
            done = run_cli_checked(
                ["sim", "fuzz.world", "--until", "0.02", "--headless", "--fast"],
                cwd=folder,
                env={"GAZEBO_MODEL_PATH": str(folder)},
            )
            assert done.returncode in (0, 1), f"{label}: {done.stderr[-2000:]}"
    watch.check()
    assert outcomes["ran"] > 0 and outcomes["refused"] > 0, outcomes
    report("worlds", runs, **outcomes)
