"""Guarding the Python expressions of an untrusted xacro document (``${...}``, ``$(eval ...)``).

xacro evaluates ``${...}`` with :func:`eval` over its symbol table and no builtins; that is
no sandbox (``${''.__class__.__mro__}``, ``'{0.__globals__}'.format(f)``, a generator's
``gi_frame.f_back.f_globals`` all reach the interpreter). :func:`check_expression` parses
the expression and refuses, *before* anything is evaluated:

- attribute names starting with ``_`` (``__class__``, ``_asdict``) and the attributes that
  reach frames, code or formatting of arbitrary attributes (``format``, ``format_map``,
  ``mro``, ``gi_*``, ``cr_*``, ``ag_*``, ``f_*``, ``tb_*``, ``co_*``);
- names starting with ``__`` (xacro itself forbids such property names);
- string constants containing ``__`` (a key into ``vars()``-like mappings);

and rewrites ``a ** b`` and ``a << b`` to calls of guards that refuse integer results of
more than :data:`MAX_INT_BITS` bits at once (``${9**9**9}`` would otherwise hold the CPU
for minutes). The child process running the expansion is bounded as well (time, memory),
so these guards make refusals quick and clear; they are not the only bound.
"""

from __future__ import annotations

import ast
import math
import re
from typing import Any

#: Largest integer (in bits) a ``**`` or ``<<`` in an expression may produce.
MAX_INT_BITS = 100_000
#: Names under which the guards are put into the symbol table (users cannot name them:
#: names starting with ``__`` are refused).
POW_GUARD = "__denavit_pow__"
LSHIFT_GUARD = "__denavit_lshift__"

_FORBIDDEN_ATTRIBUTES = frozenset({"format", "format_map", "mro"})
_FORBIDDEN_ATTRIBUTE_PREFIX = re.compile(r"^(gi|cr|ag|f|tb|co|func|im)_")


class ExpressionRefused(Exception):  # noqa: N818 - a refusal, reported to the client
    """The expression uses something a client's document may not use."""


def _check_node(node: ast.AST) -> None:
    if isinstance(node, ast.Attribute):
        attr = node.attr
        if attr.startswith("_"):
            raise ExpressionRefused(
                f"attribute {attr!r}: attributes starting with '_' are not allowed"
            )
        if attr in _FORBIDDEN_ATTRIBUTES or _FORBIDDEN_ATTRIBUTE_PREFIX.match(attr):
            raise ExpressionRefused(f"attribute {attr!r} is not allowed")
    elif isinstance(node, ast.Name) and node.id.startswith("__"):
        raise ExpressionRefused(f"name {node.id!r}: names starting with '__' are not allowed")
    elif isinstance(node, ast.Constant) and isinstance(node.value, (str, bytes)):
        text = node.value if isinstance(node.value, str) else node.value.decode("latin-1")
        if "__" in text:
            raise ExpressionRefused("string constants containing '__' are not allowed")


class _GuardOperators(ast.NodeTransformer):
    """``a ** b`` → ``__denavit_pow__(a, b)``; ``a << b`` → ``__denavit_lshift__(a, b)``."""

    def visit_BinOp(self, node: ast.BinOp) -> ast.AST:  # noqa: N802 - ast API
        self.generic_visit(node)
        guard = {ast.Pow: POW_GUARD, ast.LShift: LSHIFT_GUARD}.get(type(node.op))
        if guard is None:
            return node
        call = ast.Call(ast.Name(guard, ast.Load()), [node.left, node.right], [])
        return ast.copy_location(call, node)

    def visit_AugAssign(self, node: ast.AugAssign) -> ast.AST:  # noqa: N802 - ast API
        raise ExpressionRefused("assignments are not allowed")  # not reachable in eval mode


def compile_expression(expr: str) -> Any:
    """The code object of a checked xacro expression (eval mode), guards inserted.

    Raises
    ------
    ExpressionRefused
        The expression uses a refused name, attribute or string.
    SyntaxError
        Not a Python expression.
    """
    tree = ast.parse(expr.strip(), "<expression>", "eval")
    for node in ast.walk(tree):
        _check_node(node)
    tree = ast.fix_missing_locations(_GuardOperators().visit(tree))
    return compile(tree, "<expression>", "eval")


def _int_bits(value: Any) -> float:
    return math.log2(abs(value)) if value else 0.0


def guarded_pow(base: Any, exponent: Any) -> Any:
    """``base ** exponent``, refusing an integer result of more than :data:`MAX_INT_BITS`."""
    if isinstance(base, int) and isinstance(exponent, int) and exponent > 0 and abs(base) > 1:
        if exponent * _int_bits(base) > MAX_INT_BITS:
            raise ExpressionRefused(
                f"{base} ** {exponent} would have more than {MAX_INT_BITS} bits"
            )
    return base**exponent


def guarded_lshift(value: Any, shift: Any) -> Any:
    """``value << shift``, refusing an integer result of more than :data:`MAX_INT_BITS`."""
    if isinstance(value, int) and isinstance(shift, int) and value and shift > MAX_INT_BITS:
        raise ExpressionRefused(f"<< {shift} would make more than {MAX_INT_BITS} bits")
    return value << shift


#: The guards, to put into the symbol table an expression is evaluated with.
GUARDS = {POW_GUARD: guarded_pow, LSHIFT_GUARD: guarded_lshift}
