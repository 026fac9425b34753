"""Drawing in the browser: one Meshcat viewer per process, snapshots, PNG rendering.

Importing this package is cheap; pydrake is imported when a viewer starts.
"""

from __future__ import annotations

from workbench.viz.viewer import Viewer

__all__ = ["Viewer"]
