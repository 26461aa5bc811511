"""Formulas of ``equal``, ``atom`` and ``vector`` variables, in LAMMPS's grammar, parsed once and
evaluated as often as they are read.

Grammar (LAMMPS's variable page): numbers, constants (``PI``, ``version``, ``on``/``off``,
``true``/``false``, ``yes``/``no``), thermo keywords, ``c_ID``, ``c_ID[i]``, ``c_ID[i][j]``, ``f_ID...``,
``v_NAME``, ``v_NAME[i]``, atom values (``x[23]``: the x of particle 23), atom vectors (``x``, ``vx``,
``mass``, ``type``, ``id``... in atom-style formulas), math, group and special functions, and the
operators, from the tightest binding to the loosest, each level left to right:

====================  ==========================
unary ``-`` ``!``     ``-2^2`` is ``(-2)^2`` = 4
``^``                 ``2^3^2`` is ``(2^3)^2`` = 64
``*`` ``/`` ``%``     ``%`` is C's fmod: ``-7%3`` = -1
``+`` ``-``
``<`` ``<=`` ``>`` ``>=``
``==`` ``!=``
``&&``
``||`` ``|^``         ``|^`` is exclusive or
====================  ==========================

Comparisons and logic give 1 or 0. Values are doubles. Division and modulo by zero, ``0^-1``, the
square root of a negative number and the logarithm of one <= 0 are errors naming the formula, as in
LAMMPS.

An expression compiles to nested Python closures over an ``env`` (the simulation's view, see
``Variables``); evaluated with per-atom vectors (atom-style) the same closures work elementwise on
numpy arrays.
"""

import math
import operator
import re

import numpy as np

from ..errors import ScriptError

VERSION = 20250722          # what ``version`` gives: the LAMMPS release whose grammar this follows
CONSTANTS = {"PI": math.pi, "version": float(VERSION), "on": 1.0, "off": 0.0, "true": 1.0,
             "false": 0.0, "yes": 1.0, "no": 0.0}
ATOM_NAMES = ("id", "mass", "type", "mol", "radius", "q", "x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz")

TOKEN = re.compile(r"""
    (?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)
  | (?P<name>[A-Za-z_][A-Za-z0-9_]*)
  | (?P<op>\|\^|&&|\|\||==|!=|<=|>=|[-+*/^%!<>(),\[\]])
  | (?P<space>\s+)
""", re.VERBOSE)

# binary operators by level, loosest first; every level is left-associative
LEVELS = [("||", "|^"), ("&&",), ("==", "!="), ("<", "<=", ">", ">="), ("+", "-"), ("*", "/", "%"), ("^",)]
PRECEDENCE = {op: level for level, ops in enumerate(LEVELS) for op in ops}
# Parentheses and function calls nested deeper than this are refused: each level costs the parser a
# few Python frames, and the limit keeps them well inside Python's recursion limit (LAMMPS took 100
# and 10,000 levels in a check with LAMMPS 22 Jul 2025; it refuses --3, which reads here as 3).
MAX_NESTING = 128


class FormulaError(ScriptError):
    pass


def _tokens(text):
    tokens, at = [], 0
    while at < len(text):
        match = TOKEN.match(text, at)
        if match is None:
            raise FormulaError(f"unexpected character {text[at]!r} in formula {text!r}")
        kind = match.lastgroup
        if kind != "space":
            tokens.append((kind, match.group(kind)))
        at = match.end()
    tokens.append(("end", ""))
    return tokens


