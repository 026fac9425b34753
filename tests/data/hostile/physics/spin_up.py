"""A model plugin that twists its light link with 1e6 N m, within the bounds, until it fails."""

from workbench.sim.plugins import ModelPlugin


class SpinUp(ModelPlugin):
    def load(self, model, sdf, node):
        self.model = model

    def update(self, info):
        self.model.apply_wrench("body", [0.0, 0.0, 0.0], [1e6, -1e6, 1e6])
