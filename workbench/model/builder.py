"""Build a model step by step, as Gazebo's model editor does, and write it as SDF or URDF.

Example (the manual's two-wheeled robot, Experiment 6)::

    from workbench.model import ModelBuilder

    robot = ModelBuilder("simple_bot")
    robot.add_link("base", pose=(0, 0, 0.4, 0, 0, 0), mass=20.0)
    robot.add_box("base", (2.0, 1.0, 0.15))
    for wheel, side in (("wheel_1", "max"), ("wheel_2", "min")):
        robot.add_link(wheel, pose=(0, 0, 0, 1.5707963, 0, 0), mass=2.0)
        robot.add_cylinder(wheel, radius=0.3, length=0.25)
        robot.align(wheel, "base", x="max", y=side, z="center", reverse="y")
        robot.add_joint(f"{wheel}_joint", "revolute", "base", wheel, axis="z", frame="child")
    robot.save("simple_bot.sdf")

Poses are ``(x, y, z, roll, pitch, yaw)`` in the model frame (m, rad), like the
link inspector's pose fields; shapes are posed in their link's frame. A link's
inertia is computed from its collision shapes (uniform density over their
volumes) unless given. ``align`` moves a link like the editor's Align tool:
per axis, the child's ``min``/``center``/``max`` of its bounding box goes to
the parent's, and ``reverse`` puts it on the other side (the child's min at the
parent's max, or the reverse), i.e. beside the parent.

``add_sensor`` puts a ``<sensor>`` on a link (a depth camera, a laser...), in the
link for SDF and in a ``<gazebo reference>`` block for URDF; ``add_plugin`` adds a
model plugin, e.g. Gazebo's follower (``examples/gazebo/build_simpledoifffbot.py``).

URDF has no ball joint: ``to_urdf`` writes a ball joint as a fixed joint and
makes that link's contact frictionless (``mu1 = mu2 = 0`` in a ``<gazebo>``
block), the usual way a URDF robot carries a ball caster.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

import numpy as np

from workbench.errors import ModelError
from workbench.model.sensor_element import SensorElement

Pose = tuple[float, float, float, float, float, float]
_JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "ball")
_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}


@dataclass
class _Shape:
    kind: str  # box, cylinder, sphere
    size: tuple[float, ...]
    pose: Pose
    color: tuple[float, float, float, float] | None
    visual: bool
    collision: bool
    name: str

    def volume(self) -> float:
        if self.kind == "box":
            return float(np.prod(self.size))
        if self.kind == "cylinder":
            return math.pi * self.size[0] ** 2 * self.size[1]
        return 4.0 / 3.0 * math.pi * self.size[0] ** 3

    def central_inertia(self, mass: float) -> np.ndarray:
        """About the shape's centre, in its own frame, kg m^2."""
        if self.kind == "box":
            x, y, z = self.size
            return np.diag([y * y + z * z, x * x + z * z, x * x + y * y]) * mass / 12.0
        if self.kind == "cylinder":
            r, h = self.size
            side = mass * (3 * r * r + h * h) / 12.0
            return np.diag([side, side, mass * r * r / 2.0])
        return np.eye(3) * (2.0 / 5.0) * mass * self.size[0] ** 2

    def half_extents(self) -> np.ndarray:
        if self.kind == "box":
            return np.array(self.size) / 2.0
        if self.kind == "cylinder":
            return np.array([self.size[0], self.size[0], self.size[1] / 2.0])
        return np.full(3, self.size[0])


@dataclass
class _Link:
    name: str
    pose: Pose
    mass: float | None
    inertia: tuple[float, float, float, float, float, float] | None
    shapes: list[_Shape] = field(default_factory=list)
    sensors: list[SensorElement] = field(default_factory=list)


@dataclass
class _Joint:
    name: str
    kind: str
    parent: str
    child: str
    axis: tuple[float, float, float]
    lower: float | None
    upper: float | None
    effort: float | None
    velocity: float | None
    damping: float