class Expression:
    """A formula parsed into a closure; ``evaluate(env)`` reads it now."""

    def __init__(self, text):
        self.text = text.strip()
        if not self.text:
            raise FormulaError("empty formula")
        self._tokens = _tokens(self.text)
        self._at = 0
        self._depth = 0                 # parentheses and function calls open around the parser
        self.atom_vectors = False       # reads per-atom vectors: only atom-style variables may
        self.closure = self._expression()
        if self._peek()[0] != "end":
            self._fail(f"unexpected {self._peek()[1]!r}")
        del self._tokens

    def evaluate(self, env):
        with np.errstate(all="ignore"):
            return self.closure(env)

    # ---- parsing ------------------------------------------------------------------------------
    def _peek(self):
        return self._tokens[self._at]

    def _take(self):
        token = self._tokens[self._at]
        self._at += 1
        return token

    def _expect(self, op):
        kind, value = self._take()
        if (kind, value) != ("op", op):
            self._fail(f"expected {op!r}, got {value or 'the end'!r}")

    def _fail(self, message):
        raise FormulaError(f"{message} in formula {self.text!r}")

    def _expression(self):
        """Binary operators by precedence climbing over an operand stack: a run of operators of one
        level (1+2+3+...) becomes one closure that folds left to right, so neither parsing nor
        evaluating a long formula recurses once per operator."""
        operands, operators = [self._unary()], []
        while self._peek()[0] == "op" and self._peek()[1] in PRECEDENCE:
            op = self._take()[1]
            level = PRECEDENCE[op]
            while operators and operators[-1][1] >= level:
                self._reduce(operands, operators)
            operators.append((op, level))
            operands.append(self._unary())
        while operators:
            self._reduce(operands, operators)
        return _closure(operands[0])

    def _reduce(self, operands, operators):
        op, level = operators.pop()
        right = _closure(operands.pop())
        left = operands.pop()
        if not (isinstance(left, _Chain) and left.level == level):
            left = _Chain(level, _closure(left))
        left.rest.append((self._operator(op), right))
        operands.append(left)

    def _unary(self):
        """Prefix - ! + (any number of them, read in a loop) before a primary."""
        prefix = []
        while self._peek()[0] == "op" and self._peek()[1] in ("-", "!", "+"):
            op = self._take()[1]
            if op != "+":
                prefix.append(op)
        operand = self._primary()
        if not prefix:
            return operand
        if prefix == ["-"]:
            return lambda env: -operand(env)
        innermost_first = tuple(reversed(prefix))

        def unary(env):
            value = operand(env)
            for op in innermost_first:
                value = -value if op == "-" else _truth(_equal(value, 0.0))
            return value
        return unary

    def _primary(self):
        kind, value = self._take()
        if kind == "number":
            number = float(value)
            if not math.isfinite(number):
                self._fail(f"number {value} out of range")
            return lambda env: number
        if kind == "op" and value == "(":
            self._nest()
            inner = self._expression()
            self._expect(")")
            self._depth -= 1
            return inner
        if kind == "name":
            return self._named(value)
        self._fail(f"unexpected {value or 'end'!r}")

    def _nest(self):
        self._depth += 1
        if self._depth > MAX_NESTING:
            self._fail(f"parentheses and function calls nested more than {MAX_NESTING} deep")

    def _indices(self):
        indices = []
        while self._peek() == ("op", "["):
            self._take()
            kind, value = self._take()
            if kind != "number" or not value.isdigit():
                self._fail(f"an index must be a whole number (got {value!r})")
            self._expect("]")
            indices.append(int(value))
        return tuple(indices)

    def _arguments(self):
        """Function arguments as raw closures and as words (group, region, dimension names)."""
        self._expect("(")
        self._nest()
        args = []
        if self._peek() == ("op", ")"):
            self._take()
            self._depth -= 1
            return args
        while True:
            start = self._at
            token = self._peek()
            closure = self._expression()
            taken = self._tokens[start:self._at]
            # the argument's text where it is one reference: NAME, or NAME[N] (a column of an array)
            word = token[1] if len(taken) == 1 and token[0] == "name" else None
            if (len(taken) == 4 and token[0] == "name" and taken[1] == ("op", "[") and taken[2][0] == "number"
                    and taken[3] == ("op", "]")):
                word = f"{token[1]}[{taken[2][1]}]"
            args.append((closure, word))
            kind, value = self._take()
            if (kind, value) == ("op", ")"):
                self._depth -= 1
                return args
            if (kind, value) != ("op", ","):
                self._fail(f"expected ',' or ')', got {value or 'the end'!r}")

    def _group_arguments(self):
        """A group function's arguments: words (a group, a dimension, a region), never values, so
        that ``xcm(all,x)`` reads no atom vector x."""
        self._expect("(")
        words = []
        while True:
            kind, value = self._take()
            if kind not in ("name", "number"):
                self._fail(f"expected a group, dimension or region ID, got {value or 'the end'!r}")
            words.append(value)
            kind, value = self._take()
            if (kind, value) == ("op", ")"):
                return words
            if (kind, value) != ("op", ","):
                self._fail(f"expected ',' or ')', got {value or 'the end'!r}")

    def _named(self, name):
        if self._peek() == ("op", "(") and name in GROUP_FUNCTIONS:
            return self._group_function(name, self._group_arguments())
        if self._peek() == ("op", "("):
            return self._function(name, self._arguments())
        prefix = name[:2]
        if prefix in ("c_", "f_", "v_") and len(name) > 2:
            indices = self._indices()
            ident = name[2:]
            return lambda env: env.reference(prefix[0], ident, indices)
        if self._peek() == ("op", "["):
            indices = self._indices()
            if name not in ATOM_NAMES or len(indices) != 1:
                self._fail(f"{name}[...] is not an atom value (atom values: {', '.join(ATOM_NAMES)})")
            tag = indices[0]
            return lambda env: env.atom_value(name, tag)
        if name in CONSTANTS:
            constant = CONSTANTS[name]
            return lambda env: constant
        if name in ATOM_NAMES:
            # an atom vector: only meaningful per atom (atom-style); checked when read
            self.atom_vectors = True
            return lambda env: env.atom_vector(name)
        return lambda env: env.thermo(name)

    # ---- operators ------------------------------------------------------------------------------
    def _operator(self, op):
        """The function of two values ``op`` stands for (numbers, or numpy arrays per atom)."""
        text = self.text
        if op == "+":
            return operator.add
        if op == "-":
            return operator.sub
        if op == "*":
            return operator.mul
        if op == "/":
            def divide(a, b):
                if np.any(np.asarray(b) == 0.0):
                    raise FormulaError(f"divide by 0 in formula {text!r}")
                return a / b
            return divide
        if op == "%":
            def modulo(a, b):
                if np.any(np.asarray(b) == 0.0):
                    raise FormulaError(f"modulo 0 in formula {text!r}")
                return np.fmod(a, b)
            return modulo
        if op == "^":
            def power(a, b):
                if np.ndim(a) or np.ndim(b):
                    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
                    if np.any((a == 0.0) & (b < 0.0)):
                        raise FormulaError(f"0 to a negative power in formula {text!r}")
                    if np.any((a < 0.0) & (b != np.floor(b))):
                        raise FormulaError(f"a negative number to a fractional power in formula {text!r}")
                    return np.where(b == 0.0, 1.0, np.power(a, b))
                if b == 0.0:
                    return 1.0
                if a == 0.0 and b < 0.0:
                    raise FormulaError(f"0 to a negative power in formula {text!r}")
                if a < 0.0 and not float(b).is_integer():
                    raise FormulaError(f"a negative number to a fractional power in formula {text!r}")
                return float(np.power(float(a), float(b)))
            return power
        compare = {"<": np.less, "<=": np.less_equal, ">": np.greater, ">=": np.greater_equal,
                   "==": _equal, "!=": np.not_equal}
        if op in compare:
            function = compare[op]
            return lambda a, b: _truth(function(a, b))
        if op == "&&":
            return lambda a, b: _truth(np.logical_and(_nonzero(a), _nonzero(b)))
        if op == "||":
            return lambda a, b: _truth(np.logical_or(_nonzero(a), _nonzero(b)))
        return lambda a, b: _truth(np.logical_xor(_nonzero(a), _nonzero(b)))

    # ---- functions --------------------------------------------------------------------------------
    def _function(self, name, args):
        text = self.text
        closures = [a for a, _ in args]
        words = [w for _, w in args]

        def arity(*counts):
            if len(args) not in counts:
                expected = " or ".join(map(str, counts))
                self._fail(f"{name}() takes {expected} argument(s), got {len(args)}")

        if name in MATH1:
            arity(1)
            function, domain, complaint = MATH1[name]
            (a,) = closures

            def math1(env):
                x = a(env)
                if domain is not None and not np.all(domain(np.asarray(x))):
                    raise FormulaError(f"{complaint} in {name}() in formula {text!r}")
                return function(x)
            return math1
        if name == "atan2":
            arity(2)
            y, x = closures
            return lambda env: np.arctan2(y(env), x(env))
        if name == "ternary":
            arity(3)
            test, yes, no = closures

            def ternary(env):
                value = test(env)
                if np.ndim(value):
                    return np.where(_nonzero(value), yes(env), no(env))
                return yes(env) if value != 0.0 else no(env)
            return ternary
        if name in TIME_FUNCTIONS:
            arity(TIME_FUNCTIONS[name][0])
            function = TIME_FUNCTIONS[name][1]
            return lambda env: function(env, *[c(env) for c in closures])
        if name in ("min", "max") and not (len(args) == 1 and words[0] and words[0][:2] in ("c_", "f_", "v_")):
            # min(x, y, ...) of numbers (a pdps extension; LAMMPS's min() takes a vector reference)
            if not args:
                self._fail(f"{name}() needs arguments")
            pick = np.minimum if name == "min" else np.maximum

            def extreme(env):
                values = [c(env) for c in closures]
                result = values[0]
                for value in values[1:]:
                    result = pick(result, value)
                return result
            return extreme
        if name in ("sum", "min", "max", "ave", "trap", "slope"):
            arity(1)
            reference = self._reference_word(args[0], name)
            return lambda env: env.vector_reduce(name, *reference)
        if name in ("gmask", "rmask", "grmask"):
            arity({"gmask": 1, "rmask": 1, "grmask": 2}[name])
            if None in words:
                self._fail(f"{name}() takes group and region IDs")
            self.atom_vectors = True
            return lambda env: env.mask_function(name, words)
        self._fail(f"unknown function {name}()")

    def _group_function(self, name, words):
        low, high = GROUP_FUNCTIONS[name]
        if not low <= len(words) <= high:
            expected = " or ".join(map(str, range(low, high + 1)))
            self._fail(f"{name}() takes {expected} argument(s), got {len(words)}")
        group, rest = words[0], words[1:]
        return lambda env: env.group_function(name, group, rest)

    def _reference_word(self, arg, name):
        # sum(c_ID) and the like take a reference, not a value: re-read it from the source text
        closure, word = arg
        if word is None or word[:2] not in ("c_", "f_", "v_") or (word.endswith("]") and word[0] == "v"):
            self._fail(f"{name}() takes a compute, fix or vector-variable reference (c_ID, f_ID, c_ID[i], f_ID[i], "
                       "v_NAME)")
        ident, _, column = word[2:].partition("[")
        return word[0], ident, int(column[:-1]) if column else None


