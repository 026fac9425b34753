"""The modules of ``benchmarks/`` for tests: the scripts import each other by bare name
(``import mrpt_rawlog``), so their folder goes on ``sys.path`` while they are imported and used.

Importable by name from any test module (``from benchmark_modules import benchmark_modules``).
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from types import ModuleType

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"


@contextmanager
def benchmark_modules(*names: str) -> Iterator[tuple[ModuleType, ...]]:
    """The modules ``benchmarks/<name>.py``, with ``benchmarks/`` on ``sys.path`` meanwhile."""
    sys.path.insert(0, str(BENCHMARKS))
    try:
        yield tuple(importlib.import_module(name) for name in names)
    finally:
        sys.path.remove(str(BENCHMARKS))
