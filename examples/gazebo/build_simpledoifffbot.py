"""Experiment 6, steps 23-27: the two-wheeled robot with a depth camera and the follower plugin.

Run ``python examples/gazebo/build_simpledoifffbot.py [OUT.sdf]`` (default:
``simpledoifffbot.sdf`` here); ``urdf/simpledoifffbot.sdf`` is this script's
output, so ``model://simpledoifffbot`` and ``workbench sim --spawn simpledoifffbot``
find it. The robot of steps 3-22 comes from ``build_two_wheeled_robot.py``.
"""

import runpy
import sys
from pathlib import Path

from workbench.model import ModelBuilder

#: Gazebo's model database "Depth camera" (model://depth_camera): a 0.1 m cube of
#: 0.1 kg carrying a depth sensor, 60 degrees wide, 320 x 240, 0.1-100 m, 30 Hz.
DEPTH_CAMERA_SIZE = 0.1
DEPTH_CAMERA_MASS = 0.1
DEPTH_CAMERA_IMAGE = (320, 240)
DEPTH_CAMERA_RATE = 30.0


def add_depth_camera(
    robot: ModelBuilder,
    parent: str,
    *,
    image: tuple[int, int] = DEPTH_CAMERA_IMAGE,
    update_rate: float = DEPTH_CAMERA_RATE,
) -> ModelBuilder:
    """Steps 23-25: the database's depth camera on top of ``parent``'s front, on a fixed joint."""
    width, height = image
    robot.add_link("depth_camera", mass=DEPTH_CAMERA_MASS)
    robot.add_box("depth_camera", (DEPTH_CAMERA_SIZE,) * 3, color=(0.3, 0.3, 0.3))
    robot.add_sensor(
        "depth_camera",
        "camera",
        "depth",
        update_rate=update_rate,
        always_on=True,
        visualize=True,
        camera={
            "horizontal_fov": 1.047,
            "image": {"width": width, "height": height},
            "clip": {"near": 0.1, "far": 100},
        },
    )
    # 24: moved by hand onto the chassis, at its front, centred across it
    robot.align("depth_camera", parent, x="max", y="center", z="max", reverse="z")
    # 25: a fixed joint, the chassis its parent
    return robot.add_joint("depth_camera_joint", "fixed", parent, "depth_camera")


def build(
    image: tuple[int, int] = DEPTH_CAMERA_IMAGE,
    update_rate: float = DEPTH_CAMERA_RATE,
    **follower: str,
) -> ModelBuilder:
    """The manual's "simpledoifffbot" (a smaller ``image`` makes a faster test model;
    ``follower``: the plugin's parameters, none in the manual)."""
    script = Path(__file__).with_name("build_two_wheeled_robot.py")
    robot: ModelBuilder = runpy.run_path(str(script))["build"]()
    robot.name = "simpledoifffbot"  # 27: saved under the manual's name
    add_depth_camera(robot, "chassis", image=image, update_rate=update_rate)
    # 26: the model plugin; it needs no parameters
    robot.add_plugin("follower", "libFollowerPlugin.so", **follower)
    return robot


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "simpledoifffbot.sdf"
    print(f"wrote {build().save(out)}")
