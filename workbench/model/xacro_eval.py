"""Evaluate xacro's ``${...}`` expressions so that a model file can compute and nothing else.

xacro evaluates ``${...}`` with Python's ``eval`` and filters only names that
start with ``__``; an attribute walk from any exposed function reaches module
globals (``os``), and generator frames reach every caller's globals. Here an
expression is parsed first and only plain expressions survive: literals,
arithmetic, comparisons, conditionals, comprehensions, lambdas, calls and
attribute access. The tree is then rewritten so that every call, attribute,
subscript, operator and loop goes through a small guard:

* **calls** reach only the functions workbench exposes (xacro's ``python``,
  ``math`` and ``xacro`` namespaces, re-made here) and lambdas written in the
  model; everything a model can reach is data or one of those;
* **attributes** are property namespaces, YAML keys, and a list of harmless
  methods of strings, numbers and containers (no ``format``: it walks
  attributes by name);
* **work is bounded**: integers have at most :data:`MAX_INT_BITS` bits (so
  ``9**9**9`` is refused before it starts), a value at most :data:`MAX_SIZE`
  characters or items, and every operation is charged to a :class:`Meter`
  that stops after :data:`MAX_STEPS` units or :data:`MAX_SECONDS` seconds.
  No single step runs long in C, so Ctrl-C always gets through.

Nothing here reads files: ``load_yaml`` and ``$(find)`` come from
:mod:`workbench.model.xacro_sandbox`, which checks their paths.
"""

from __future__ import annotations

import ast
import contextlib
import functools
import math
import operator
import re
import time
import types
from collections.abc import Callable, Iterator
from typing import Any

from workbench.errors import ModelError

#: Largest integer a model expression may make, in bits (about 1233 decimal digits).
MAX_INT_BITS = 4096
#: Largest value a model expression may make: characters of a string, items of a collection
#: (counted through nested collections).
MAX_SIZE = 1_000_000
#: Work units one file's expressions may spend (an operation on a value of size n costs n).
MAX_STEPS = 2_000_000
#: Seconds one file's expansion may take (a backstop: the bounds above stop hostile files
#: within a few seconds; xacro itself needs a few for thousands of macro calls).
MAX_SECONDS = 60.0
#: Longest expression text, characters.
MAX_EXPRESSION_LENGTH = 10_000
#: Widths and precisions allowed in ``%`` formats and f-strings.
MAX_FORMAT_WIDTH = 10_000

#: The file name compiled expressions carry (tells a model's own lambdas from anything else).
SANDBOX_FILENAME = "<xacro expression>"


class ExpressionError(ModelError):
    """A xacro expression uses something a model file may not (a refusal, not a limit)."""


class ExpressionLimitError(ModelError):
    """A xacro expression needs more work, memory or time than a model file may use."""


# --- the meter ----------------------------------------------------------------------


class Meter:
    """Work and time spent by one file's expressions.

    Args:
        max_steps: Work units allowed.
        max_seconds: Wall-clock seconds allowed from now.
    """

    def __init__(self, max_steps: int = MAX_STEPS, max_seconds: float = MAX_SECONDS) -> None:
        self.max_steps = max_steps
        self.max_seconds = max_seconds
        self.steps = 0
        self.started = time.monotonic()
        self._next_clock = 10_000

    def charge(self, units: int = 1) -> None:
        """Spend ``units``; raise :class:`ExpressionLimitError` past a bound."""
        self.steps += units
        if self.steps > self.max_steps:
            raise ExpressionLimitError(
                f"the expressions need more than {self.max_steps:,} operations",
                hint="a model file may compute, but within bounds; see 'Limits on input' "
                "in the README",
            )
        if self.steps >= self._next_clock:
            self._next_clock = self.steps + 10_000
            self.check_time()

    def check_time(self) -> None:
        """Raise :class:`ExpressionLimitError` once the time is up."""
        if time.monotonic() - self.started > self.max_seconds:
            raise ExpressionLimitError(
                f"expanding the file takes more than {self.max_seconds:g} s",
                hint="a model file may compute, but within bounds; see 'Limits on input' "
                "in the README",
            )


