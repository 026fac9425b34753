"""A model plugin that calls sys.exit in its first update."""

import sys

from workbench.sim.plugins import ModelPlugin


class Quit(ModelPlugin):
    def update(self, info):
        sys.exit(3)
