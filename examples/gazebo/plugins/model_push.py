"""Gazebo's first plugin tutorial ("model push") as a workbench plugin.

Attach it to a model (SDF ``<model>`` or URDF ``<gazebo>`` block)::

    <plugin name="model_push" filename="model_push.py">
      <x>0.3</x>   <!-- optional velocity, m/s, world frame -->
    </plugin>

Before every physics step it sets the model's horizontal velocity, so the
model slides along x at 0.3 m/s whatever friction does. Unlike the tutorial's
``SetLinearVel`` it keeps the vertical velocity unless ``<z>`` is given: zeroing
it every step would stop gravity from holding the model on the ground.
"""

from workbench.sim.plugins import ModelPlugin


class ModelPush(ModelPlugin):
    """Keep the model moving at a constant linear velocity."""

    def load(self, model, sdf, node):
        self.model = model
        self.velocity = [sdf.get("x", 0.3), sdf.get("y", 0.0), sdf.get("z")]

    def update(self, info):
        x, y, z = self.velocity
        if z is None:
            z = self.model.linear_velocity()[2]
        self.model.set_linear_velocity([x, y, z])
