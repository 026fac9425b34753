"""Seeded fuzzing of ``.rviz`` configs: a loaded config or a one-line ViewerError, nothing else.

The shipped configs are mutated at the byte level and with RViz-shaped fragments spliced
in (groups, aliases, huge counts, odd numbers, tools); each mutant is read with
``load_config`` within the hang bound, and each display of a config that loads is made
from its options (what ``workbench rviz`` then adds to the viewer). A few go through
``workbench rviz --check`` in a subprocess as well.
"""

from __future__ import annotations

import math
import random
from pathlib import Path

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
from workbench.rviz.config import MAX_DISPLAYS, load_config
from workbench.rviz.rviz import DISPLAY_CLASSES

REPO = Path(__file__).resolve().parents[2]
SEEDS = [
    REPO / "examples" / "rviz" / "lab.rviz",
    REPO
    / "examples"
    / "packages"
    / "turtlebot3_navigation"
    / "rviz"
    / "turtlebot3_navigation.rviz",
    REPO / "examples" / "packages" / "turtlebot3_slam" / "rviz" / "turtlebot3_gmapping.rviz",
]

RVIZ_TOKENS = [
    *TEXT_TOKENS,
    b"\n    - Class: rviz/Group\n      Name: G\n      Displays:\n        - Class: rviz/Grid\n",
    b"\n    - &g {Class: rviz/Group, Name: loop, Displays: [*g]}\n",
    b"\n    - {Class: rviz/Group, Displays: [{Class: rviz/Group, Displays: [{Class: rviz/TF}]}]}\n",
    b"Plane Cell Count: 100000000",
    b"Plane Cell Count: -3",
    b"Plane Cell Count: 2.5",
    b"Cell Size: 0",
    b"Cell Size: .inf",
    b"Alpha: .nan",
    b"Alpha: [1, 2]",
    b"Marker Scale: 1e400",
    b"Length: -.inf",
    b"Arrow Length: {a: 1}",
    b"Color: nan; 0; 0",
    b"Color: 1; 2",
    b"Color Scheme: rainbow",
    b"Topic: ''",
    b"Topic: bad topic name!",
    b"Topic: [a, b]",
    b"Class: rviz/Map",
    b"Class: rviz/Grid",
    b"Class: rviz/PoseArray",
    b"Class: rviz/Polygon",
    b"Class: 42",
    b"Name: " + b"n" * 5000,
    b"X std deviation: -1",
    b"Theta std deviation: .nan",
    b"Tools:\n    - Class: rviz/SetGoal\n      Topic: [x]\n",
    b"Displays: [" + b"{Class: rviz/Marker}, " * 50 + b"]",
    b"Visualization Manager: ~\n",
    b"Global Options: [1]\n",
    b"Fixed Frame: {a: b}\n",
    b"\xef\xbb\xbf",
]


#: Keys of displays and tools whose values the value mutations replace.
KEYS = [
    "Class", "Name", "Enabled", "Topic", "Marker Topic", "Update Topic", "Robot Description",
    "Plane Cell Count", "Cell Size", "Alpha", "Color", "Color Scheme", "Marker Scale",
    "Length", "Arrow Length", "Reference Frame", "Displays", "X std deviation",
    "Theta std deviation",
]  # fmt: skip
#: What they are replaced with.
VALUES = [
    math.nan, math.inf, -math.inf, -1, 0, 1, 2.5, 1e8, 10**30, 1000, 1001, "x", "", "1e8",
    None, True, [1, 2], {"a": 1}, "n" * 5000, "rviz/Grid", "rviz/Group", "rviz/Map",
    "rviz/PoseArray", "costmap", "nan; 1; 2", "255; 255; 255", [{"Class": "rviz/Group"}],
]  # fmt: skip


def _value_mutant(data: bytes, rng: random.Random) -> bytes:
    """The config of ``data`` with display and tool values replaced, displays repeated or
    wrapped in groups (what byte mutations seldom reach: valid YAML with odd values)."""
    config = yaml.load(data, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))  # noqa: S506
    manager = config["Visualization Manager"]
    displays = manager["Displays"]
    for _ in range(rng.randint(1, 4)):
        choice = rng.randrange(5)
        if choice == 0 and manager.get("Tools"):
            tool = rng.choice(manager["Tools"])
            tool[rng.choice(KEYS)] = rng.choice(VALUES)
        elif choice == 1:
            displays.extend(displays * rng.choice((1, 3, 40)))
        elif choice == 2:
            group = {"Class": "rviz/Group", "Name": "G", "Displays": displays}
            for _ in range(rng.choice((1, 5, 15, 17, 40))):
                group = {"Class": "rviz/Group", "Name": "G", "Displays": [group]}
            manager["Displays"] = displays = [group]
        else:
            display = rng.choice(displays)
            display[rng.choice(KEYS)] = rng.choice(VALUES)
    dumper = getattr(yaml, "CSafeDumper", yaml.SafeDumper)
    return yaml.dump(config, Dumper=dumper, width=1000).encode()


def _load(path: Path) -> int:
    """Read ``path`` and make its displays; the number of displays."""
    config = load_config(path)
    assert len(config.displays) <= MAX_DISPLAYS
    for spec in config.displays:
        DISPLAY_CLASSES[spec.class_name](**spec.options)
    return len(config.displays)


def test_mutated_rviz_configs(tmp_path):
    seed = fuzz_seed(6)
    runs = fuzz_runs(300)
    mutator = Mutator(seed=seed, tokens=RVIZ_TOKENS)
    seeds = [path.read_bytes() for path in SEEDS]
    watch = WriteWatch(tmp_path)
    loaded = refused = 0
    rng = random.Random(seed)
    for run in range(runs):
        path = tmp_path / f"fuzz{run % 3}.rviz"
        data = seeds[run % len(seeds)]
        if run % 2:
            path.write_bytes(_value_mutant(data, rng))
        else:
            path.write_bytes(mutator.mutate(data, rounds=1 + run % 4))
        with bounded(f".rviz mutant {run} (seed {seed})"):
            try:
                _load(path)
                loaded += 1
            except WorkbenchError as error:
                check_one_line(error, f".rviz mutant {run} (seed {seed})")
                assert str(path) in error.one_line(), error.one_line()
                refused += 1
            except Exception as error:  # what the test is for: a traceback
                raise AssertionError(
                    f".rviz mutant {run} (seed {seed}): {type(error).__name__}: {error}"
                ) from error
    watch.check()
    assert loaded > runs // 20 and refused > runs // 20, (loaded, refused)
    report(".rviz configs", runs, loaded=loaded, refused=refused)


def test_mutated_rviz_configs_through_the_command_line(tmp_path):
    seed = fuzz_seed(66)
    runs = fuzz_runs(4)
    mutator = Mutator(seed=seed, tokens=RVIZ_TOKENS)
    original = SEEDS[0].read_bytes()
    watch = WriteWatch(tmp_path)
    for run in range(runs):
        path = tmp_path / f"cli{run}.rviz"
        path.write_bytes(mutator.mutate(original))
        run_cli_checked(["rviz", "--check", "-d", str(path)], cwd=tmp_path)
    watch.check()
    report(".rviz configs (workbench rviz --check)", runs)
