"""Seeded fuzzing of bags: mutated bytes through bag info, the Python reader and bag play.

Every mutation must give a summary and the readable messages (with BagWarnings naming what
was skipped) or one BagError line; playing it must never wait longer than the time span of
the messages it publishes (a damaged time must not make it wait for years).
"""

from __future__ import annotations

import warnings

from fuzz_helpers import Mutator, WriteWatch, bounded, check_one_line, run_cli_checked

from workbench.bag import BagWarning, BagWriter, format_info, play, read_messages, summarize
from workbench.errors import BagError
from workbench.msgs.geometry_msgs import Twist, Vector3
from workbench.msgs.std_msgs import String

RUNS = 300
T0 = 1638598185.0


def _seed(path, compression):
    with BagWriter(path, compression=compression, chunk_size=400) as bag:
        for i in range(20):
            bag.write("/cmd_vel", Twist(linear=Vector3(x=0.1 * i)), T0 + 0.01 * i)
            bag.write("/chatter", String(data=f"hello {i}"), T0 + 0.01 * i + 0.005)
    return path.read_bytes()


class FakeClock:
    """Wall time that passes only when the player sleeps."""

    def __init__(self) -> None:
        self.t = 0.0

    def now(self) -> float:
        return self.t

    def sleep(self, seconds: float) -> None:
        self.t += max(0.0, seconds)


def _play_within_its_span(path, run):
    clock = FakeClock()
    offsets: list[float] = []
    play(
        path,
        lambda topic, typename, msg: None,
        delay=0.0,
        sleep=clock.sleep,
        now=clock.now,
        progress=lambda bag_time, elapsed: offsets.append(elapsed),
    )
    longest = max(offsets, default=0.0)
    assert clock.t <= longest + 0.02, f"mutation {run}: waited {clock.t} s for {longest} s"


def test_mutated_bags(tmp_path):
    seeds = [_seed(tmp_path / f"seed_{c}.bag", c) for c in ("none", "bz2", "lz4")]
    mutator = Mutator(seed=11)
    watch = WriteWatch(tmp_path)
    read = refused = 0
    for run in range(RUNS):
        path = tmp_path / f"fuzz{run % 5}.bag"
        path.write_bytes(mutator.mutate(seeds[run % 3], rounds=1 + run % 3))
        with bounded(f"bag mutation {run}"), warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                format_info(summarize(path), name=path.name)
                messages = list(read_messages(path))
                assert len(messages) <= 40 + 40  # nothing invented beyond the seed's records
                _play_within_its_span(path, run)
                read += 1
            except BagError as error:
                check_one_line(error, f"bag mutation {run}")
                refused += 1
        for warning in caught:
            assert issubclass(warning.category, BagWarning), f"{run}: {warning.message}"
            assert "\n" not in str(warning.message)
    watch.check()
    assert read > 100 and refused > 5, (read, refused)


def test_mutated_bags_through_the_command_line(tmp_path):
    seed = _seed(tmp_path / "seed.bag", "none")
    mutator = Mutator(seed=1111)
    watch = WriteWatch(tmp_path)
    for run in range(4):
        path = tmp_path / f"cli{run}.bag"
        path.write_bytes(mutator.mutate(seed, rounds=2))
        run_cli_checked(["bag", "info", str(path)], cwd=tmp_path)
        run_cli_checked(["bag", "play", "-d", "0", "-q", str(path)], cwd=tmp_path)
    watch.check()
