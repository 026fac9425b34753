"""roslaunch's substitution args: ``$(arg)``, ``$(env)``, ``$(optenv)``, ``$(anon)``,
``$(dirname)``, ``$(find)`` and ``$(eval)``, resolved as ROS 1's roslaunch resolves them.

The rules matched (roslaunch's ``substitution_args``): a value that is wholly
``$(eval EXPR)`` is an expression; otherwise every ``$(command words)`` is replaced, the
others first and ``$(find)`` last (so a value that an ``$(arg)`` brought in may hold a
``$(find)``); a ``$`` or ``(`` inside a substitution and an unknown command are errors;
``$(optenv NAME DEFAULT WORDS)`` joins the default's words with single spaces; ``$(arg)``
and ``arg()`` in an expression see the values of the current scope, typed as roslaunch
types a ``<param>`` value (:func:`convert_value`).

An expression is evaluated in workbench's expression sandbox (the one xacro's ``${}``
uses: no attribute walks to Python's internals, bounded work and sizes), which the model
layer provides: this layer gets it as an :data:`ExpressionEvaluator` (``workbench launch``
passes it). Its names are roslaunch's: ``arg()``, ``find()``, ``env()``, ``optenv()``,
``anon()``, ``dirname()``, ``true``/``false``, :mod:`math`, the harmless builtins, and
every argument by name. Like roslaunch, an expression may not contain ``__``.
"""

from __future__ import annotations

import os
import random
import socket
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from workbench.errors import WorkbenchError

#: ``evaluate(expression, variables, functions) -> value``: workbench's expression sandbox
#: (``workbench.model.launch_eval.evaluate_launch_expression``).
ExpressionEvaluator = Callable[[str, dict[str, Any], dict[str, Callable[..., Any]]], Any]

COMMANDS = ("find", "env", "optenv", "dirname", "anon", "arg")


