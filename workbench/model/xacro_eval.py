"""Evaluate xacro's ``${...}`` expressions so that a model file can compute and nothing else.

xacro evaluates ``${...}`` with Python's ``eval`` and filters only names that
start with ``__``; an attribute walk from any exposed function reaches module
globals (``os``), and generator frames reach every caller's globals. Here an
expression is parsed first and only plain expressions survive: literals,
arithmetic, comparisons, conditionals, comprehensions, lambdas, calls and
attribute access. The tree is then rewritten so that every call, attribute,
subscript, operator and loop goes through a guard of
:mod:`workbench.model.xacro_guards` (only exposed functions and the model's own
lambdas can be called; only namespaces, YAML keys and harmless methods can be
reached), and every step is charged to the meter of
:mod:`workbench.model.xacro_meter` (bounded integers, sizes, work and time).
The namespaces themselves are in :mod:`workbench.model.xacro_namespaces`.

Nothing here reads files: ``load_yaml`` and ``$(find)`` come from
:mod:`workbench.model.xacro_sandbox`, which checks their paths.
"""

from __future__ import annotations

import ast
import functools
import re
import types
from typing import Any

from workbench.model.xacro_guards import (
    SANDBOX_FILENAME,
    ExpressionError,
    attribute,
    binary,
    call,
    charged,
    item,
    iterate,
)
from workbench.model.xacro_meter import (
    MAX_EXPRESSION_LENGTH,
    MAX_FORMAT_WIDTH,
    ExpressionLimitError,
    Meter,
    check_int,
    check_size,
    meter_in_use,
    metered,
)

HELPERS: dict[str, Any] = {
    "__wb_attribute": attribute,
    "__wb_call": call,
    "__wb_binary": binary,
    "__wb_item": item,
    "__wb_slice": slice,
    "__wb_iterate": iterate,
    "__wb_charged": charged,
}


# --- parsing and rewriting ------------------------------------------------------------------

_ALLOWED = (
    ast.Expression,
    ast.Constant,
    ast.Name,
    ast.Attribute,
    ast.Subscript,
    ast.Slice,
    ast.BinOp,
    ast.UnaryOp,
    ast.BoolOp,
    ast.Compare,
    ast.IfExp,
    ast.Call,
    ast.keyword,
    ast.List,
    ast.Tuple,
    ast.Set,
    ast.Dict,
    ast.ListComp,
    ast.SetComp,
    ast.DictComp,
    ast.GeneratorExp,
    ast.comprehension,
    ast.Lambda,
    ast.arguments,
    ast.arg,
    ast.Starred,
    ast.JoinedStr,
    ast.FormattedValue,
    ast.expr_context,
    ast.operator,
    ast.unaryop,
    ast.boolop,
    ast.cmpop,
)

_WIDTH = re.compile(r"\d+")


def _helper(name: str, *args: ast.expr) -> ast.Call:
    return ast.Call(func=ast.Name(id=f"__wb_{name}", ctx=ast.Load()), args=list(args), keywords=[])


def _validate(tree: ast.AST) -> None:
    for node in ast.walk(tree):
        if not isinstance(node, _ALLOWED):
            raise ExpressionError(
                f"{type(node).__name__} is not available in a model file's expressions"
            )
        identifier = None
        if isinstance(node, ast.Name):
            identifier = node.id
        elif isinstance(node, ast.arg | ast.keyword):
            identifier = node.arg
        if identifier is not None and identifier.startswith("__"):
            raise ExpressionError(f"the name '{identifier}' is not available in a model file")
        if isinstance(node, ast.Attribute) and node.attr.startswith("_"):
            raise ExpressionError(f"attribute '{node.attr}' is not available in a model file")
        if isinstance(node, ast.FormattedValue) and node.format_spec is not None:
            for part in ast.walk(node.format_spec):
                if isinstance(part, ast.FormattedValue) and part is not node:
                    raise ExpressionError("a computed format in an f-string is not available")
                if isinstance(part, ast.Constant) and isinstance(part.value, str):
                    for width in _WIDTH.findall(part.value):
                        if int(width) > MAX_FORMAT_WIDTH:
                            raise ExpressionLimitError(
                                f"the f-string format '{part.value}' asks for more than "
                                f"{MAX_FORMAT_WIDTH} characters"
                            )


