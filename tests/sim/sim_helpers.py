"""Small models for the simulator tests, written straight as SimModels (no Gazebo tags)."""

from __future__ import annotations

from workbench.sim.model_spec import PluginSpec, SimModel


def box_model(
    name: str,
    size: float | tuple[float, float, float] = 0.1,
    mass: float = 0.5,
    plugins: list[PluginSpec] | None = None,
    static: bool = False,
) -> SimModel:
    """A box of edges ``size`` (m; a number for a cube) and ``mass`` (kg), frame at its centre."""
    x, y, z = (size, size, size) if isinstance(size, (int, float)) else size
    ixx, iyy, izz = (mass * (b * b + c * c) / 12.0 for b, c in ((y, z), (x, z), (x, y)))
    text = f"""<robot name="{name}"><link name="body">
  <inertial><mass value="{mass}"/>
    <inertia ixx="{ixx}" iyy="{iyy}" izz="{izz}" ixy="0" ixz="0" iyz="0"/></inertial>
  <visual><geometry><box size="{x} {y} {z}"/></geometry></visual>
  <collision><geometry><box size="{x} {y} {z}"/></geometry></collision>
</link></robot>"""
    return SimModel(
        name=name,
        format="urdf",
        text=text,
        root_link="body",
        plugins=list(plugins or []),
        static=static,
        source=f"test box {name}",
    )


def spinner_model(name: str) -> SimModel:
    """A heavy base with a disc on a continuous joint about z."""
    text = f"""<robot name="{name}">
  <link name="base">
    <inertial><origin xyz="0 0 0.05"/><mass value="5"/>
      <inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.05"/><geometry><box size="0.3 0.3 0.1"/></geometry></collision>
    <visual><origin xyz="0 0 0.05"/><geometry><box size="0.3 0.3 0.1"/></geometry></visual>
  </link>
  <link name="disc">
    <inertial><mass value="0.2"/>
      <inertia ixx="0.0002" iyy="0.0002" izz="0.0004" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><cylinder radius="0.06" length="0.02"/></geometry></visual>
  </link>
  <joint name="spin" type="continuous">
    <parent link="base"/><child link="disc"/>
    <origin xyz="0 0 0.15"/><axis xyz="0 0 1"/>
  </joint>
</robot>"""
    return SimModel(name=name, format="urdf", text=text, root_link="base", source="test spinner")


def plugin_spec(
    path: str, name: str = "test_plugin", body: str = "", kind: str = "model"
) -> PluginSpec:
    """A PluginSpec for the Python file ``path`` with parameter elements ``body``."""
    return PluginSpec(
        name=name,
        filename=path,
        element=f'<plugin name="{name}" filename="{path}">{body}</plugin>',
        kind=kind,
        source="test",
    )
