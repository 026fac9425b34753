"""``tf.transformations`` for the lab's scripts: ``from workbench.compat.tf.transformations import ...``."""

from workbench.tf.transformations import *  # noqa: F403
from workbench.tf.transformations import __all__  # noqa: F401