class _Rewrite(ast.NodeTransformer):
    """Route every operation that can cost or reach something through a guard."""

    def visit_Attribute(self, node: ast.Attribute) -> ast.AST:
        self.generic_visit(node)
        return _helper("attribute", node.value, ast.Constant(node.attr))

    def visit_Call(self, node: ast.Call) -> ast.AST:
        self.generic_visit(node)
        rewritten = _helper("call", node.func, *node.args)
        rewritten.keywords = node.keywords
        return rewritten

    def visit_BinOp(self, node: ast.BinOp) -> ast.AST:
        self.generic_visit(node)
        return _helper("binary", ast.Constant(type(node.op).__name__), node.left, node.right)

    def visit_Subscript(self, node: ast.Subscript) -> ast.AST:
        self.generic_visit(node)
        return _helper("item", node.value, node.slice)

    def visit_Slice(self, node: ast.Slice) -> ast.AST:
        self.generic_visit(node)
        none = ast.Constant(None)
        return _helper("slice", node.lower or none, node.upper or none, node.step or none)

    def visit_comprehension(self, node: ast.comprehension) -> ast.AST:
        self.generic_visit(node)
        node.iter = _helper("iterate", node.iter)
        return node

    def visit_Compare(self, node: ast.Compare) -> ast.AST:
        self.generic_visit(node)
        node.left = _helper("charged", node.left)
        node.comparators = [_helper("charged", value) for value in node.comparators]
        return node

    def _charge_value(self, node: ast.Starred | ast.FormattedValue) -> ast.AST:
        """``*value`` copies it and ``f"{value}"`` prints it: both cost its size."""
        self.generic_visit(node)
        node.value = _helper("charged", node.value)
        return node

    visit_Starred = _charge_value
    visit_FormattedValue = _charge_value

    def visit_Dict(self, node: ast.Dict) -> ast.AST:
        self.generic_visit(node)
        node.values = [
            _helper("charged", value) if key is None else value
            for key, value in zip(node.keys, node.values, strict=True)
        ]
        return node


@functools.lru_cache(maxsize=4096)
def compile_expression(text: str) -> types.CodeType:
    """Check and rewrite one expression; the code runs only with :data:`HELPERS` as builtins.

    Raises:
        ExpressionError: Syntax errors and anything a model may not use.
        ExpressionLimitError: An expression too long or too deeply nested.
    """
    source = text.strip()
    if len(source) > MAX_EXPRESSION_LENGTH:
        raise ExpressionLimitError(
            f"an expression of {len(source):,} characters; at most {MAX_EXPRESSION_LENGTH:,}"
        )
    try:
        tree = ast.parse(source, SANDBOX_FILENAME, mode="eval")
        _validate(tree)
        tree = ast.fix_missing_locations(_Rewrite().visit(tree))
        return compile(tree, SANDBOX_FILENAME, "eval")
    except SyntaxError as error:
        raise ExpressionError(f"invalid expression: {error.msg}") from None
    except (RecursionError, MemoryError):
        raise ExpressionLimitError("the expression is nested too deeply") from None


def evaluate(text: str, symbols: dict[str, Any]) -> Any:
    """Evaluate ``text`` with ``symbols`` as its names (a xacro property table, or a dict).

    The result is bounded like every intermediate value. Work is charged to the
    :class:`Meter` of :func:`metered`, or to a fresh one for this expression alone.

    Raises:
        ExpressionError: The expression uses what a model may not.
        ExpressionLimitError: It needs more work, memory or time than allowed.
    """
    if meter_in_use() is None:
        with metered(Meter()):
            return evaluate(text, symbols)
    code = compile_expression(text)
    # Builtins come from the globals' own storage: only the guards, never Python's.
    dict.__setitem__(symbols, "__builtins__", HELPERS)
    try:
        result = eval(code, symbols)  # noqa: S307 - checked and rewritten above
    except RecursionError:
        raise ExpressionLimitError("the expression recurses too deeply") from None
    return check_int(check_size(result))
