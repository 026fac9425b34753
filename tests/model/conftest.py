"""Fixtures shared by the model tests."""

from __future__ import annotations

import pytest
from urdfdom_tools import Tools


@pytest.fixture
def ros_tools(require_program) -> Tools:
    """Debian's urdfdom tools (liburdfdom-tools), or skip (fail under WORKBENCH_REQUIRE_ALL=1)."""
    return Tools(require_program("check_urdf"), require_program("urdf_to_graphviz"))