class _Chain:
    """Operands of one precedence level joined left to right while parsing: first, then (operator,
    operand) pairs."""

    def __init__(self, level, first):
        self.level, self.first, self.rest = level, first, []


def _closure(node):
    """A parsed operand as the closure that evaluates it."""
    if not isinstance(node, _Chain):
        return node
    first, rest = node.first, tuple(node.rest)
    if len(rest) == 1:
        (function, second), = rest
        return lambda env: function(first(env), second(env))

    def chain(env):
        value = first(env)
        for function, operand in rest:
            value = function(value, operand(env))
        return value
    return chain


def _equal(a, b):
    return np.equal(a, b)


def _nonzero(value):
    return np.not_equal(value, 0.0)


def _truth(value):
    return np.asarray(value, dtype=np.float64) if np.ndim(value) else (1.0 if value else 0.0)


def _round(x):
    return np.floor(np.asarray(x) + 0.5) if np.ndim(x) else float(math.floor(x + 0.5))


MATH1 = {
    "sqrt": (np.sqrt, lambda x: x >= 0.0, "a negative value"),
    "exp": (np.exp, None, ""),
    "ln": (np.log, lambda x: x > 0.0, "a value <= 0"),
    "log": (np.log10, lambda x: x > 0.0, "a value <= 0"),
    "abs": (np.abs, None, ""),
    "sin": (np.sin, None, ""), "cos": (np.cos, None, ""), "tan": (np.tan, None, ""),
    "asin": (np.arcsin, lambda x: np.abs(x) <= 1.0, "a value beyond [-1, 1]"),
    "acos": (np.arccos, lambda x: np.abs(x) <= 1.0, "a value beyond [-1, 1]"),
    "atan": (np.arctan, None, ""),
    "ceil": (np.ceil, None, ""), "floor": (np.floor, None, ""),
    "round": (_round, None, ""),
    "sign": (lambda x: np.where(np.asarray(x) >= 0.0, 1.0, -1.0) if np.ndim(x) else (1.0 if x >= 0.0 else -1.0),
             None, ""),
}


