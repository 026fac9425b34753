"""Seeded fuzzing of hostile input: mutations, and the checks every mutated input must pass.

Importable by name from any test folder (``from fuzz_helpers import Mutator``). Each fuzz test
takes a valid input, mutates it a few hundred times with a fixed seed, feeds every mutation to
workbench, and asserts what issue 17 promises for any input:

* no traceback: only a :class:`~workbench.errors.WorkbenchError` (one line) may come out;
* no signal: a command run as a process exits with a status, never killed by a signal;
* no hang: each input finishes within a generous bound (:func:`bounded`), else the test fails
  naming the input (a hang detector, not a performance check);
* no file written outside the test's directory (:class:`WriteWatch`).

A campaign of fresh inputs reruns the same tests outside the suite with other seeds and more
runs: ``WORKBENCH_FUZZ_SEED`` shifts every seed (:func:`fuzz_seed`), ``WORKBENCH_FUZZ_RUNS``
sets the number of mutants per test or ``WORKBENCH_FUZZ_SCALE`` multiplies it (:func:`fuzz_runs`), and ``WORKBENCH_FUZZ_REPORT`` names a
file that :func:`report` appends one JSON line per test to (``benchmarks/fuzz_campaign.py``).
"""

from __future__ import annotations

import contextlib
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: Seconds one input may take before the fuzz test calls it a hang.
HANG_SECONDS = 60

#: Fragments that break parsers in interesting ways, spliced into text inputs.
TEXT_TOKENS = [
    b"&a [*a]",
    b"*a",
    b"[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
    b"{",
    b"]",
    b"!!python/object/apply:os.system ['touch /tmp/pwned']",
    b"\x00",
    b"\xff\xfe",
    b"nan",
    b"-.inf",
    b"1e400",
    b"9" * 5000,
    b"'",
    b'"',
    b"<",
    b"/>",
    b"$(arg x)",
    b"$(find nope)",
    b"$(env NOPE_NOT_SET)",
    b"\n- ",
    b": ",
    b"x" * 70000,
]


def fuzz_seed(default: int) -> int:
    """The seed of a fuzz test: ``default``, shifted by ``WORKBENCH_FUZZ_SEED`` in a campaign."""
    return default + int(os.environ.get("WORKBENCH_FUZZ_SEED", "0")) * 1_000_003


def fuzz_runs(default: int) -> int:
    """The number of mutants a fuzz test makes: ``default``, ``WORKBENCH_FUZZ_RUNS``, or
    ``default`` times ``WORKBENCH_FUZZ_SCALE`` (which keeps slow and fast tests in proportion)."""
    if "WORKBENCH_FUZZ_RUNS" in os.environ:
        return int(os.environ["WORKBENCH_FUZZ_RUNS"])
    return max(1, round(default * float(os.environ.get("WORKBENCH_FUZZ_SCALE", "1"))))


def report(surface: str, runs: int, **outcomes: int) -> None:
    """Append ``{surface, runs, seed, **outcomes}`` to ``WORKBENCH_FUZZ_REPORT`` (if set).

    ``outcomes`` counts how the mutants ended (accepted, refused with one line, ...); a test
    reaches this only when every mutant passed its checks.
    """
    path = os.environ.get("WORKBENCH_FUZZ_REPORT")
    if not path:
        return
    line = {"surface": surface, "runs": runs, "seed": os.environ.get("WORKBENCH_FUZZ_SEED", "0")}
    line.update(outcomes)
    with open(path, "a", encoding="utf-8") as stream:
        stream.write(json.dumps(line) + "\n")


class Mutator:
    """Seeded byte-level mutations of a valid input (flip, cut, splice, repeat, insert).

    Args:
        seed: The random seed (every run of a test makes the same inputs).
        tokens: Fragments to insert; None for none.
    """

    def __init__(self, seed: int, tokens: Sequence[bytes] | None = None) -> None:
        self.rng = random.Random(seed)
        self.tokens = list(tokens or [])

    def mutate(self, data: bytes, rounds: int | None = None) -> bytes:
        """``data`` changed 1-4 times (or ``rounds`` times)."""
        out = bytearray(data)
        for _ in range(rounds or self.rng.randint(1, 4)):
            out = self._once(out)
        return bytes(out)

    def _once(self, out: bytearray) -> bytearray:
        rng = self.rng
        choice = rng.randrange(7 if self.tokens else 6)
        at = rng.randrange(len(out) + 1)
        if choice == 0 and out:  # flip bits of a few bytes
            for _ in range(rng.randint(1, 8)):
                i = rng.randrange(len(out))
                out[i] ^= 1 << rng.randrange(8)
        elif choice == 1:  # cut the rest off
            del out[at:]
        elif choice == 2 and out:  # delete a slice
            del out[at : at + rng.randint(1, 64)]
        elif choice == 3 and out:  # repeat a slice
            end = min(len(out), at + rng.randint(1, 256))
            out[at:at] = out[at:end] * rng.randint(2, 16)
        elif choice == 4:  # random bytes
            out[at:at] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
        elif choice == 5 and out:  # an extreme integer where one was
            i = rng.randrange(max(1, len(out) - 8))
            out[i : i + 4] = rng.choice([b"\xff\xff\xff\xff", b"\x00\x00\x00\x80", b"\0\0\0\0"])
        elif self.tokens:
            out[at:at] = rng.choice(self.tokens)
        return out


