"""Seeded fuzzing of launch files (XML and YAML): a plan or a one-line LaunchError, nothing else."""

from __future__ import annotations

import shutil

from fuzz_helpers import TEXT_TOKENS, Mutator, WriteWatch, bounded, check_one_line, run_cli_checked

from workbench.bus.launch import LaunchError, load_launch
from workbench.errors import WorkbenchError
from workbench.model.launch_eval import evaluate_launch_expression

RUNS = 300

LAUNCH_TOKENS = [
    *TEXT_TOKENS,
    b'<include file="fuzz0.launch"/>',
    b'<include file="inner.yaml"/>',
    b'<arg name="x" default="$(arg x)$(arg x)"/>',
    b' respawn_delay="-1" ',
    b' args="\'" ',
    b'<param name="t" textfile="/dev/zero"/>',
    b"<group ns=''>",
    b"</group>",
    b"&#0;",
    b"<!DOCTYPE launch [<!ENTITY e SYSTEM 'file:///etc/passwd'>]>",
    b"include: [{}]\n",
    b"nodes: [1]\n",
    b"remap: [a]\n",
    b'<arg name="e" default="$(eval 9 ** 9 ** 9)"/>',
    b'<param name="v" value="$(eval [x for x in range(10**6) for y in range(10**6)])"/>',
    b' pass_all_args="true" ',
    b' clear_params="true" ',
    b'<machine name="m" address="elsewhere"/>',
    b"<rosparam>{a: !radians pi/2, b: deg(90)}</rosparam>",
    b'<env name="E" value="$(optenv HOME)"/>',
    b'<test test-name="t" pkg="p" type="t"/>',
]


def _refuse(command, path):
    raise LaunchError(f"the fuzz test runs no command ({command!r})")


def test_mutated_launch_files(tmp_path, data_dir):
    for name in ("features.launch", "inner.yaml", "costmap.yaml", "start_demo.launch"):
        shutil.copy(data_dir / "bus" / name, tmp_path / name)
    seeds = [
        ((data_dir / "bus" / name).read_bytes(), suffix, args)
        for name, suffix, args in (
            ("features.launch", ".launch", {"robot": "r1"}),
            ("start_demo.launch", ".launch", {}),
            ("inner.yaml", ".yaml", {"who": "me"}),
        )
    ]
    mutator = Mutator(seed=15, tokens=LAUNCH_TOKENS)
    watch = WriteWatch(tmp_path)
    planned = refused = 0
    for run in range(RUNS):
        data, suffix, args = seeds[run % len(seeds)]
        path = tmp_path / f"fuzz{run % 3}{suffix}"
        path.write_bytes(mutator.mutate(data, rounds=1 + run % 3))
        with bounded(f"launch file mutation {run}"):
            try:
                load_launch(
                    path,
                    args,
                    dry_run=run % 2 == 0,
                    command_runner=_refuse,
                    evaluate=evaluate_launch_expression,
                )
                planned += 1
            except WorkbenchError as error:
                check_one_line(error, f"mutation {run} of {path.name}")
                refused += 1
    watch.check()
    assert planned > 10 and refused > 10, (planned, refused)


def test_mutated_launch_files_through_the_command_line(tmp_path, data_dir):
    for name in ("inner.yaml", "costmap.yaml"):
        shutil.copy(data_dir / "bus" / name, tmp_path / name)
    seed = (data_dir / "bus" / "features.launch").read_bytes()
    mutator = Mutator(seed=1515, tokens=LAUNCH_TOKENS)
    watch = WriteWatch(tmp_path)
    for run in range(6):
        path = tmp_path / f"cli{run}.launch"
        path.write_bytes(mutator.mutate(seed))
        run_cli_checked(["launch", "--dry-run", str(path)], cwd=tmp_path)
    watch.check()
