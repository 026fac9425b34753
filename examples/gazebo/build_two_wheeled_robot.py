"""Experiment 6: the manual's two-wheeled robot, built step by step with ModelBuilder.

Run ``python examples/gazebo/build_two_wheeled_robot.py [OUT.sdf]`` (default:
``two_wheeled_robot.sdf`` here); ``urdf/two_wheeled_robot.sdf`` is this script's
output. Each step is the model editor's step of the same number in the manual.
"""

import sys

from workbench.model import ModelBuilder

BASE_COLOR = (0.2, 0.4, 0.8)
WHEEL_COLOR = (0.1, 0.1, 0.1)


def build() -> ModelBuilder:
    robot = ModelBuilder("two_wheeled_robot")
    # 3-8: a box, its pose z = 0.4 m, visual and collision 2 m x 1 m x 0.15 m
    robot.add_link("chassis", pose=(0, 0, 0.4, 0, 0, 0), mass=20.0)
    robot.add_box("chassis", (2.0, 1.0, 0.15), color=BASE_COLOR)
    # 9-19: two cylinders rolled 90 degrees about x (radius 0.3 m, length 0.25 m),
    # on revolute joints about their own z, aligned x = max, y = max/min (reversed), z = center
    for wheel, side in (("wheel_1", "max"), ("wheel_2", "min")):
        robot.add_link(wheel, pose=(0, 0, 0.4, 1.5707963267948966, 0, 0), mass=2.0)
        robot.add_cylinder(wheel, radius=0.3, length=0.25, color=WHEEL_COLOR)
        robot.align(wheel, "chassis", x="max", y=side, z="center", reverse="y")
        robot.add_joint(f"{wheel}_joint", "continuous", "chassis", wheel, axis="z", frame="child")
    # 20-22: a sphere of radius 0.2 m on a ball joint, aligned x = min, y = center, z = max
    robot.add_link("caster", pose=(0, 0, 0.4, 0, 0, 0), mass=1.0)
    robot.add_sphere("caster", radius=0.2, color=(0.7, 0.7, 0.7))
    robot.align("caster", "chassis", x="min", y="center", z="max")
    robot.add_joint("caster_joint", "ball", "chassis", "caster")
    return robot


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "two_wheeled_robot.sdf"
    print(f"wrote {build().save(out)}")