class ModelBuilder:
    """A model assembled from links, shapes, joints and plugins.

    Args:
        name: The model's name.
        static: A static model (welded where it is placed).
    """

    def __init__(self, name: str, *, static: bool = False) -> None:
        _check_name(name, "model")
        self.name = name
        self.static = static
        self._links: dict[str, _Link] = {}
        self._joints: dict[str, _Joint] = {}
        self._plugins: list[tuple[str, str, dict[str, Any]]] = []

    # --- links and shapes ------------------------------------------------------------

    def add_link(
        self,
        name: str,
        *,
        pose: Pose | tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        mass: float | None = 1.0,
        inertia: tuple[float, float, float, float, float, float] | None = None,
    ) -> ModelBuilder:
        """A link at ``pose`` in the model frame; ``mass`` kg (None: massless, for fixed parts).

        ``inertia`` is ``(ixx, iyy, izz, ixy, ixz, iyz)`` about the centre of mass in
        the link frame; None computes it from the collision shapes.
        """
        from workbench.model.limits import MAX_LINKS

        _check_name(name, "link")
        if len(self._links) >= MAX_LINKS:
            raise ModelError(
                f"model '{self.name}' has {MAX_LINKS:,} links already; workbench loads at most "
                f"{MAX_LINKS:,}",
                hint="see 'Limits on input' in the README",
            )
        if name in self._links:
            raise ModelError(f"link '{name}' already exists in model '{self.name}'")
        if mass is not None and not (math.isfinite(mass) and mass > 0):
            raise ModelError(f"link '{name}': mass must be a positive number, got {mass}")
        if inertia is not None and (len(inertia) != 6 or not np.all(np.isfinite(inertia))):
            raise ModelError(f"link '{name}': inertia must be 6 finite numbers")
        self._links[name] = _Link(name, _pose(pose, f"link '{name}'"), mass, inertia)
        return self

    def add_box(
        self,
        link: str,
        size: tuple[float, float, float],
        *,
        pose: Pose | tuple[float, ...] = (0.0,) * 6,
        color: tuple[float, ...] | None = None,
        visual: bool = True,
        collision: bool = True,
    ) -> ModelBuilder:
        """A box of edges ``size`` (x, y, z; m) to ``link``, as visual and/or collision."""
        return self._add_shape(link, "box", tuple(size), pose, color, visual, collision, 3)

    def add_cylinder(
        self,
        link: str,
        radius: float,
        length: float,
        *,
        pose: Pose | tuple[float, ...] = (0.0,) * 6,
        color: tuple[float, ...] | None = None,
        visual: bool = True,
        collision: bool = True,
    ) -> ModelBuilder:
        """A cylinder (axis along its z) of ``radius`` and ``length`` (m) to ``link``."""
        return self._add_shape(
            link, "cylinder", (radius, length), pose, color, visual, collision, 2
        )

    def add_sphere(
        self,
        link: str,
        radius: float,
        *,
        pose: Pose | tuple[float, ...] = (0.0,) * 6,
        color: tuple[float, ...] | None = None,
        visual: bool = True,
        collision: bool = True,
    ) -> ModelBuilder:
        """A sphere of ``radius`` (m) to ``link``."""
        return self._add_shape(link, "sphere", (radius,), pose, color, visual, collision, 1)

    def _add_shape(
        self,
        link: str,
        kind: str,
        size: tuple[float, ...],
        pose: Any,
        color: Any,
        visual: bool,
        collision: bool,
        count: int,
    ) -> ModelBuilder:
        target = self._link(link)
        from workbench.model.limits import MAX_SHAPE_SIZE

        if len(size) != count or not all(
            math.isfinite(s) and 0 < s <= MAX_SHAPE_SIZE for s in size
        ):
            raise ModelError(
                f"link '{link}': {kind} sizes must be {count} positive numbers of at most "
                f"{MAX_SHAPE_SIZE:g} m, got {size}"
            )
        if not (visual or collision):
            raise ModelError(f"link '{link}': a {kind} must be a visual, a collision or both")
        rgba = None
        if color is not None:
            rgba = tuple(float(c) for c in color)
            if len(rgba) == 3:
                rgba = (*rgba, 1.0)
            if len(rgba) != 4 or not all(0.0 <= c <= 1.0 for c in rgba):
                raise ModelError(f"link '{link}': color must be (r, g, b[, a]) in [0, 1]")
        name = f"{kind}_{len(target.shapes)}"
        target.shapes.append(
            _Shape(kind, size, _pose(pose, f"{kind} of '{link}'"), rgba, visual, collision, name)  # type: ignore[arg-type]
        )
        return self

    def add_wheel(
        self,
        name: str,
        parent: str,
        *,
        radius: float,
        width: float,
        xyz: tuple[float, float, float],
        mass: float = 1.0,
        color: tuple[float, ...] | None = None,
    ) -> ModelBuilder:
        """A cylinder rolled 90 degrees about x (axis along y) at ``xyz``, on a continuous joint."""
        self.add_link(name, pose=(*xyz, math.pi / 2, 0.0, 0.0), mass=mass)
        self.add_cylinder(name, radius, width, color=color)
        return self.add_joint(f"{name}_joint", "continuous", parent, name, axis="z", frame="child")

    def add_caster(
        self,
        name: str,
        parent: str,
        *,
        radius: float,
        xyz: tuple[float, float, float],
        mass: float = 0.5,
        color: tuple[float, ...] | None = None,
    ) -> ModelBuilder:
        """A sphere at ``xyz`` on a ball joint (a ball caster)."""
        self.add_link(name, pose=(*xyz, 0.0, 0.0, 0.0), mass=mass)
        self.add_sphere(name, radius, color=color)
        return self.add_joint(f"{name}_joint", "ball", parent, name)

    # --- joints, alignment, plugins --------------------------------------------------

    def add_joint(
        self,
        name: str,
        kind: str,
        parent: str,
        child: str,
        *,
        axis: str | tuple[float, float, float] = "z",
        frame: str = "model",
        limits: tuple[float, float] | None = None,
        effort: float | None = None,
        velocity: float | None = None,
        damping: float = 0.0,
    ) -> ModelBuilder:
        """A joint between two links, at the child link's origin.

        Args:
            kind: revolute, continuous, prismatic, fixed or ball.
            axis: ``"x"``, ``"y"``, ``"z"`` or a vector, in ``frame``.
            frame: ``"model"`` or ``"child"`` (the child link's frame, as the editor's
                "Joint axis" field).
            limits: ``(lower, upper)`` in rad or m (revolute, prismatic).
            damping: Viscous damping, N m s/rad or N s/m.
        """
        _check_name(name, "joint")
        if name in self._joints:
            raise ModelError(f"joint '{name}' already exists in model '{self.name}'")
        if kind not in _JOINT_TYPES:
            raise ModelError(
                f"joint '{name}': unknown type '{kind}' (one of {', '.join(_JOINT_TYPES)})"
            )
        for role, link in (("parent", parent), ("child", child)):
            if link not in self._links:
                raise ModelError(
                    f"joint '{name}': {role} link '{link}' does not exist",
                    hint="add it with add_link first",
                )
        if parent == child:
            raise ModelError(f"joint '{name}': a link cannot be its own parent")
        if any(j.child == child for j in self._joints.values()):
            raise ModelError(f"joint '{name}': link '{child}' already has a parent joint")
        vector = np.array(_AXES[axis] if isinstance(axis, str) and axis in _AXES else axis, float)
        if vector.shape != (3,) or not np.all(np.isfinite(vector)) or np.linalg.norm(vector) < 1e-9:
            raise ModelError(f"joint '{name}': axis must be x, y, z or a non-zero 3-vector")
        vector /= np.linalg.norm(vector)
        if frame == "child":
            vector = _rotation(self._links[child].pose) @ vector
        elif frame != "model":
            raise ModelError(f"joint '{name}': frame must be 'model' or 'child'")
        lower, upper = limits if limits is not None else (None, None)
        if kind == "revolute" and limits is None:
            lower, upper = -math.pi, math.pi
        if lower is not None and upper is not None and not lower <= upper:
            raise ModelError(
                f"joint '{name}': lower limit {lower:g} is above upper limit {upper:g}"
            )
        if not (math.isfinite(damping) and damping >= 0):
            raise ModelError(f"joint '{name}': damping must be >= 0")
        for label, value in (("effort", effort), ("velocity", velocity)):
            if value is not None and not (math.isfinite(value) and value >= 0):
                raise ModelError(
                    f"joint '{name}': {label} limit must be a finite number >= 0, got {value}"
                )
        if any(v is not None and not math.isfinite(v) for v in (lower, upper)):
            raise ModelError(f"joint '{name}': limits must be finite numbers, got {limits}")
        self._joints[name] = _Joint(
            name,
            kind,
            parent,
            child,
            tuple(vector),
            lower,
            upper,
            effort,
            velocity,
            float(damping),
        )
        return self

    def align(
        self,
        child: str,
        parent: str,
        *,
        x: str | None = None,
        y: str | None = None,
        z: str | None = None,
        reverse: str = "",
    ) -> ModelBuilder:
        """Move ``child`` so its bounding box lines up with ``parent``'s (the Align tool).

        Args:
            x, y, z: ``"min"``, ``"center"`` or ``"max"`` per axis of the model frame (None:
                leave that axis).
            reverse: Axes (e.g. ``"y"``) where the child goes beside the parent
                instead: its min at the parent's max, or its max at the parent's min.
        """
        lo_c, hi_c = self._bounds(child)
        lo_p, hi_p = self._bounds(parent)
        pose = list(self._links[child].pose)
        for index, (axis, mode) in enumerate((("x", x), ("y", y), ("z", z))):
            if mode is None:
                continue
            if mode not in ("min", "center", "max"):
                raise ModelError(f"align {child}: {axis} must be min, center or max, got '{mode}'")
            if mode == "center":
                shift = (lo_p[index] + hi_p[index]) / 2 - (lo_c[index] + hi_c[index]) / 2
            elif axis in reverse:
                shift = hi_p[index] - lo_c[index] if mode == "max" else lo_p[index] - hi_c[index]
            else:
                shift = hi_p[index] - hi_c[index] if mode == "max" else lo_p[index] - lo_c[index]
            pose[index] += shift
        self._links[child].pose = tuple(pose)  # type: ignore[assignment]
        return self

    def add_sensor(
        self,
        link: str,
        name: str,
        kind: str,
        *,
        pose: Pose | tuple[float, ...] = (0.0,) * 6,
        update_rate: float = 0.0,
        always_on: bool = False,
        visualize: bool = False,
        **settings: Any,
    ) -> ModelBuilder:
        """A ``<sensor name type>`` on ``link`` at ``pose`` in the link frame.

        ``settings`` are the type's elements as nested dicts, e.g. for a depth camera
        ``camera={"horizontal_fov": 1.047, "image": {"width": 320, "height": 240}}``
        (see :mod:`workbench.model.sensor_element`).
        """
        _check_name(name, "sensor")
        target = self._link(link)
        if any(s.name == name for s in target.sensors):
            raise ModelError(f"link '{link}' already has a sensor '{name}'")
        target.sensors.append(
            SensorElement(
                name,
                kind,
                _pose(pose, f"sensor '{name}'"),
                float(update_rate),
                bool(always_on),
                bool(visualize),
                settings,
            )
        )
        return self

    def add_plugin(self, name: str, filename: str, **parameters: Any) -> ModelBuilder:
        """A model plugin element: ``<plugin name filename><key>value</key>...``."""
        _check_name(name, "plugin")
        if not filename:
            raise ModelError(f"plugin '{name}': filename is empty")
        self._plugins.append((name, filename, dict(parameters)))
        return self

    # --- queries ---------------------------------------------------------------------

    @property
    def links(self) -> list[str]:
        return list(self._links)

    @property
    def joints(self) -> list[str]:
        return list(self._joints)

    def link_pose(self, name: str) -> Pose:
        """A link's pose in the model frame."""
        return self._link(name).pose

    def inertial(self, name: str) -> tuple[float, np.ndarray, np.ndarray]:
        """``(mass, centre of mass in the link frame, 3x3 inertia about it)`` of a link."""
        link = self._link(name)
        mass = link.mass or 0.0
        if link.inertia is not None:
            ixx, iyy, izz, ixy, ixz, iyz = link.inertia
            return mass, np.zeros(3), np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        solids = [s for s in link.shapes if s.collision] or link.shapes
        if not solids or mass <= 0:
            return mass, np.zeros(3), np.eye(3) * 1e-6 * max(mass, 1e-3)
        volumes = np.array([s.volume() for s in solids])
        masses = mass * volumes / volumes.sum()
        centres = np.array([s.pose[:3] for s in solids])
        com = (masses[:, None] * centres).sum(axis=0) / mass
        inertia = np.zeros((3, 3))
        for shape, m, c in zip(solids, masses, centres, strict=True):
            R = _rotation(shape.pose)
            d = c - com
            inertia += R @ shape.central_inertia(m) @ R.T + m * (d @ d * np.eye(3) - np.outer(d, d))
        return mass, com, inertia

    def _link(self, name: str) -> _Link:
        if name not in self._links:
            raise ModelError(
                f"model '{self.name}' has no link '{name}'",
                hint="links: " + (", ".join(self._links) or "none"),
            )
        return self._links[name]

    def _bounds(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        link = self._link(name)
        if not link.shapes:
            raise ModelError(f"align: link '{name}' has no shapes to align")
        R_ML, p_ML = _rotation(link.pose), np.array(link.pose[:3])
        corners = []
        for shape in link.shapes:
            R, p = R_ML @ _rotation(shape.pose), p_ML + R_ML @ np.array(shape.pose[:3])
            half = shape.half_extents()
            for signs in np.array(np.meshgrid([-1, 1], [-1, 1], [-1, 1])).T.reshape(-1, 3):
                corners.append(p + R @ (signs * half))
        points = np.array(corners)
        return points.min(axis=0), points.max(axis=0)

    def _check(self) -> None:
        self._root()

    def _root(self) -> str:
        if not self._links:
            raise ModelError(f"model '{self.name}' has no links")
        children = {j.child for j in self._joints.values()}
        roots = [name for name in self._links if name not in children]
        if len(roots) != 1:
            raise ModelError(
                f"model '{self.name}' must have one root link, has {len(roots)}: {', '.join(roots)}",
                hint="connect every other link with a joint",
            )
        return roots[0]

    # --- output ----------------------------------------------------------------------

    def to_sdf(self) -> str:
        """The model as SDF 1.7 text."""
        self._check()
        out = [
            '<?xml version="1.0"?>',
            '<sdf version="1.7">',
            f"  <model name={quoteattr(self.name)}>",
        ]
        if self.static:
            out.append("    <static>true</static>")
        for link in self._links.values():
            out.append(f"    <link name={quoteattr(link.name)}>")
            out.append(f"      <pose>{_fmt(link.pose)}</pose>")
            if link.mass is not None:
                mass, com, inertia = self.inertial(link.name)
                out += [
                    "      <inertial>",
                    f"        <pose>{_fmt((*com, 0, 0, 0))}</pose>",
                    f"        <mass>{mass:.6g}</mass>",
                    "        <inertia>"
                    + "".join(f"<{k}>{v}</{k}>" for k, v in _inertia_entries(inertia))
                    + "</inertia>",
                    "      </inertial>",
                ]
            for shape in link.shapes:
                geometry = _sdf_geometry(shape)
                if shape.collision:
                    out += [
                        f'      <collision name="{shape.name}_collision">',
                        f"        <pose>{_fmt(shape.pose)}</pose>",
                        f"        <geometry>{geometry}</geometry>",
                        "      </collision>",
                    ]
                if shape.visual:
                    out += [
                        f'      <visual name="{shape.name}_visual">',
                        f"        <pose>{_fmt(shape.pose)}</pose>",
                        f"        <geometry>{geometry}</geometry>",
                    ]
                    if shape.color is not None:
                        rgba = " ".join(f"{c:g}" for c in shape.color)
                        out.append(
                            f"        <material><ambient>{rgba}</ambient><diffuse>{rgba}</diffuse></material>"
                        )
                    out.append("      </visual>")
            for sensor in link.sensors:
                out += sensor.lines(6)
            out.append("    </link>")
        for joint in self._joints.values():
            out.append(f'    <joint name={quoteattr(joint.name)} type="{_sdf_joint_type(joint)}">')
            out.append(f"      <parent>{joint.parent}</parent>")
            out.append(f"      <child>{joint.child}</child>")
            if joint.kind not in ("fixed", "ball"):
                axis = _rotation(self._links[joint.child].pose).T @ np.array(joint.axis)
                out.append("      <axis>")
                out.append(f"        <xyz>{_fmt(axis)}</xyz>")
                if joint.lower is not None and joint.upper is not None:
                    out.append(
                        f"        <limit><lower>{joint.lower:.6g}</lower><upper>{joint.upper:.6g}</upper>"
                        + (f"<effort>{joint.effort:g}</effort>" if joint.effort is not None else "")
                        + (
                            f"<velocity>{joint.velocity:g}</velocity>"
                            if joint.velocity is not None
                            else ""
                        )
                        + "</limit>"
                    )
                if joint.damping:
                    out.append(f"        <dynamics><damping>{joint.damping:g}</damping></dynamics>")
                out.append("      </axis>")
            out.append("    </joint>")
        for name, filename, parameters in self._plugins:
            out.append(f"    <plugin name={quoteattr(name)} filename={quoteattr(filename)}>")
            out += [f"      <{key}>{_value(value)}</{key}>" for key, value in parameters.items()]
            out.append("    </plugin>")
        out += ["  </model>", "</sdf>", ""]
        return "\n".join(out)

    def to_urdf(self) -> str:
        """The model as URDF text (ball joints become fixed, frictionless casters)."""
        self._check()
        out = ['<?xml version="1.0"?>', f"<robot name={quoteattr(self.name)}>"]
        frictionless = []
        # URDF has no link poses: the root link's frame is the model frame, so the
        # root's own pose moves into its shapes and inertial.
        root = self._root()
        for link in self._links.values():
            X_FL = _matrix(link.pose) if link.name == root else np.eye(4)
            out.append(f"  <link name={quoteattr(link.name)}>")
            if link.mass is not None:
                mass, com, inertia = self.inertial(link.name)
                com = X_FL[:3, :3] @ com + X_FL[:3, 3]
                inertia = X_FL[:3, :3] @ inertia @ X_FL[:3, :3].T
                out += [
                    "    <inertial>",
                    f'      <origin xyz="{_fmt(com)}"/>',
                    f'      <mass value="{mass:.6g}"/>',
                    "      <inertia "
                    + " ".join(f'{k}="{v}"' for k, v in _inertia_entries(inertia))
                    + "/>",
                    "    </inertial>",
                ]
            for shape in link.shapes:
                X = X_FL @ _matrix(shape.pose)
                origin = f'<origin xyz="{_fmt(X[:3, 3])}" rpy="{_fmt(_rpy(X[:3, :3]))}"/>'
                geometry = _urdf_geometry(shape)
                if shape.visual:
                    out.append(f"    <visual>{origin}<geometry>{geometry}</geometry>")
                    if shape.color is not None:
                        rgba = " ".join(f"{c:g}" for c in shape.color)
                        out.append(
                            f'      <material name="{link.name}_{shape.name}"><color rgba="{rgba}"/></material>'
                        )
                    out.append("    </visual>")
                if shape.collision:
                    out.append(
                        f"    <collision>{origin}<geometry>{geometry}</geometry></collision>"
                    )
            out.append("  </link>")
        for joint in self._joints.values():
            parent, child = self._links[joint.parent], self._links[joint.child]
            X_MP = np.eye(4) if parent.name == root else _matrix(parent.pose)
            X = np.linalg.inv(X_MP) @ _matrix(child.pose)
            xyz, rpy = X[:3, 3], _rpy(X[:3, :3])
            kind = "fixed" if joint.kind == "ball" else joint.kind
            if joint.kind == "ball":
                frictionless.append(joint.child)
            out.append(f'  <joint name={quoteattr(joint.name)} type="{kind}">')
            out.append(f"    <parent link={quoteattr(joint.parent)}/>")
            out.append(f"    <child link={quoteattr(joint.child)}/>")
            out.append(f'    <origin xyz="{_fmt(xyz)}" rpy="{_fmt(rpy)}"/>')
            if kind not in ("fixed",):
                axis = _rotation(child.pose).T @ np.array(joint.axis)
                out.append(f'    <axis xyz="{_fmt(axis)}"/>')
            if kind in ("revolute", "prismatic"):
                effort = joint.effort if joint.effort is not None else 1000.0
                velocity = joint.velocity if joint.velocity is not None else 100.0
                out.append(
                    f'    <limit lower="{joint.lower:.6g}" upper="{joint.upper:.6g}" '
                    f'effort="{effort:g}" velocity="{velocity:g}"/>'
                )
            if joint.damping:
                out.append(f'    <dynamics damping="{joint.damping:g}"/>')
            out.append("  </joint>")
        for link in self._links.values():
            X_FL = _matrix(link.pose) if link.name == root else np.eye(4)
            for sensor in link.sensors:
                X = X_FL @ _matrix(sensor.pose)
                out.append(f"  <gazebo reference={quoteattr(link.name)}>")
                out += sensor.lines(4, pose=(*X[:3, 3], *_rpy(X[:3, :3])))
                out.append("  </gazebo>")
        for caster in frictionless:
            out.append(f"  <gazebo reference={quoteattr(caster)}><mu1>0</mu1><mu2>0</mu2></gazebo>")
        if self.static:
            out.append("  <gazebo><static>true</static></gazebo>")
        for name, filename, parameters in self._plugins:
            out.append("  <gazebo>")
            out.append(f"    <plugin name={quoteattr(name)} filename={quoteattr(filename)}>")
            out += [f"      <{key}>{_value(value)}</{key}>" for key, value in parameters.items()]
            out.append("    </plugin>")
            out.append("  </gazebo>")
        out += ["</robot>", ""]
        return "\n".join(out)

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write ``.sdf`` or ``.urdf`` (by the suffix) and return the path."""
        target = Path(path)
        if target.suffix == ".sdf":
            text = self.to_sdf()
        elif target.suffix == ".urdf":
            text = self.to_urdf()
        else:
            raise ModelError(f"cannot tell the format of '{target}'", hint="name it .sdf or .urdf")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
        return target


_IJ = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def _inertia_entries(inertia: np.ndarray) -> list[tuple[str, str]]:
    """``(ixx, value) ... (iyz, value)`` as both formats write them."""
    names = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
    return [(k, _number(inertia[i, j])) for k, (i, j) in zip(names, _IJ, strict=True)]


def _check_name(name: str, what: str) -> None:
    from workbench.model.limits import name_problem, shown_name

    if not isinstance(name, str) or not name or any(c in name for c in "<>&\"' \t\n/"):
        shown = repr(shown_name(name)) if isinstance(name, str) else repr(name)
        raise ModelError(f"{what} name {shown} is empty or has characters XML names cannot hold")
    problem = name_problem(name)
    if problem is not None:
        raise ModelError(f"{what} name '{shown_name(name)}' {problem}")


def _pose(pose: Any, what: str) -> Pose:
    values = tuple(float(v) for v in pose)
    if len(values) == 3:
        values = (*values, 0.0, 0.0, 0.0)
    if len(values) != 6 or not all(math.isfinite(v) for v in values):
        raise ModelError(f"{what}: pose must be (x, y, z[, roll, pitch, yaw]) finite numbers")
    return values


def _rotation(pose: Any) -> np.ndarray:
    roll, pitch, yaw = pose[3:6]
    cr, sr, cp, sp, cy, sy = (
        math.cos(roll),
        math.sin(roll),
        math.cos(pitch),
        math.sin(pitch),
        math.cos(yaw),
        math.sin(yaw),
    )
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def _matrix(pose: Any) -> np.ndarray:
    X = np.eye(4)
    X[:3, :3] = _rotation(pose)
    X[:3, 3] = pose[:3]
    return X


def _rpy(R: np.ndarray) -> np.ndarray:
    pitch = math.asin(max(-1.0, min(1.0, -R[2, 0])))
    if abs(R[2, 0]) < 1 - 1e-9:
        roll, yaw = math.atan2(R[2, 1], R[2, 2]), math.atan2(R[1, 0], R[0, 0])
    else:
        roll, yaw = math.atan2(-R[1, 2], R[1, 1]), 0.0
    return np.array([roll, pitch, yaw])


def _fmt(values: Any) -> str:
    return " ".join(f"{0.0 if abs(v) < 1e-12 else float(v):.9g}" for v in values)


def _number(value: float) -> str:
    """A value for an inertia entry: 6 significant digits, round-off below 1e-12 as 0."""
    return "0" if abs(value) < 1e-12 else f"{value:.6g}"


def _value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    text = str(value)
    if any(c in text for c in "<>&"):
        raise ModelError(f"plugin parameter value {text!r} has characters XML text cannot hold")
    return text


def _sdf_geometry(shape: _Shape) -> str:
    if shape.kind == "box":
        return f"<box><size>{_fmt(shape.size)}</size></box>"
    if shape.kind == "cylinder":
        return f"<cylinder><radius>{shape.size[0]:g}</radius><length>{shape.size[1]:g}</length></cylinder>"
    return f"<sphere><radius>{shape.size[0]:g}</radius></sphere>"


def _urdf_geometry(shape: _Shape) -> str:
    if shape.kind == "box":
        return f'<box size="{_fmt(shape.size)}"/>'
    if shape.kind == "cylinder":
        return f'<cylinder radius="{shape.size[0]:g}" length="{shape.size[1]:g}"/>'
    return f'<sphere radius="{shape.size[0]:g}"/>'


def _sdf_joint_type(joint: _Joint) -> str:
    # SDF has no "continuous": a revolute joint without limits is one.
    return "revolute" if joint.kind == "continuous" else joint.kind
