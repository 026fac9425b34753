"""Motion planning: setup (SRDF, planning.yaml), goals, collision checking, planners, timing.

Import the submodules you need; this package itself imports nothing heavy::

    from workbench.planning.srdf import read_srdf
    from workbench.planning.config import load_config
    from workbench.planning.setup import run_setup
"""

from __future__ import annotations