_meter: Meter | None = None


@contextlib.contextmanager
def metered(meter: Meter) -> Iterator[Meter]:
    """Charge every expression evaluated inside to ``meter``."""
    global _meter
    previous, _meter = _meter, meter
    try:
        yield meter
    finally:
        _meter = previous


def _charge(units: int = 1) -> None:
    if _meter is not None:  # outside an evaluation (xacro printing a result) nothing is charged
        _meter.charge(units)


# --- sizes ----------------------------------------------------------------------------

_SCALARS = (int, float, complex, bool, type(None))
_DATA = (str, bytes, list, tuple, dict, set, frozenset, range, *_SCALARS)
_COLLECTIONS: tuple[type, ...] = (list, tuple, set, frozenset, types.MappingProxyType)
_COLLECTIONS += (type({}.keys()), type({}.values()), type({}.items()))


def weight(value: Any, cap: int = MAX_SIZE) -> int:
    """How much work converting or comparing ``value`` costs: characters plus items, deep.

    Counting stops just above ``cap`` (a shared or endless structure cannot hang it).
    """
    total = 0
    stack = [value]
    while stack and total <= cap:
        item = stack.pop()
        if isinstance(item, str | bytes):
            total += len(item)
        elif isinstance(item, int):
            total += 1 + item.bit_length() // 64
        elif isinstance(item, _SCALARS):
            total += 1
        elif isinstance(item, range):
            total += len(item)
        elif isinstance(item, dict):
            total += 1
            stack.extend(dict.keys(item))
            stack.extend(dict.values(item))
            parent = getattr(item, "parent", None)  # a xacro namespace prints its parents too
            if isinstance(parent, dict) and parent is not item:
                stack.append(parent)
        elif isinstance(item, _COLLECTIONS):
            total += 1
            stack.extend(item)  # type: ignore[arg-type]
        else:
            total += 1
    return total


def _check_size(value: Any, what: str = "the result") -> Any:
    size = weight(value)
    if size > MAX_SIZE:
        raise ExpressionLimitError(
            f"{what} would hold more than {MAX_SIZE:,} characters or items",
            hint="a model file may compute, but within bounds; see 'Limits on input' in the README",
        )
    _charge(size)
    return value


def _charge_weight(value: Any) -> None:
    """Charge what reading ``value`` costs; refuse a value past :data:`MAX_SIZE`."""
    _check_size(value, "a value")


def _check_int(value: Any) -> Any:
    if isinstance(value, int) and value.bit_length() > MAX_INT_BITS:
        raise ExpressionLimitError(
            f"the result has {value.bit_length():,} bits; a model file may compute integers "
            f"of at most {MAX_INT_BITS} bits",
            hint="use floats, such as 1e300, for very large numbers",
        )
    return value


def _int_bits_limit(bits: float, what: str) -> None:
    if bits > MAX_INT_BITS:
        raise ExpressionLimitError(
            f"{what} would have about {bits:,.0f} bits; a model file may compute integers "
            f"of at most {MAX_INT_BITS} bits",
            hint="use floats, such as 9.0**99, for very large numbers",
        )


# --- operators --------------------------------------------------------------------------

_BINARY: dict[str, Callable[[Any, Any], Any]] = {
    "Add": operator.add,
    "Sub": operator.sub,
    "Mult": operator.mul,
    "MatMult": operator.matmul,
    "Div": operator.truediv,
    "FloorDiv": operator.floordiv,
    "Mod": operator.mod,
    "Pow": operator.pow,
    "LShift": operator.lshift,
    "RShift": operator.rshift,
    "BitOr": operator.or_,
    "BitXor": operator.xor,
    "BitAnd": operator.and_,
}

