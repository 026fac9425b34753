"""A model plugin that pushes its link with 1e308 N."""

from workbench.sim.plugins import ModelPlugin


class Push(ModelPlugin):
    def load(self, model, sdf, node):
        self.model = model

    def update(self, info):
        self.model.apply_wrench("body", [0.0, 0.0, 1e308])
