"""Script variables: ``variable NAME equal EXPR``, ``index V1 V2 ...``, ``string TEXT``.

Semantics follow LAMMPS: an ``equal`` variable is evaluated each time it is read, so it can follow a
run (``variable t equal temp``); an ``index`` variable set with ``-var`` on the command line is not
redefined by the script; ``next NAME`` steps an index variable to its next value.

Expressions use numbers, ``+ - * / ^ %``, parentheses, comparisons, ``&& || !``, the functions in
``FUNCTIONS``, thermo keywords (``step``, ``temp``, ...), ``v_NAME``, ``c_ID``, ``c_ID[i]`` and
``c_ID[i][j]``.
They are parsed with Python's ``ast`` and walked node by node; nothing is ``eval``-ed.
"""

import ast
import math
import operator
import re

from ..errors import ScriptError

FUNCTIONS = {
    "sqrt": math.sqrt, "exp": math.exp, "ln": math.log, "log": math.log10, "abs": abs,
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": math.asin, "acos": math.acos,
    "atan": math.atan, "atan2": math.atan2, "floor": math.floor, "ceil": math.ceil,
    "round": lambda x: math.floor(x + 0.5),    # 2.5 -> 3 as in LAMMPS (Python's round gives 2)
    "min": min, "max": max,
}
CONSTANTS = {"PI": math.pi}
BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
          ast.Div: operator.truediv, ast.Pow: operator.pow, ast.Mod: operator.mod}
COMPARE = {ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt, ast.GtE: operator.ge,
           ast.Eq: operator.eq, ast.NotEq: operator.ne}
NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


class Variable:
    def __init__(self, name, style, values):
        self.name, self.style, self.values, self.index = name, style, values, 0


class Variables:
    """The variables of one simulation; ``reader(name)`` resolves thermo keywords and compute refs."""

    def __init__(self, reader):
        self._vars = {}
        self._reader = reader
        self._evaluating = []      # equal-style variables being evaluated, to catch cycles

    def __contains__(self, name):
        return name in self._vars

    def names(self):
        return list(self._vars)

    def define(self, words, from_command_line=False):
        if len(words) < 2:
            raise ScriptError("expected: variable NAME STYLE ARGS")
        name, style, args = words[0], words[1], words[2:]
        if not NAME.match(name):
            raise ScriptError(f"variable name must be letters, digits and _ (got {name})")
        if style == "delete":
            self._vars.pop(name, None)
            return
        if style not in ("equal", "index", "string"):
            raise ScriptError(f"unknown variable style {style} (known: equal, index, string, delete)")
        if not args:
            raise ScriptError(f"variable {name} {style} needs a value")
        existing = self._vars.get(name)
        if existing is not None and style == "index":
            return  # LAMMPS: a variable, once set (e.g. by -var), keeps its value
        if existing is not None and existing.style != style:
            # LAMMPS refuses too: silently replacing it would lose a -var value
            raise ScriptError(f"variable {name} is already defined as {existing.style}; it cannot become "
                              f"{style} (use variable {name} delete first)")
        if style == "index":
            values = args
        else:
            values = [" ".join(args)]
        if style == "equal":
            self._parse(values[0], name)
        self._vars[name] = Variable(name, style, values)

    def next(self, name):
        """Step an index variable; return False when it is exhausted (and then deleted)."""
        var = self._get(name)
        if var.style != "index":
            raise ScriptError(f"next works only on index variables ({name} is {var.style})")
        var.index += 1
        if var.index >= len(var.values):
            del self._vars[name]
            return False
        return True

    def _get(self, name):
        try:
            return self._vars[name]
        except KeyError:
            raise ScriptError(f"undefined variable {name}") from None

    def text(self, name):
        """The value as text, as ``${name}`` substitutes it; ``(expr)`` is an immediate expression."""
        if name.startswith("("):
            return _format(self.evaluate(name[1:-1]))
        var = self._get(name)
        if var.style == "equal":
            return _format(self.value(name))
        return var.values[var.index]

    def value(self, name):
        """The value as a number, as ``v_name`` reads it."""
        var = self._get(name)
        if var.style == "equal":
            if name in self._evaluating:
                cycle = " -> ".join(self._evaluating[self._evaluating.index(name):] + [name])
                raise ScriptError(f"variable {name} refers to itself ({cycle})")
            self._evaluating.append(name)
            try:
                return self.evaluate(var.values[0], name)
            finally:
                self._evaluating.pop()
        text = var.values[var.index]
        try:
            return float(text)
        except ValueError:
            # LAMMPS reads an index or string variable in a formula as a number, never as a formula
            raise ScriptError(f"variable {name} is not a number (got {text})") from None

    def _parse(self, expression, name=None):
        source = expression.replace("^", "**").replace("&&", " and ").replace("||", " or ")
        source = re.sub(r"!(?!=)", " not ", source)
        try:
            return ast.parse(source.strip(), mode="eval").body
        except SyntaxError:
            label = f"variable {name}: " if name else ""
            raise ScriptError(f"{label}cannot parse expression {expression!r}") from None

    def evaluate(self, expression, name=None):
        return float(self._eval(self._parse(expression, name), expression))

    def _eval(self, node, expression):
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            try:
                return float(node.value)
            except OverflowError:
                raise ScriptError(f"number too large in {expression!r}") from None
        if isinstance(node, ast.BinOp) and type(node.op) in BINARY:
            # doubles, as in LAMMPS: Python integers would make 10^10^10 a hang instead of an overflow
            left = float(self._eval(node.left, expression))
            right = float(self._eval(node.right, expression))
            try:
                return BINARY[type(node.op)](left, right)
            except ZeroDivisionError:
                raise ScriptError(f"division by zero in {expression!r}") from None
            except OverflowError:
                raise ScriptError(f"overflow in {expression!r}") from None
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd, ast.Not)):
            value = self._eval(node.operand, expression)
            return -value if isinstance(node.op, ast.USub) else (value if isinstance(node.op, ast.UAdd) else float(not value))
        if isinstance(node, ast.Compare) and len(node.ops) == 1 and type(node.ops[0]) in COMPARE:
            return float(COMPARE[type(node.ops[0])](self._eval(node.left, expression),
                                                    self._eval(node.comparators[0], expression)))
        if isinstance(node, ast.BoolOp):
            values = [bool(self._eval(v, expression)) for v in node.values]
            return float(all(values) if isinstance(node.op, ast.And) else any(values))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in FUNCTIONS:
            args = [self._eval(a, expression) for a in node.args]
            try:
                return FUNCTIONS[node.func.id](*args)
            except (ValueError, TypeError, OverflowError) as exc:
                raise ScriptError(f"{node.func.id}() in {expression!r}: {exc}") from None
        if isinstance(node, ast.Name):
            if node.id in CONSTANTS:
                return CONSTANTS[node.id]
            if node.id.startswith("v_"):
                return self.value(node.id[2:])
            return self._reader(node.id, ())
        if isinstance(node, ast.Subscript):
            indices = []
            while isinstance(node, ast.Subscript):
                indices.insert(0, int(self._eval(node.slice, expression)))
                node = node.value
            if isinstance(node, ast.Name):
                return self._reader(node.id, tuple(indices))
        raise ScriptError(f"unsupported expression {expression!r}")


def _format(value):
    """As LAMMPS substitutes a number: an integer when it is one, else 15 significant digits."""
    if float(value).is_integer() and abs(value) < 1e15:
        return str(int(value))
    return f"{float(value):.15g}"
