"""Write the hostile laser logs of this folder (deterministic; run from anywhere).

``python tests/data/hostile/logs/make_logs.py`` rewrites the two small bags (LaserScan and
Odometry, 20 scans) whose odometry or beam angles are not finite; the CARMEN logs here are
plain text, edited by hand.
"""

from __future__ import annotations

import math
from pathlib import Path

HERE = Path(__file__).resolve().parent


def write(path: Path, bad: str) -> None:
    from workbench.bag import BagWriter
    from workbench.msgs.nav_msgs import Odometry
    from workbench.msgs.sensor_msgs import LaserScan

    with BagWriter(path) as bag:
        for i in range(20):
            t = 100.0 + i * 0.2
            odom = Odometry()
            odom.header.frame_id, odom.child_frame_id = "odom", "base_link"
            odom.header.stamp.secs, odom.header.stamp.nsecs = int(t), round((t % 1) * 1e9)
            odom.pose.pose.position.x = float("nan") if bad == "odom" and i == 10 else 0.05 * i
            odom.pose.pose.orientation.w = 1.0
            bag.write("/odom", odom, t)
            scan = LaserScan()
            scan.header.stamp = odom.header.stamp
            scan.header.frame_id = "base_link"
            scan.angle_min = -math.pi / 2
            scan.angle_increment = float("nan") if bad == "angles" else math.pi / 90
            scan.range_max = 10.0
            scan.ranges = [2.0 + 0.5 * math.sin(k / 10) for k in range(91)]
            bag.write("/scan", scan, t + 0.01)


if __name__ == "__main__":
    write(HERE / "odometry_nan.bag", "odom")
    write(HERE / "angles_nan.bag", "angles")
    print("wrote odometry_nan.bag, angles_nan.bag")