_SEQUENCES = (str, bytes, list, tuple)
_PERCENT_FIELD = re.compile(r"%(?:\([^)]*\))?[-+ #0]*(\*|\d+)?(?:\.(\*|\d+))?")


def _is_int(value: Any) -> bool:
    return isinstance(value, int)


def _check_percent_format(text: str | bytes) -> None:
    pattern = text.decode("latin-1") if isinstance(text, bytes) else text
    for match in _PERCENT_FIELD.finditer(pattern):
        for number in match.groups():
            if number == "*" or (number is not None and int(number) > MAX_FORMAT_WIDTH):
                raise ExpressionLimitError(
                    f"the format '{match.group()}' asks for a field wider than "
                    f"{MAX_FORMAT_WIDTH} characters"
                )


def binary(name: str, left: Any, right: Any) -> Any:
    """``left <op> right`` with the work charged and the result bounded."""
    _charge(1)
    if name == "Pow" and _is_int(left) and _is_int(right) and right > 0 and abs(left) > 1:
        _int_bits_limit(right * math.log2(abs(left)), "the power")
    elif name == "LShift" and _is_int(left) and _is_int(right) and left != 0 and right > 0:
        _int_bits_limit(left.bit_length() + right, "the shift")
    elif name == "Mult":
        for sequence, count in ((left, right), (right, left)):
            if isinstance(sequence, _SEQUENCES) and _is_int(count) and count > 0:
                size = weight(sequence) * count
                if size > MAX_SIZE:
                    raise ExpressionLimitError(
                        f"repeating a value {count:,} times would make more than "
                        f"{MAX_SIZE:,} characters or items"
                    )
                _charge(size)
        if _is_int(left) and _is_int(right):
            _int_bits_limit(left.bit_length() + right.bit_length(), "the product")
    elif name == "Add" and isinstance(left, _SEQUENCES) and isinstance(right, _SEQUENCES):
        _charge(len(left) + len(right))
        if weight(left) + weight(right) > MAX_SIZE:
            raise ExpressionLimitError(
                f"joining the values would make more than {MAX_SIZE:,} characters or items"
            )
    elif name == "Mod" and isinstance(left, str | bytes):
        _check_percent_format(left)
        _charge_weight(left)
        _charge_weight(right)
    try:
        return _check_int(_BINARY[name](left, right))
    except OverflowError:
        raise ExpressionLimitError("the result is too large for a floating-point number") from None


# --- attributes and methods -------------------------------------------------------------

_STR_METHODS = frozenset(
    [
        "capitalize",
        "casefold",
        "count",
        "endswith",
        "find",
        "index",
        "isalnum",
        "isalpha",
        "isdecimal",
        "isdigit",
        "islower",
        "isnumeric",
        "isspace",
        "istitle",
        "isupper",
        "join",
        "lower",
        "lstrip",
        "partition",
        "removeprefix",
        "removesuffix",
        "replace",
        "rfind",
        "rindex",
        "rpartition",
        "rsplit",
        "rstrip",
        "split",
        "splitlines",
        "startswith",
        "strip",
        "swapcase",
        "title",
        "upper",
        "center",
        "ljust",
        "rjust",
        "zfill",
        "expandtabs",
    ]
)
_LIST_METHODS = frozenset({"count", "index"})
_DICT_METHODS = frozenset({"keys", "values", "items", "get", "copy"})
_SET_METHODS = frozenset(
    [
        "union",
        "intersection",
        "difference",
        "symmetric_difference",
        "issubset",
        "issuperset",
        "isdisjoint",
        "copy",
    ]
)
_NUMBER_ATTRIBUTES = frozenset(
    [
        "real",
        "imag",
        "conjugate",
        "numerator",
        "denominator",
        "bit_length",
        "is_integer",
        "as_integer_ratio",
    ]
)
_PADDING = frozenset({"center", "ljust", "rjust", "zfill"})


