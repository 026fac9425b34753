"""roslaunch's ``$(eval ...)`` in the sandbox xacro's ``${...}`` runs in.

roslaunch evaluates ``$(eval EXPR)`` with Python's ``eval``: its names are the launch
file's arguments, ``arg()``, ``find()``, ``env()``, ``optenv()``, ``anon()``,
``dirname()``, ``true``/``false``, everything in :mod:`math` and (through ``eval``'s
defaults) Python's builtins. Here the same expression goes through
:func:`workbench.model.xacro_eval.evaluate`: the launch functions and math become guarded
functions, the builtins are the harmless ones xacro's ``python`` namespace keeps
(``len``, ``str``, ``int``, ``range`` bounded, ``sorted`` ...; no ``open``, ``getattr``,
``__import__``), attribute walks are refused and the work is bounded.

The bus layer below calls this through the ``evaluate=`` hook of ``load_launch``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from workbench.model.xacro_eval import evaluate
from workbench.model.xacro_guards import ExpressionError, SafeFunction
from workbench.model.xacro_meter import ExpressionLimitError
from workbench.model.xacro_namespaces import math_functions, python_functions


def _launch_words(message: str) -> str:
    return message.replace("a model file", "a launch file").replace("model file's", "launch file's")


def evaluate_launch_expression(
    expression: str, variables: dict[str, Any], functions: dict[str, Callable[..., Any]]
) -> Any:
    """The value of a roslaunch expression.

    Args:
        expression: The text of ``$(eval ...)`` (or a rosparam ``!radians`` angle).
        variables: Names the expression may read (the launch file's arguments, typed).
        functions: The launch file's functions (``arg``, ``find`` ...); like roslaunch's,
            they win over an argument of the same name.

    Raises:
        ExpressionError: The expression uses what a launch file may not (its message
            speaks of a launch file).
        ExpressionLimitError: It needs more work, memory or time than allowed.
    """
    symbols: dict[str, Any] = python_functions()
    symbols.update(variables)
    symbols.update(math_functions())
    symbols.update({"true": True, "false": False, "True": True, "False": False})
    for name, function in functions.items():
        symbols[name] = SafeFunction(function, name)
    try:
        return evaluate(expression, symbols)
    except ExpressionLimitError as error:
        raise ExpressionLimitError(_launch_words(error.message), hint=error.hint) from None
    except ExpressionError as error:
        raise ExpressionError(_launch_words(error.message), hint=error.hint) from None
