r"""Pair style ``formula``: a pair potential written as a formula of the distance r, differentiated
symbolically (sympy) and compiled by numba into the core's pair loop, so it runs at the speed of a
hand-written style (LAMMPS's ``pair python`` calls Python for every pair; ``pair lepton``
interprets its expression tree).

For each type pair the script gives the energy :math:`E(r)` (energy units) and its parameters; the
force is

.. math::

    \mathbf{F}_{ij} = -\frac{dE}{dr}\,\frac{\mathbf{r}_{ij}}{r}, \qquad r < r_c

How it is compiled: E is rewritten as a function of :math:`s = r^2` (or of :math:`u = 1/r^2` when
E holds only negative even powers of r, as Lennard-Jones does), so most formulas need no square
root; the force :math:`F/r = -2\,dE/ds` is derived from it. Products of parameters that do not
depend on r (:math:`4\varepsilon\sigma^{12}`) are computed once per type pair when a run starts, and
common subexpressions are shared. ``pair_modify shift yes`` subtracts :math:`E(r_c)`.

Formula syntax: numbers, ``r``, the parameter names given, ``+ - * / ^`` (or ``**``), parentheses
and the functions exp, log, sqrt, sin, cos, tan, sinh, cosh, tanh, erf, erfc, abs, min, max.
Anything else (an unknown name, an attribute, a string) is an error naming it. Quote the formula
so it stays one word.

Parameters:

- ``pair_style formula RC``: global cutoff (> 0, distance).
- ``pair_coeff I J "FORMULA" NAME VALUE ... [cutoff RC]``: the energy formula, then its parameters
  as name value pairs (units as the formula needs them), and optionally this pair's cutoff
  (distance). Every type pair must be given (no mixing).

Example (Lennard-Jones, as ``lj/cut``)::

    pair_style formula 2.5
    pair_coeff 1 1 "4*eps*((sig/r)^12 - (sig/r)^6)" eps 1.0 sig 1.0
    pair_coeff 1 2 "A*exp(-r/rho) - C/r^6" A 1000.0 rho 0.3 C 10.0 cutoff 3.0
"""

import ast
import hashlib
import math
from typing import NamedTuple

import sympy
from sympy.printing.pycode import PythonCodePrinter

from pdps_core.api import PairLaw, ScriptError, StyleArgs, keyword, param

FUNCTIONS = {"exp": sympy.exp, "log": sympy.log, "sqrt": sympy.sqrt, "sin": sympy.sin,
             "cos": sympy.cos, "tan": sympy.tan, "sinh": sympy.sinh, "cosh": sympy.cosh,
             "tanh": sympy.tanh, "erf": sympy.erf, "erfc": sympy.erfc, "abs": sympy.Abs,
             "min": sympy.Min, "max": sympy.Max}
RESERVED = {"r", "rsq", "u", "coeff", "math", "law", "cutoff"} | set(FUNCTIONS)


def parse_formula(text, names):
    """The sympy expression of ``text``, a formula of r and ``names``; only arithmetic and the
    functions above are accepted (checked on the syntax tree before sympy sees it)."""
    source = text.replace("^", "**")
    try:
        tree = ast.parse(source.strip(), mode="eval")
    except SyntaxError:
        raise ScriptError(f"cannot read formula {text!r}") from None
    allowed = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow,
               ast.USub, ast.UAdd, ast.Call, ast.Name, ast.Load, ast.Constant)
    for node in ast.walk(tree):
        if not isinstance(node, allowed):
            raise ScriptError(f"formula {text!r}: {type(node).__name__.lower()} is not allowed")
        if isinstance(node, ast.Constant) and not isinstance(node.value, (int, float)):
            raise ScriptError(f"formula {text!r}: {node.value!r} is not a number")
        if isinstance(node, ast.Call) and not (isinstance(node.func, ast.Name) and node.func.id in FUNCTIONS):
            name = node.func.id if isinstance(node.func, ast.Name) else ast.unparse(node.func)
            raise ScriptError(f"formula {text!r}: unknown function {name} (known: {', '.join(FUNCTIONS)})")
        if isinstance(node, ast.Name) and node.id not in FUNCTIONS and node.id != "r" and node.id not in names:
            raise ScriptError(f"formula {text!r}: unknown name {node.id} (give it as a parameter: "
                              f"NAME VALUE)")
    symbols = {name: sympy.Symbol(name, real=True) for name in names}
    symbols["r"] = sympy.Symbol("r", positive=True)
    return sympy.sympify(source, locals={**symbols, **FUNCTIONS}), symbols


