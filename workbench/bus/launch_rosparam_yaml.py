"""The YAML of ``<rosparam>`` and ``type="yaml"``: rosparam's angle tags on top of safe YAML.

ROS's ``rosparam`` adds two tags, and roslaunch reads rosparam YAML with them:

* ``!degrees 180`` and the plain scalar ``deg(180)``: the number times pi/180;
* ``!radians pi/2`` and the plain scalar ``rad(pi/2)``: an arithmetic expression in
  radians (``pi`` is pi). rosparam evaluates it with Python's ``eval``; here a plain
  number is read directly and anything else goes to workbench's expression sandbox (the
  one ``$(eval)`` uses), so ``!radians __import__('os')`` computes nothing.
"""

from __future__ import annotations

import math
import re
from typing import Any

from workbench.bus.launch_subst import ExpressionEvaluator
from workbench.errors import WorkbenchError
from workbench.limits import load_yaml

_DEGREES = re.compile(r"^deg\([^\)]*\)$")
_RADIANS = re.compile(r"^rad\([^\)]*\)$")


def _degrees(text: str) -> float:
    if text.startswith("deg("):
        text = text.strip()[4:-1]
    try:
        return float(text) * math.pi / 180.0
    except ValueError:
        raise ValueError(f"invalid degree value: {text}") from None


def _radians(text: str, evaluate: ExpressionEvaluator | None) -> float:
    text = text.strip()
    if text.startswith("rad("):
        text = text[4:-1]
    try:
        return float(text)
    except ValueError:
        pass
    if evaluate is None:
        raise ValueError(f"!radians {text} needs workbench's expression sandbox")
    if "__" in text:
        raise ValueError(f"invalid radian expression: {text}")
    try:
        return float(evaluate(text, {}, {}))
    except WorkbenchError as error:
        raise ValueError(f"invalid radian expression {text}: {error.message}") from None
    except (ArithmeticError, LookupError, NameError, TypeError, ValueError) as error:
        raise ValueError(f"invalid radian expression {text}: {error}") from None


def rosparam_loader(evaluate: ExpressionEvaluator | None) -> Any:
    """A safe YAML loader class with rosparam's ``!degrees`` and ``!radians``."""
    import yaml

    base = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

    def construct(convert: Any) -> Any:
        def constructor(loader: Any, node: Any) -> float:
            try:
                return convert(loader.construct_scalar(node))
            except ValueError as error:
                raise yaml.constructor.ConstructorError(
                    None, None, str(error), node.start_mark
                ) from None

        return constructor

    class RosparamLoader(base):  # type: ignore[misc, valid-type]
        pass

    RosparamLoader.add_constructor("!degrees", construct(_degrees))
    RosparamLoader.add_constructor("!radians", construct(lambda t: _radians(t, evaluate)))
    RosparamLoader.add_implicit_resolver("!degrees", _DEGREES, list("deg("))
    RosparamLoader.add_implicit_resolver("!radians", _RADIANS, list("rad("))
    return RosparamLoader


def load_rosparam_yaml(
    text: str,
    what: str,
    error: type[WorkbenchError],
    evaluate: ExpressionEvaluator | None,
    path: str | None = None,
) -> Any:
    """``text`` as rosparam YAML, within :mod:`workbench.limits`' YAML bounds.

    Raises:
        error: Invalid YAML, a bad angle, or a bound passed (with the line).
    """
    return load_yaml(text, what, error=error, path=path, loader=rosparam_loader(evaluate))