# functions of the timestep (LAMMPS: the current step, the run's first and last step, dt)
def _ramp(env, x, y):
    first, last = env.run_bounds()
    fraction = 0.0 if last == first else (env.step() - first) / (last - first)
    return x + (y - x) * fraction


def _stagger(env, x, y):
    every, offset = int(x), int(y)
    if every <= 0 or not 0 <= offset < every:
        raise FormulaError(f"stagger({x:g},{y:g}): needs x > 0 and 0 <= y < x")
    step = env.step()
    lower = step // every * every
    return float(lower + offset if step - lower < offset else lower + every)


def _logfreq(env, x, y, z):
    first, count, factor = int(x), int(y), int(z)
    if first <= 0 or count <= 0 or factor <= 1 or count >= factor:
        raise FormulaError(f"logfreq({x:g},{y:g},{z:g}): needs x > 0, y > 0, z > 1 and y < z")
    step = env.step()
    if step < first:
        return float(first)
    lower = first
    while step >= factor * lower:
        lower *= factor
    multiple = step // lower
    return float((multiple + 1) * lower if multiple < count else lower * factor)


def _stride(env, x, y, z):
    start, stop, every = int(x), int(y), int(z)
    if start < 0 or stop <= start or every <= 0:
        raise FormulaError(f"stride({x:g},{y:g},{z:g}): needs 0 <= x < y and z > 0")
    step = env.step()
    if step < start:
        return float(start)
    if step < stop:
        value = start + (step - start) // every * every + every
        return float(value) if value <= stop else float(2 ** 63 - 1)
    return float(2 ** 63 - 1)


