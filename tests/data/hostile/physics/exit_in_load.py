"""A model plugin that calls sys.exit while loading."""

import sys

from workbench.sim.plugins import ModelPlugin


class Leave(ModelPlugin):
    def load(self, model, sdf, node):
        sys.exit("bye")
