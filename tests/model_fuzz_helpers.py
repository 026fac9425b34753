"""What the seeded fuzz tests share: hostile values, a hang guard, and the file-write check.

A fuzz test mutates real inputs with a seeded ``random.Random`` and feeds each
mutant to workbench in-process. Every mutant must end in a result or a
:class:`~workbench.errors.WorkbenchError`: any other exception is a failure naming
the mutant, a hang past :data:`HANG_SECONDS` is turned into one by
:func:`hang_guard`, and a crash (a signal) takes the test run down with it. No
mutant may write a file outside the test's folder (:func:`outside_writes`).
"""

from __future__ import annotations

import contextlib
import signal
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

from model_hostile_corpus import REPO, snapshot

#: A mutant still running after this long is a hang (the bounds stop hostile input within
#: seconds; this is a guard against a lost bound, not a measurement).
HANG_SECONDS = 120

#: Numbers and words that broke readers before: NaN, infinities, zero, negatives, huge.
HOSTILE_NUMBERS = ["nan", "inf", "-inf", "NaN", "0", "-0", "-1", "1e308", "-1e308", "1e-320"]
HOSTILE_NUMBERS += ["9" * 400, "", " ", "abc", "1 2", "1,2,3", "0x10", "1e", "+", "1_000"]
#: Names that broke names: long, with quotes, line breaks, path pieces, markup.
HOSTILE_NAMES = ["x" * 300, "y" * 50000, 'x" shape=none image="/etc/passwd', "a\nb", "a\tb"]
HOSTILE_NAMES += [
    "../../escaped",
    "/abs/name",
    "",
    " ",
    "::",
    "a::b",
    "<b>",
    "ünïcødé",
    "\\",
    "a\\",
]
#: xacro expressions that reached Python, read files, or never ended.
HOSTILE_EXPRESSIONS = [
    "${9**9**9}",
    "${'a'*10**9}",
    "${python.vars(python.type(xacro.load_yaml))['__globals__']}",
    "${xacro.load_yaml('/etc/passwd')}",
    "$(env HOME)",
    "$(eval __import__('os'))",
    "${(lambda f: f(f))(lambda f: f(f))}",
    "${[x for x in python.range(10**6) for y in python.range(10**6)]}",
    "${(lambda L: [L.append((q.gi_frame.f_back.f_back.f_back.f_globals['os']"
    ".system('touch {sentinel}') for q in L)), python.list(L[0])][1])([])}",
    "${1/0}",
    "${undefined_name}",
    "${math.factorial(10**7)}",
    "${'%0999999999d' % 1}",
    "${" + "(" * 300 + "1" + ")" * 300 + "}",
    "${1" + "+1" * 20000 + "}",
]


class Hang(Exception):
    """A mutant ran past :data:`HANG_SECONDS`."""


@contextlib.contextmanager
def hang_guard(what: str, seconds: int = HANG_SECONDS) -> Iterator[None]:
    """Raise :class:`Hang` naming ``what`` if the block runs longer than ``seconds``."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def expire(signum, frame):
        raise Hang(f"no result after {seconds} s: {what}")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def run_workbench(
    args: list[str], cwd: Path, what: str, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess:
    """``python -m workbench ARGS`` in a fresh process; asserts it ended cleanly.

    Cleanly: exit status 0 or 1 (no signal, no guard's 70), no traceback, no guard line.
    """
    result = subprocess.run(
        [sys.executable, "-m", "workbench", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=600,
        env=env,
    )
    assert result.returncode in (0, 1), (what, result.returncode, result.stderr[-1000:])
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr, what
    return result


def watched() -> tuple[Path, ...]:
    """The folders of the checkout no input may write into."""
    return (REPO / "urdf", REPO / "planning", REPO / "tests" / "data", REPO / "examples")


def outside_writes(before: dict, sentinels: list[Path]) -> list[str]:
    """Files that changed in :func:`watched` since ``before``, and sentinels that appeared."""
    changed = [path for path, info in snapshot(watched()).items() if before.get(path) != info]
    changed += [path for path in before if not Path(path).exists()]
    return changed + [str(path) for path in sentinels if path.exists()]