class SafeFunction:
    """A function a model's expressions may call; it charges its own work.

    Args:
        function: What it calls.
        name: The name shown in messages (``python.len``).
        consumes: Its iterable arguments are read item by item (charged per item).
    """

    def __init__(self, function: Callable[..., Any], name: str, consumes: bool = False) -> None:
        self.function = function
        self.name = name
        self.consumes = consumes

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        _charge(1)
        for value in (*args, *kwargs.values()):
            _charge_weight(value)
        if self.consumes:
            args = tuple(metered_items(a) if _is_lazy(a) else a for a in args)
        result = self.function(*args, **kwargs)
        if isinstance(result, str | bytes | list | tuple | dict | set | frozenset):
            _check_size(result)
        return _check_int(result)

    def __repr__(self) -> str:
        return f"<function {self.name}>"


def _is_lazy(value: Any) -> bool:
    return not isinstance(value, _DATA) and hasattr(value, "__iter__")


def metered_items(iterable: Any) -> Iterator[Any]:
    """The items of ``iterable``, each charged by its weight."""
    for item in iterable:
        _charge_weight(item)
        yield item


def iterate(iterable: Any) -> Iterator[Any]:
    """The items of a comprehension's ``for``, one work unit each."""
    _charge(1)
    for item in iterable:
        _charge(1)
        yield item


def _method(value: Any, name: str) -> SafeFunction:
    bound = getattr(value, name)

    def call(*args: Any, **kwargs: Any) -> Any:
        _charge_weight(value)
        if name in _PADDING or name == "expandtabs":
            width = args[0] if args else kwargs.get("width", kwargs.get("tabsize", 8))
            size = width * (len(value) if name == "expandtabs" else 1)
            if _is_int(width) and size > MAX_SIZE:
                raise ExpressionLimitError(f"{name}() would make more than {MAX_SIZE:,} characters")
        elif name == "replace" and len(args) >= 2 and isinstance(args[0], str | bytes):
            old, new = args[0], args[1]
            count = len(value) + 1 if not old else value.count(old)
            if len(value) + count * max(0, len(new) - len(old)) > MAX_SIZE:
                raise ExpressionLimitError(
                    f"replace() would make more than {MAX_SIZE:,} characters"
                )
        elif name == "join" and args:
            parts = list(metered_items(args[0]))
            if sum(weight(part) for part in parts) > MAX_SIZE:
                raise ExpressionLimitError(f"join() would make more than {MAX_SIZE:,} characters")
            args = (parts, *args[1:])
        return bound(*args, **kwargs)

    return SafeFunction(call, f"{type(value).__name__}.{name}")


def attribute(value: Any, name: str) -> Any:
    """``value.name`` for namespaces, YAML mappings and a few harmless methods only."""
    import xacro

    _charge(1)
    if name.startswith("_"):
        raise ExpressionError(f"attribute '{name}' is not available in a model file")
    if isinstance(value, xacro.NameSpace):
        try:
            return xacro.Table.__getitem__(value, name)
        except KeyError:
            removed = vars(value).get("removed_names", {}).get(name)
            if removed is not None:
                raise ExpressionError(removed) from None
            raise NameError(f"name '{name}' is not defined") from None
    if isinstance(value, xacro.YamlDictWrapper) and name not in _DICT_METHODS:
        return xacro.YamlDictWrapper.__getattr__(value, name)
    allowed: frozenset[str] = frozenset()
    if isinstance(value, str):
        allowed = _STR_METHODS
    elif isinstance(value, list | tuple):
        allowed = _LIST_METHODS
    elif isinstance(value, dict):
        allowed = _DICT_METHODS
    elif isinstance(value, set | frozenset):
        allowed = _SET_METHODS
    elif isinstance(value, int | float | complex):
        allowed = _NUMBER_ATTRIBUTES
    if name not in allowed:
        raise ExpressionError(
            f"'{type(value).__name__}.{name}' is not available in a model file",
            hint="expressions may use properties, arithmetic, math and a few string methods",
        )
    found = getattr(value, name)
    return _method(value, name) if callable(found) else found


