"""Fixtures of the mapping tests (a module's own fixture of the same name takes precedence)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from gmapping_feed import STARTED
from laser_robot import sim_time_bus

from workbench.bus import Bus


@pytest.fixture
def bus() -> Iterator[Bus]:
    """An in-process bus on simulated time; the mappers started on it are closed after."""
    yield from sim_time_bus(STARTED)