def _elapsed_time(env):
    first, _ = env.run_bounds()
    return env.dt() * (env.step() - first)


def _vdisplace(env, x, y):
    return x + y * _elapsed_time(env)


def _swiggle(env, x, y, z):
    if z <= 0.0:
        raise FormulaError(f"swiggle(): the period must be > 0 (got {z:g})")
    return x + y * math.sin(2.0 * math.pi / z * _elapsed_time(env))


def _cwiggle(env, x, y, z):
    if z <= 0.0:
        raise FormulaError(f"cwiggle(): the period must be > 0 (got {z:g})")
    return x + y * (1.0 - math.cos(2.0 * math.pi / z * _elapsed_time(env)))


TIME_FUNCTIONS = {"ramp": (2, _ramp), "stagger": (2, _stagger), "logfreq": (3, _logfreq),
                  "stride": (3, _stride), "vdisplace": (2, _vdisplace), "swiggle": (3, _swiggle),
                  "cwiggle": (3, _cwiggle)}

# group functions: (fewest, most arguments), the group ID first, then a dimension and/or a region ID
GROUP_FUNCTIONS = {"count": (1, 2), "mass": (1, 2), "charge": (1, 2), "xcm": (2, 3), "vcm": (2, 3),
                   "fcm": (2, 2), "bound": (2, 3), "gyration": (1, 2), "ke": (1, 2)}