def call(function: Any, /, *args: Any, **kwargs: Any) -> Any:
    """Call ``function`` if it is one a model may call: an exposed one or its own lambda."""
    _charge(1)
    own_lambda = (
        isinstance(function, types.FunctionType)
        and function.__code__.co_filename == SANDBOX_FILENAME
    )
    if not (own_lambda or isinstance(function, SafeFunction)):
        raise ExpressionError(
            f"calling a {type(function).__name__} is not available in a model file",
            hint="expressions may call the functions of xacro's python, math and xacro "
            "namespaces and their own lambdas",
        )
    return function(*args, **kwargs)


def item(value: Any, key: Any) -> Any:
    """``value[key]``; a slice is charged by the length of what it copies."""
    if isinstance(key, slice) and hasattr(value, "__len__"):
        _charge(1 + len(value))
    else:
        _charge(1 + (weight(key) if isinstance(key, str | bytes | tuple) else 0))
    return value[key]


def charged(value: Any) -> Any:
    """``value`` unchanged, after charging what comparing or printing it costs."""
    _charge_weight(value)
    return value


HELPERS: dict[str, Any] = {
    "__wb_attribute": attribute,
    "__wb_call": call,
    "__wb_binary": binary,
    "__wb_item": item,
    "__wb_slice": slice,
    "__wb_iterate": iterate,
    "__wb_charged": charged,
}