class HangError(AssertionError):
    """An input took longer than :data:`HANG_SECONDS`."""


@contextlib.contextmanager
def bounded(what: str, seconds: float = HANG_SECONDS) -> Iterator[None]:
    """Fail with :class:`HangError` naming ``what`` if the block runs past ``seconds``."""

    def expired(signum, frame):
        raise HangError(f"{what} did not finish within {seconds} s (a hang)")

    previous = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _tree(root: Path, skip: Sequence[Path] = ()) -> set[str]:
    found = set()
    try:
        entries = list(os.scandir(root))
    except OSError:
        return found
    for entry in entries:
        if any(Path(entry.path) == s for s in skip):
            continue
        found.add(entry.name)
    return found


class WriteWatch:
    """Records what exists in the checkout and the temp folder; :meth:`check` finds new files.

    Only ``allowed`` (the test's own folder) may gain files. The checkout is compared with
    ``git status --porcelain --ignored`` (so a stray output in any sub-folder shows), the temp
    folder and the home folder by their top-level names.
    """

    def __init__(self, allowed: Path) -> None:
        self.allowed = allowed.resolve()
        self.places = [Path(tempfile.gettempdir()), Path.home(), Path.cwd()]
        self.before = self._snapshot()

    def _git(self) -> set[str]:
        done = subprocess.run(
            ["git", "status", "--porcelain", "--ignored", "--untracked-files=all"],
            cwd=REPO,
            capture_output=True,
            text=True,
            check=False,
        )
        return {
            line
            for line in done.stdout.splitlines()
            # caches of Python and of the developer's tools (ruff, mypy) run beside the tests
            if not any(cache in line for cache in ("__pycache__", ".egg-info", ".pyc", "_cache/"))
        }

    def _snapshot(self) -> dict[str, set[str]]:
        snap = {str(place): _tree(place, [self.allowed]) for place in self.places}
        snap["git"] = self._git()
        return snap

    def check(self) -> None:
        after = self._snapshot()
        for place, names in after.items():
            new = sorted(names - self.before[place])
            # other tests running in parallel make their own pytest/tmp folders, and the
            # launch tests their launches' log folders
            parallel = ("pytest-", "tmp", "pymp-", ".coverage", "workbench-launch-")
            new = [n for n in new if not n.startswith(parallel)]
            assert not new, f"files written outside the test's folder, in {place}: {new[:5]}"


def check_one_line(error: BaseException, what: str) -> None:
    """A WorkbenchError's message is one line (no traceback, no multi-line dump)."""
    from workbench.errors import WorkbenchError

    assert isinstance(error, WorkbenchError), f"{what}: {type(error).__name__}: {error}"
    line = error.one_line()
    assert "\n" not in line and line.strip(), f"{what}: not one line: {line!r}"
    assert "Traceback" not in line, what


def run_cli_checked(
    args: Sequence[str], cwd: Path, env: dict[str, str] | None = None, timeout: float = 120
) -> subprocess.CompletedProcess:
    """Run ``python -m workbench ARGS`` and check it ended by itself, without a traceback.

    Returns:
        The finished process (exit status 0 or a one-line error on stderr).
    """
    full_env = dict(os.environ, WORKBENCH_MASTER_URI="inproc", HOME=str(cwd))
    full_env.pop("WORKBENCH_DEBUG", None)
    full_env.update(env or {})
    try:
        done = subprocess.run(
            [sys.executable, "-m", "workbench", *args],
            cwd=cwd,
            capture_output=True,
            text=True,
            timeout=timeout,
            env=full_env,
        )
    except subprocess.TimeoutExpired:
        raise HangError(f"workbench {' '.join(args)} did not finish within {timeout} s") from None
    assert done.returncode >= 0, f"{args}: killed by signal {-done.returncode}\n{done.stderr}"
    assert "Traceback" not in done.stderr, f"{args}:\n{done.stderr[-3000:]}"
    if done.returncode != 0:
        errors = [line for line in done.stderr.splitlines() if ": error: " in line]
        assert len(errors) == 1, f"{args}: expected one error line:\n{done.stderr[-3000:]}"
    return done