class Compiled:
    """One formula compiled: the law's body for it, and how to fill its coefficient slots."""

    def __init__(self, expression, symbols, names):
        r = symbols["r"]
        s = sympy.Symbol("rsq", positive=True)
        u = sympy.Symbol("u", positive=True)
        energy = sympy.expand(expression.subs(r, sympy.sqrt(s)))
        fpair = sympy.expand(-2 * sympy.diff(energy, s))
        variable = s
        in_u = [sympy.expand(e.subs(s, 1 / u)) for e in (energy, fpair)]
        if all(_polynomial_in(e, u) for e in in_u):
            energy, fpair = in_u
            variable = u
        params = [symbols[n] for n in names]
        # split each expression into sum(factor(params) * part(r)): factors are computed per type pair
        self.factors, parts = [], []
        for expr in (energy, fpair):
            terms = {}
            for term in sympy.Add.make_args(expr):
                factor, part = term.as_independent(variable, as_Add=False)
                terms[part] = terms.get(part, 0) + factor
            slots = []
            for part, factor in terms.items():
                self.factors.append(sympy.lambdify(params, factor, "math"))
                slots.append((len(self.factors) - 1, part))
            parts.append(slots)
        self.names = names
        self.params = params
        self.variable = variable
        self.parts = parts
        self.energy_function = sympy.lambdify([r] + params, expression, "math")

    def factor_values(self, values):
        return [float(f(*values)) for f in self.factors]

    def body(self, base, raw_base, indent):
        """Python lines computing (fpair, energy) from rsq; factor k is coeff[base + k], raw
        parameter p is coeff[raw_base + p]."""
        slot = {}
        expressions = []
        for slots in self.parts:
            total = 0
            for k, part in slots:
                name = sympy.Symbol(f"c{k}", real=True)
                slot[name] = f"coeff[{base + k}]"
                total += name * part
            expressions.append(total)
        raw = {p: f"coeff[{raw_base + k}]" for k, p in enumerate(self.params)}
        shared, (energy, fpair) = sympy.cse(expressions, symbols=sympy.numbered_symbols("t"))
        printer = _Printer()
        lines = []
        if self.variable.name == "u":
            lines.append("u = 1.0 / rsq")
        if any(e.has(sympy.Symbol("rsq", positive=True)) for e in [energy, fpair] + [v for _, v in shared]):
            lines.append("r = math.sqrt(rsq)")
        for name, value in shared:
            lines.append(f"{name} = {printer.doprint(value)}")
        lines.append(f"energy = {printer.doprint(energy)}")
        lines.append(f"fpair = {printer.doprint(fpair)}")
        text = "\n".join(lines)
        for symbol, code in {**slot, **raw}.items():
            text = _replace_name(text, symbol.name, code)
        return [indent + line for line in text.splitlines()]


def _polynomial_in(expr, u):
    """True when expr is a sum of non-negative integer powers of u times u-free factors."""
    for term in sympy.Add.make_args(expr):
        _, part = term.as_independent(u, as_Add=False)
        if part == 1:
            continue
        base, exponent = part.as_base_exp()
        if base != u or not (exponent.is_Integer and exponent > 0):
            return False
    return True


def _replace_name(text, name, code):
    import re
    return re.sub(rf"\b{re.escape(name)}\b", code, text)


class _Printer(PythonCodePrinter):
    """Python code for numba: math functions, and sqrt(rsq) as r."""

    def _print_Pow(self, expr, rational=False):
        base, exponent = expr.as_base_exp()
        if base == sympy.Symbol("rsq", positive=True) and exponent == sympy.Rational(1, 2):
            return "r"
        if base == sympy.Symbol("rsq", positive=True) and exponent == -sympy.Rational(1, 2):
            return "(1.0 / r)"
        if exponent.is_Integer:
            # integer powers stay integer literals: numba multiplies them out
            return f"{self.parenthesize(base, 100)}**{int(exponent)}"
        return super()._print_Pow(expr, rational)


