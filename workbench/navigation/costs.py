"""costmap_2d's cell costs, shared by costmaps, planners and displays.

The values of ``costmap_2d/cost_values.h`` (Noetic): a cost is one byte; 255 is
unknown, 254 lethal (an obstacle in the cell), 253 inscribed (the robot's centre
here puts an obstacle inside its footprint), 0 free; 1..252 are inflated costs.
"""

from __future__ import annotations

NO_INFORMATION = 255
LETHAL_OBSTACLE = 254
INSCRIBED_INFLATED_OBSTACLE = 253
FREE_SPACE = 0
