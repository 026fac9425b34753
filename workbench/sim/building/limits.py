"""Bounds on a building plan: far above any building of the lab, low enough to build in seconds.

A plan file is input like any other: it is read within the YAML bounds of
:mod:`workbench.limits` (a JSON plan within the same depth), and what it asks
for is counted before any geometry is made. The numbers are in the README's
"Limits on input".
"""

from __future__ import annotations

from workbench.limits import MAX_TEXT_FILE_BYTES, TreeLimits

#: Depth, elements and text of a plan file once parsed (a plan is about 8 levels deep).
PLAN_TREE_LIMITS = TreeLimits(max_depth=32, max_nodes=1_000_000, max_bytes=MAX_TEXT_FILE_BYTES)
#: Most walls in a plan (a chain of points counts one wall per segment), all levels together.
MAX_PLAN_WALLS = 5_000
#: Most doors and windows in a plan.
MAX_PLAN_OPENINGS = 10_000
#: Most levels, flights of stairs, and steps in one flight.
MAX_PLAN_LEVELS = 100
MAX_PLAN_STAIRS = 100
MAX_STEPS = 1_000
#: Most pieces of furniture.
MAX_PLAN_ITEMS = 10_000
#: Largest magnitude of a length, coordinate, elevation or angle in a plan (m or degrees).
MAX_PLAN_NUMBER = 100_000.0
#: Smallest size (thickness, height, width, radius) of a plan's piece, m: the world file
#: writes lengths to the micrometre, and a smaller one would come out as 0.
MIN_PLAN_SIZE = 0.001