_parsed = {}


def parsed_formula(coeff):
    """(expression, symbols, parameter names, {name: value}) of a pair_coeff's formula and parameters."""
    key = (coeff.formula, tuple(coeff.parameters))
    if key in _parsed:
        return _parsed[key]
    values = {}
    for name, value in coeff.parameters:
        if not name.isidentifier() or name in RESERVED:
            raise ScriptError(f"{name!r} cannot name a parameter")
        if name in values:
            raise ScriptError(f"parameter {name} is given twice")
        values[name] = value
    names = list(values)
    expression, symbols = parse_formula(coeff.formula, names)
    if not expression.has(symbols["r"]):
        raise ScriptError(f"formula {coeff.formula!r} does not depend on r: it has no force")
    _parsed[key] = (expression, symbols, names, values)
    return _parsed[key]


class Parameter(NamedTuple):
    """One ``NAME VALUE`` of a pair_coeff: a name the formula uses and its value."""
    name: str
    value: float


class PairFormula(PairLaw):
    name = "formula"
    usage = "pair_style formula RC"
    coeff_usage = '"FORMULA" NAME VALUE ... [cutoff RC]'

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")

    class Coeff(StyleArgs):
        formula: str = param()
        parameters: list[Parameter] = param(default_factory=list, unit=("1", "as the formula"))
        cutoff: float | None = keyword(None, gt=0, unit="distance")

    def parse_coeff(self, words):
        coeff = super().parse_coeff(words)
        parsed_formula(coeff)          # every error at pair_coeff, where the line is known
        return coeff

    def init(self, ntypes):
        # one compiled body per distinct formula; a type pair selects its body by coeff[0]
        formulas = {}
        for coeff in self.coeffs.values():
            expression, symbols, names, _ = parsed_formula(coeff)
            key = (coeff.formula, tuple(names))
            if key not in formulas:
                formulas[key] = Compiled(expression, symbols, names)
        self.compiled = formulas
        self.order = list(formulas)
        width = max(len(c.factors) + len(c.names) for c in formulas.values()) if formulas else 0
        self.params = tuple(f"slot{k}" for k in range(2 + width))
        self.law_source = self._source(width)
        return super().init(ntypes)

    def _source(self, width):
        lines = ["import math", "", "from numba import njit", "", "",
                 '@njit(cache=True, inline="always")',
                 "def law(rsq, dx, dy, dz, coeff, i, j, atom, state):"]
        for k, key in enumerate(self.order):
            compiled = self.compiled[key]
            keyword = "if" if k == 0 else "elif"
            indent = "    "
            if len(self.order) > 1:
                lines.append(f"    {keyword} coeff[0] == {k}:")
                indent = "        "
            lines += compiled.body(2, 2 + len(compiled.factors), indent)
        if len(self.order) > 1:
            lines += ["    else:", "        fpair = 0.0", "        energy = 0.0"]
        lines.append("    return fpair, energy - coeff[1]")
        text = "\n".join(lines) + "\n"
        return f"# formulas {hashlib.sha256(text.encode()).hexdigest()[:12]}\n" + text

    def init_one(self, i, j):
        coeff = self.resolved[(i, j)]
        expression, symbols, names, values = parsed_formula(coeff)
        key = (coeff.formula, tuple(names))
        compiled = self.compiled[key]
        cutoff = coeff.cutoff if coeff.cutoff is not None else self.args.cutoff
        parameters = [values[n] for n in names]
        try:
            factors = compiled.factor_values(parameters)
            shift = float(compiled.energy_function(cutoff, *parameters)) if self.shift else 0.0
        except (ValueError, ZeroDivisionError, OverflowError) as exc:
            raise ScriptError(f"pair_coeff {i} {j}: formula {coeff.formula!r} cannot be evaluated "
                              f"with these parameters ({exc})") from None
        slots = [float(self.order.index(key)), shift] + factors + parameters
        slots += [0.0] * (len(self.params) - len(slots))
        if not all(math.isfinite(v) for v in slots):
            raise ScriptError(f"pair_coeff {i} {j}: formula {coeff.formula!r} gives a non-finite "
                              "coefficient with these parameters")
        return cutoff, slots