#: What ``python.NAME`` says for the builtins ROS's xacro exposes and workbench does not.
REMOVED_PYTHON = {
    name: f"python.{name} is not available in a model file (workbench evaluates xacro "
    "expressions without access to Python's internals)"
    for name in ("vars", "getattr", "setattr", "globals", "locals", "eval", "exec", "open")
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
    if _meter is None:
        with metered(Meter()):
            return evaluate(text, symbols)
    code = compile_expression(text)
    # Builtins come from the globals' own storage: only the guards, never Python's.
    dict.__setitem__(symbols, "__builtins__", HELPERS)
    try:
        result = eval(code, symbols)  # noqa: S307 - checked and rewritten above
    except RecursionError:
        raise ExpressionLimitError("the expression recurses too deeply") from None
    return _check_int(_check_size(result))


# --- the namespaces a model sees ------------------------------------------------------------


def _bounded_range(*args: Any) -> range:
    values = range(*args)
    if len(values) > MAX_SIZE:
        raise ExpressionLimitError(f"a range of {len(values):,} numbers; at most {MAX_SIZE:,}")
    return values


def _bounded_round(number: Any, ndigits: Any = None) -> Any:
    if ndigits is not None and _is_int(ndigits) and abs(ndigits) > 1000:
        raise ExpressionLimitError(f"round() to {ndigits} digits; at most 1000")
    return round(number, ndigits) if ndigits is not None else round(number)


def _sum(iterable: Any, start: Any = 0) -> Any:
    if not isinstance(start, int | float | complex):
        raise ExpressionError("sum() adds numbers only in a model file")
    total = start
    for value in iterable:
        total = binary("Add", total, value)
    return total


def _sorted(iterable: Any, **kwargs: Any) -> list[Any]:
    values = list(iterable)
    _charge(len(values) * max(1, len(values).bit_length()))
    return sorted(values, **kwargs)


def _small_int_arguments(function: Callable[..., Any], limit: int = 10_000) -> Callable[..., Any]:
    def bounded(*args: Any) -> Any:
        for value in args:
            if _is_int(value) and abs(value) > limit:
                raise ExpressionLimitError(
                    f"{function.__name__}() of {value}; at most {limit} in a model file"
                )
        return function(*args)

    return bounded


def _prod(iterable: Any, *, start: Any = 1) -> Any:
    """``math.prod`` one factor at a time, so a product cannot outgrow :data:`MAX_INT_BITS`."""
    total = start
    for value in iterable:
        total = _check_int(total * value)
    return total


def _lcm(*values: Any) -> Any:
    """``math.lcm`` one number at a time, bounded like :func:`_prod`."""
    total = 1
    for value in values:
        total = _check_int(math.lcm(total, value))
    return total


def _type(value: Any) -> Any:
    exposed = _TYPE_WRAPPERS.get(type(value))
    if exposed is None:
        raise ExpressionError(
            f"python.type() of a {type(value).__name__} is not available in a model file"
        )
    return exposed


def _types(spec: Any) -> Any:
    if isinstance(spec, tuple):
        return tuple(_types(s) for s in spec)
    if isinstance(spec, SafeFunction) and isinstance(spec.function, type):
        return spec.function
    raise ExpressionError("isinstance() takes the types of the python namespace")


def _isinstance(value: Any, spec: Any) -> bool:
    return isinstance(value, _types(spec))


def _issubclass(value: Any, spec: Any) -> bool:
    return issubclass(_types(value), _types(spec))


_CONSUMERS = {"list", "tuple", "set", "frozenset", "dict", "min", "max", "any", "all"}
_CONSUMERS |= {"enumerate", "zip", "map", "filter", "reversed"}
_PLAIN: tuple[str, ...] = ("bool", "float", "int", "complex", "str", "repr", "len", "abs", "divmod")
_PLAIN += ("ord", "hash", "slice", "list", "tuple", "set", "frozenset", "dict", "min", "max")
_PLAIN += ("any", "all", "enumerate", "zip", "map", "filter", "reversed")

_TYPE_WRAPPERS: dict[type, SafeFunction] = {}


def python_functions() -> dict[str, Any]:
    """xacro's ``python`` namespace, re-made: the builtins it exposes, each one guarded.

    ``vars``, ``type`` of anything but plain data, and attribute walks are gone.
    """
    import builtins

    functions: dict[str, Any] = {"True": True, "False": False}
    for name in _PLAIN:
        functions[name] = SafeFunction(
            getattr(builtins, name), f"python.{name}", consumes=name in _CONSUMERS
        )
    functions["range"] = SafeFunction(_bounded_range, "python.range")
    functions["round"] = SafeFunction(_bounded_round, "python.round")
    functions["sum"] = SafeFunction(_sum, "python.sum", consumes=True)
    functions["sorted"] = SafeFunction(_sorted, "python.sorted", consumes=True)
    functions["type"] = SafeFunction(_type, "python.type")
    functions["isinstance"] = SafeFunction(_isinstance, "python.isinstance")
    functions["issubclass"] = SafeFunction(_issubclass, "python.issubclass")
    for name in ("bool", "float", "int", "complex", "str", "list", "tuple", "set"):
        _TYPE_WRAPPERS[getattr(builtins, name)] = functions[name]
    for name in ("frozenset", "dict", "slice"):
        _TYPE_WRAPPERS[getattr(builtins, name)] = functions[name]
    return functions


def math_functions() -> dict[str, Any]:
    """xacro's ``math`` namespace: every public name of :mod:`math`, the integer ones bounded."""
    special = {
        "factorial": _small_int_arguments(math.factorial, 2000),
        "comb": _small_int_arguments(math.comb),
        "perm": _small_int_arguments(math.perm),
        "prod": _prod,
        "lcm": _lcm,
    }
    functions: dict[str, Any] = {}
    for name, value in vars(math).items():
        if name.startswith("_"):
            continue
        if callable(value):
            consumes = name in ("fsum", "prod", "dist", "hypot")
            functions[name] = SafeFunction(special.get(name, value), f"math.{name}", consumes)
        else:
            functions[name] = value
    return functions