class SubstitutionError(Exception):
    """A substitution that cannot be resolved; the caller adds the file and line."""

    def __init__(self, message: str, hint: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.hint = hint


class ArgNotSet(SubstitutionError):
    """``$(arg NAME)`` of an argument without a value (roslaunch: "requires the arg")."""

    def __init__(self, name: str) -> None:
        super().__init__(
            f"$(arg {name}) is not set", hint=f"pass {name}:=VALUE, or give it a default"
        )
        self.name = name


def anonymous_name(base: str) -> str:
    """``base_HOST_PID_RANDOM`` with ``.``, ``-`` and ``:`` made ``_``, as roslaunch names them."""
    name = f"{base}_{socket.gethostname()}_{os.getpid()}_{random.randint(0, sys.maxsize)}"
    return name.replace(".", "_").replace("-", "_").replace(":", "_")


def convert_value(value: str, type_name: str) -> Any:
    """A text value typed as roslaunch types a ``<param>`` (``auto``, ``str``, ``int``,
    ``double``, ``bool``); ``yaml`` is the caller's.

    ``auto``: a number if it parses (with a ``.``: a float; without and with no ``_``: an
    int), else ``true``/``false`` in any case as a bool, else the text.

    Raises:
        ValueError: Not of the type asked for, or an unknown type.
    """
    kind = type_name.lower()
    if kind == "auto":
        try:
            if "." in value:
                return float(value)
            if "_" not in value:
                return int(value)
        except ValueError:
            pass
        if value.lower() in ("true", "false"):
            return value.lower() == "true"
        return value
    if kind in ("str", "string"):
        return value
    if kind == "int":
        return int(value)
    if kind == "double":
        return float(value)
    if kind in ("bool", "boolean"):
        text = value.lower().strip()
        if text in ("true", "1"):
            return True
        if text in ("false", "0"):
            return False
        raise ValueError(f"{value} is not a '{type_name}' type")
    raise ValueError(f"unknown type '{type_name}'")


@dataclass
class Scope:
    """What substitutions see where a value is read.

    Attributes:
        args: Argument values of the current scope.
        anon: ``$(anon id)`` names given so far in the scope.
        filename: The launch file, for ``$(dirname)``.
        find: ``find(package) -> folder``.
        evaluate: The expression sandbox, or None (then ``$(eval)`` is refused).
    """

    args: dict[str, str]
    anon: dict[str, str]
    filename: Path
    find: Callable[[str], Path]
    evaluate: ExpressionEvaluator | None


def collect(text: str) -> list[str]:
    """The bodies of the ``$(...)`` in ``text``, as roslaunch's state machine reads them.

    Raises:
        SubstitutionError: A ``$`` or ``(`` inside a substitution.
    """
    found: list[str] = []
    buffer: list[str] = []
    state = "out"
    for char in text:
        if char == "$":
            if state not in ("out", "dollar"):
                raise SubstitutionError(f"a '$' cannot be inside a substitution: {text!r}")
            state = "dollar"
        elif char == "(":
            if state == "dollar":
                state = "paren"
            elif state != "out":
                raise SubstitutionError(f"a '(' cannot be inside a substitution: {text!r}")
        elif char == ")":
            if state == "in":
                found.append("".join(buffer))
                buffer.clear()
            state = "out"
        elif state == "dollar":
            state = "out"
        elif state == "paren":
            state = "in"
        if state == "in":
            buffer.append(char)
    return found


def _arg(scope: Scope, name: str) -> str:
    if name not in scope.args:
        raise ArgNotSet(name)
    return scope.args[name]


def _env(name: str) -> str:
    if name not in os.environ:
        raise SubstitutionError(
            f"environment variable {name} is not set", hint=f"export {name}=VALUE first"
        )
    return os.environ[name]


def _optenv(name: str, default: str = "") -> str:
    return os.environ.get(name, default)


def _anon(scope: Scope, base: str) -> str:
    if base not in scope.anon:
        scope.anon[base] = anonymous_name(base)
    return scope.anon[base]


def _one_word(command: str, words: list[str], body: str) -> str:
    if len(words) != 1:
        raise SubstitutionError(f"$({body}): {command} takes one word")
    return words[0]


def _replacement(body: str, words: list[str], scope: Scope) -> str:
    command = words[0]
    if command == "arg":
        return _arg(scope, _one_word("arg", words[1:], body))
    if command == "env":
        return _env(_one_word("env", words[1:], body))
    if command == "optenv":
        if len(words) < 2:
            raise SubstitutionError(f"$({body}): optenv needs a variable name")
        return _optenv(words[1], " ".join(words[2:]))
    if command == "anon":
        return _anon(scope, _one_word("anon", words[1:], body))
    if command == "dirname":
        return str(scope.filename.parent)
    name = _one_word("find", words[1:], body)
    try:
        return str(scope.find(name))
    except WorkbenchError as error:  # a package that is not there
        raise SubstitutionError(f"$(find {name}): {error.message}", error.hint) from None


def _pass(text: str, scope: Scope, commands: tuple[str, ...], limit: int) -> str:
    resolved = text
    for body in collect(text):
        words = [w for w in body.split(" ") if w]
        if not words:
            raise SubstitutionError(f"an empty substitution $({body})")
        if words[0] not in COMMANDS:
            raise SubstitutionError(
                f"unknown substitution $({body})",
                hint="roslaunch knows " + ", ".join(f"$({c})" for c in (*COMMANDS, "eval")),
            )
        if words[0] in commands:
            resolved = resolved.replace(f"$({body})", _replacement(body, words, scope))
            if len(resolved) > limit:
                raise SubstitutionError(
                    f"the value is {len(resolved):,} characters long after substitution, "
                    f"more than {limit:,}",
                    hint="are <arg>s defined in terms of each other over and over?",
                )
    return resolved


def resolve(text: str, scope: Scope, limit: int) -> str:
    """``text`` with its substitutions resolved (see the module's note).

    Raises:
        SubstitutionError: Unknown or malformed substitutions, an unset argument or
            variable, a bad expression, a result longer than ``limit`` characters.
    """
    if not text or "$" not in text:
        return text
    if text.startswith("$(eval ") and text.endswith(")"):
        return evaluate(text[7:-1], scope, limit)
    first = _pass(text, scope, ("env", "optenv", "dirname", "anon", "arg"), limit)
    return _pass(first, scope, ("find",), limit)


def expression_names(scope: Scope) -> tuple[dict[str, Any], dict[str, Callable[..., Any]]]:
    """The variables (every argument, typed) and functions an ``$(eval)`` sees."""
    variables = {
        name: convert_value(value, "auto")
        for name, value in scope.args.items()
        if name.isidentifier()
    }
    functions: dict[str, Callable[..., Any]] = {
        "arg": lambda name: convert_value(_arg(scope, str(name)), "auto"),
        "anon": lambda base: _anon(scope, str(base)),
        "dirname": lambda: str(scope.filename.parent),
        "env": lambda name: _env(str(name)),
        "optenv": lambda name, default="": _optenv(str(name), default),
        "find": lambda name: str(scope.find(str(name))),
    }
    return variables, functions


def evaluate(expression: str, scope: Scope, limit: int) -> str:
    """``$(eval expression)``: its value as text (``True``, ``3.0``, ``burger``).

    Raises:
        SubstitutionError: No sandbox given, ``__`` in the expression, or the expression
            fails (a name it does not know, a refused operation, a bound passed).
    """
    where = f"$(eval {expression})" if len(expression) <= 60 else "$(eval ...)"
    if "__" in expression:
        raise SubstitutionError(f"{where}: an expression may not contain '__' (as in roslaunch)")
    if scope.evaluate is None:
        raise SubstitutionError(
            f"{where} needs workbench's expression sandbox",
            hint="start the file with 'workbench launch' (load_launch(..., evaluate=...) "
            "from Python)",
        )
    variables, functions = expression_names(scope)
    try:
        value = scope.evaluate(expression, variables, functions)
    except (SubstitutionError, WorkbenchError) as error:
        raise SubstitutionError(f"{where}: {error.message}", error.hint) from None
    except (ArithmeticError, LookupError, NameError, TypeError, ValueError) as error:
        raise SubstitutionError(f"{where}: {type(error).__name__}: {error}") from None
    text = str(value)
    if len(text) > limit:
        raise SubstitutionError(f"{where} gives more than {limit:,} characters")
    return text
