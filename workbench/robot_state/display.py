"""The robot drawn from tf (RViz's RobotModel display): each link posed by a tf lookup."""

from __future__ import annotations

from typing import Any

from workbench.tf.buffer import Buffer
from workbench.tf.exceptions import TransformException
from workbench.viz.frames import rigid_transform


class RobotModelDisplay:
    """Draws ``robot`` in the viewer and moves each link to where tf says it is.

    Args:
        robot: A loaded :class:`workbench.model.Robot`.
        buffer: A buffer filled with the robot's frames (robot_state_publisher's output).
        viewer: A :class:`workbench.viz.Viewer`; default the process-wide one.
        fixed_frame: The frame the scene is drawn in; default the robot's root link.
        tf_prefix: The prefix robot_state_publisher put on the frame names, if any.
    """

    def __init__(
        self,
        robot: Any,
        buffer: Buffer,
        viewer: Any = None,
        fixed_frame: str | None = None,
        tf_prefix: str = "",
    ) -> None:
        if viewer is None:
            from workbench.viz import Viewer

            viewer = Viewer.instance()
        self.robot = robot
        self.buffer = buffer
        self.viewer = viewer
        self.tf_prefix = tf_prefix.strip("/")
        self.fixed_frame = fixed_frame or self._frame(robot.root_link)
        self.prefix = viewer.show_robot(robot)

    def _frame(self, link: str) -> str:
        return f"{self.tf_prefix}/{link}" if self.tf_prefix else link

    def update(self) -> dict[str, str]:
        """Move every link to its latest tf pose; returns links that could not be placed, and why."""
        problems: dict[str, str] = {}
        for link in self.robot.links:
            try:
                with self.buffer._lock:
                    st = self.buffer.lookup(self.fixed_frame, self._frame(link.name), 0)
            except TransformException as exc:
                problems[link.name] = str(exc)
                continue
            self.viewer.meshcat.SetTransform(
                f"{self.prefix}/{link.name}", rigid_transform(st.translation, st.rotation)
            )
        return problems
