"""Script variables, as LAMMPS's ``variable`` command defines them.

Styles:

- ``index V1 V2 ...``, ``loop N [pad]``, ``loop N1 N2 [pad]``, ``universe V1 V2 ...``, ``uloop N [pad]``:
  a list of strings stepped by ``next``; once defined (by ``-var`` on the command line, or earlier in
  the script) a later definition of the same name is ignored, as in LAMMPS.
- ``world V``: one value per partition (pdps runs one partition).
- ``string TEXT``, ``getenv NAME``, ``format VAR FORMAT``, ``internal VALUE``, ``file FILE`` (one value per
  non-comment line, stepped by ``next``).
- ``equal FORMULA`` (a number, evaluated each time it is read), ``atom FORMULA`` (one number per
  particle), ``vector FORMULA`` or ``vector [1,2,3]`` (a global vector).
- ``delete``.

Formulas follow LAMMPS's grammar (pdps_core.script.expression) and are parsed once, when defined.
``${NAME}`` substitutes an equal-style value with 15 significant digits, ``$(FORMULA)`` with 20
(``$(FORMULA:%.3f)`` with the format given), as LAMMPS does. Redefining a variable as another style
is an error unless it is deleted first.
"""

import math
import os
import re

import numpy as np

from ..errors import ScriptError
from .expression import Expression, FormulaError

NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
LISTS = ("index", "loop", "universe", "uloop", "world", "file")
REDEFINABLE = ("string", "getenv", "format", "internal", "file", "equal", "atom", "vector")
STYLES = LISTS + ("string", "getenv", "format", "internal", "equal", "atom", "atomfile", "vector", "delete")
C_FORMAT = re.compile(r"^%[-+ #0]*\d*(?:\.\d+)?[eEfgG]$")


class Variable:
    def __init__(self, name, style, values, formula=None):
        self.name, self.style, self.values, self.formula, self.index = name, style, values, formula, 0


class Variables:
    """The variables of one simulation. ``context(per_atom=False)`` gives what formulas read (a
    pdps_core.script.context.FormulaContext of the simulation)."""

    def __init__(self, context):
        self._vars = {}
        self._context = context
        self._evaluating = []      # variables being evaluated, to catch cycles

    def __contains__(self, name):
        return name in self._vars

    def names(self):
        return list(self._vars)

    def style(self, name):
        """The variable's style as its readers take it: an atomfile variable is an atom-style one
        (its values per particle, from a file), as LAMMPS reads it wherever atom-style is."""
        style = self._get(name).style
        return "atom" if style == "atomfile" else style

    def signature(self):
        """Every variable's definition and position, to tell one state of a script loop from another."""
        return tuple(sorted((name, var.style, var.index, str(var.values)) for name, var in self._vars.items()))

    # ---- definition --------------------------------------------------------------------------------
    def define(self, words, from_command_line=False):
        if len(words) < 2:
            raise ScriptError("expected: variable NAME STYLE ARGS")
        name, style, args = words[0], words[1], list(words[2:])
        if not NAME.match(name):
            raise ScriptError(f"variable name must be letters, digits and _ (got {name})")
        if style not in STYLES:
            raise ScriptError(f"unknown variable style {style} (known: {', '.join(STYLES)})")
        if style == "delete":
            if args:
                raise ScriptError("variable NAME delete takes no more arguments")
            self._vars.pop(name, None)
            return
        if not args:
            raise ScriptError(f"variable {name} {style} needs a value")
        existing = self._vars.get(name)
        if existing is not None and style in ("index", "loop", "universe", "uloop", "world"):
            return  # LAMMPS: a variable, once set (e.g. by -var), keeps its value
        if existing is not None and (existing.style != style or style not in REDEFINABLE):
            # LAMMPS refuses too: silently replacing it would lose a -var value
            raise ScriptError(f"variable {name} is already defined as {existing.style}; it cannot become "
                              f"{style} (use variable {name} delete first)")
        self._vars[name] = self._make(name, style, args)

    def _make(self, name, style, args):
        if style in ("index", "universe"):
            return Variable(name, style, args)
        if style in ("loop", "uloop"):
            return Variable(name, style, _loop_values(name, args))
        if style == "world":
            if len(args) != 1:
                raise ScriptError(f"variable {name} world: {len(args)} values for 1 partition")
            return Variable(name, style, args)
        if style == "getenv":
            _one(name, style, args)
            return Variable(name, style, [os.environ.get(args[0], "")])
        if style == "string":
            return Variable(name, style, [" ".join(args)])
        if style == "internal":
            _one(name, style, args)
            return Variable(name, style, [_number(args[0], f"variable {name} internal")])
        if style == "format":
            if len(args) != 2:
                raise ScriptError(f"variable {name} format takes an equal-style variable and a format "
                                  f"(got {' '.join(args)})")
            if not C_FORMAT.match(args[1]):
                raise ScriptError(f"variable {name} format: {args[1]} is not a floating-point format "
                                  "such as %.6g, %10.4f or %e")
            return Variable(name, style, args)
        if style == "file":
            return Variable(name, style, _file_values(name, args))
        if style == "atomfile":
            return Variable(name, style, _atomfile_sets(name, args))
        formula_text = " ".join(args)
        if style == "vector" and formula_text.startswith("["):
            return Variable(name, style, [_vector_literal(name, formula_text)])
        try:
            formula = Expression(formula_text)
        except FormulaError as exc:
            raise ScriptError(f"variable {name}: {exc.message}") from None
        if formula.atom_vectors and style == "equal":
            raise ScriptError(f"variable {name}: an equal-style formula cannot read atom vectors "
                              f"(atom-style: variable {name} atom ...) in {formula_text!r}")
        return Variable(name, style, [formula_text], formula)

    def next(self, name):
        """Step a list variable; False when it is exhausted (and then deleted), as LAMMPS's next."""
        var = self._get(name)
        if var.style not in LISTS + ("atomfile",):
            raise ScriptError(f"next works only on index, loop, universe, uloop, world, file and atomfile "
                              f"variables ({name} is {var.style})")
        var.index += 1
        if var.index >= len(var.values):
            del self._vars[name]
            return False
        return True

    def set_internal(self, name, value):
        var = self._get(name)
        if var.style != "internal":
            raise ScriptError(f"variable {name} is {var.style}, not internal")
        var.values[0] = float(value)

    # ---- reading -----------------------------------------------------------------------------------
    def _get(self, name):
        try:
            return self._vars[name]
        except KeyError:
            raise ScriptError(f"undefined variable {name}") from None

    def text(self, name):
        """The value as text, as ``${name}`` substitutes it; ``(formula)`` and ``(formula:format)``
        are immediate formulas (``$(...)``)."""
        if name.startswith("("):
            body = name[1:-1]
            formula, _, fmt = body.rpartition(":") if _has_format(body) else (body, "", "")
            value = self.evaluate(formula)
            return _c_format(fmt, value) if fmt else f"{value:.20g}"
        var = self._get(name)
        if var.style == "equal":
            return f"{self.value(name):.15g}"
        if var.style == "internal":
            return f"{var.values[0]:.15g}"
        if var.style == "format":
            return _c_format(var.values[1], self.value(var.values[0]))
        if var.style in ("atom", "atomfile", "vector"):
            raise ScriptError(f"${{{name}}}: variable {name} is {var.style}-style, not a single value")
        return str(var.values[var.index])

    def value(self, name):
        """The value as a number, as ``v_name`` reads it in an equal-style formula."""
        var = self._get(name)
        if var.style == "equal":
            return float(self._evaluate_var(var, per_atom=False))
        if var.style == "internal":
            return float(var.values[0])
        if var.style == "format":
            return self.value(var.values[0])
        if var.style in ("atom", "atomfile", "vector"):
            raise ScriptError(f"v_{name} is {var.style}-style: name one element, v_{name}[i]")
        text = var.values[var.index]
        try:
            return float(text)
        except ValueError:
            # LAMMPS reads an index or string variable in a formula as a number, never as a formula
            raise ScriptError(f"variable {name} is not a number (got {text})") from None

    def read(self, name, indices=(), per_atom=False, index_base=1):
        """``v_NAME`` or ``v_NAME[i]`` as a formula reads it: a number, or per particle in an
        atom-style formula. ``i`` counts from ``index_base`` (the dialect's)."""
        var = self._get(name)
        if not indices:
            if var.style in ("atom", "atomfile"):
                if not per_atom:
                    raise ScriptError(f"v_{name} is atom-style: an equal-style formula reads one "
                                      f"particle's value as v_{name}[ID]")
                return self.atom_values(name)
            if var.style == "vector":
                raise ScriptError(f"v_{name} is vector-style: name one element, v_{name}[i]")
            return self.value(name)
        if len(indices) != 1:
            raise ScriptError(f"v_{name}{''.join(f'[{i}]' for i in indices)}: a variable takes one index")
        (i,) = indices
        if var.style == "vector":
            values = self.vector(name)
            k = i - index_base
            if not 0 <= k < len(values):
                raise ScriptError(f"v_{name}[{i}] is out of range (vector {name} has {len(values)} "
                                  f"values, from {index_base})")
            return float(values[k])
        if var.style in ("atom", "atomfile"):
            context = self._context(per_atom=False)
            values = self.atom_values(name)
            sim = context.sim
            rows = np.flatnonzero(sim.particles.tag[:sim.particles.nlocal] == i)
            found = sim.comm.sum(len(rows))
            if found != 1:
                raise ScriptError(f"v_{name}[{i}]: there is no particle with id {i}")
            return float(sim.comm.sum(float(values[rows[0]]) if len(rows) else 0.0))
        raise ScriptError(f"v_{name}[{i}]: variable {name} is {var.style}-style, which has no elements")

    def atom_values(self, name):
        """An atom-style variable: one number per owned particle."""
        var = self._get(name)
        if var.style == "atomfile":
            sim = self._context(per_atom=True).sim
            ids, values = var.values[var.index]
            tags = sim.particles.tag[:sim.particles.nlocal]
            # particles the file does not list read 0, as LAMMPS's
            at = np.searchsorted(ids, tags)
            listed = (at < len(ids)) & (ids[np.minimum(at, len(ids) - 1)] == tags)
            return np.where(listed, values[np.minimum(at, len(ids) - 1)], 0.0)
        if var.style != "atom":
            value = self.value(name)
            context = self._context(per_atom=True)
            return np.full(context.sim.particles.nlocal, value)
        values = self._evaluate_var(var, per_atom=True)
        n = self._context(per_atom=True).sim.particles.nlocal
        return np.broadcast_to(np.asarray(values, dtype=np.float64), (n,)).copy()

    def vector(self, name):
        var = self._get(name)
        if var.style != "vector":
            raise ScriptError(f"variable {name} is {var.style}-style, not a vector")
        if var.formula is None:
            return var.values[0]
        values = self._evaluate_var(var, per_atom=False, vector=True)
        return np.atleast_1d(np.asarray(values, dtype=np.float64))

    def evaluate(self, formula_text, name=None):
        """An immediate formula (``$(...)``, ``print``): parsed and read now."""
        try:
            formula = Expression(formula_text)
        except FormulaError as exc:
            label = f"variable {name}: " if name else ""
            raise ScriptError(f"{label}{exc.message}") from None
        return float(self._finite(formula.evaluate(self._context(per_atom=False)), formula_text))

    def _evaluate_var(self, var, per_atom, vector=False):
        if var.name in self._evaluating:
            cycle = " -> ".join(self._evaluating[self._evaluating.index(var.name):] + [var.name])
            raise ScriptError(f"variable {var.name} refers to itself ({cycle})")
        self._evaluating.append(var.name)
        try:
            context = self._context(per_atom=per_atom, vector=vector)
            return self._finite(var.formula.evaluate(context), var.values[0], var.name)
        finally:
            self._evaluating.pop()

    @staticmethod
    def _finite(value, formula_text, name=None):
        if not np.all(np.isfinite(value)):
            label = f"variable {name}: " if name else ""
            raise ScriptError(f"{label}formula {formula_text!r} gives a non-finite value")
        return value


def _one(name, style, args):
    if len(args) != 1:
        raise ScriptError(f"variable {name} {style} takes one value (got {' '.join(args)})")


def _number(word, what):
    try:
        value = float(word)
    except ValueError:
        raise ScriptError(f"{what} must be a number (got {word})") from None
    if not math.isfinite(value):
        raise ScriptError(f"{what} must be finite (got {word})")
    return value


def _loop_values(name, args):
    pad = bool(args) and args[-1] == "pad"
    numbers = args[:-1] if pad else args
    if len(numbers) not in (1, 2):
        raise ScriptError(f"variable {name} loop takes N or N1 N2, then optionally pad (got {' '.join(args)})")
    try:
        bounds = [int(w) for w in numbers]
    except ValueError:
        raise ScriptError(f"variable {name} loop: bounds must be integers (got {' '.join(numbers)})") from None
    first, last = (1, bounds[0]) if len(bounds) == 1 else bounds
    if first < 0 or last < first or last - first >= 10_000_000:
        raise ScriptError(f"variable {name} loop: needs 0 <= N1 <= N2, at most 10^7 values "
                          f"(got {' '.join(numbers)})")
    width = len(str(last)) if pad else 0
    return [str(k).zfill(width) for k in range(first, last + 1)]


def _file_values(name, args):
    from .lexer import read_text
    if len(args) != 1:
        raise ScriptError(f"variable {name} file takes one file name")
    lines = [line.split("#", 1)[0].strip() for line in read_text(args[0], "variable file").splitlines()]
    values = [line for line in lines if line]
    if not values:
        raise ScriptError(f"variable {name} file: {args[0]} holds no values")
    return values


def _atomfile_sets(name, args):
    """LAMMPS's atomfile: sets of 'N' then N lines 'ID value' (# comments and blank lines skipped);
    [(sorted ids, their values)] one per set, ``next`` stepping to the following one."""
    from .lexer import read_text
    if len(args) != 1:
        raise ScriptError(f"variable {name} atomfile takes one file name")
    lines = [line.split("#", 1)[0].split() for line in read_text(args[0], "variable atomfile").splitlines()]
    lines = [words for words in lines if words]
    sets, at = [], 0
    while at < len(lines):
        head = lines[at]
        if len(head) != 1 or not head[0].isdigit():
            raise ScriptError(f"variable {name} atomfile: {args[0]}: expected a count of lines, got {' '.join(head)}")
        count = int(head[0])
        rows = lines[at + 1:at + 1 + count]
        if len(rows) < count or any(len(row) != 2 for row in rows):
            raise ScriptError(f"variable {name} atomfile: {args[0]}: {count} lines 'ID value' expected after "
                              f"line {at + 1} of its values")
        try:
            ids = np.array([int(row[0]) for row in rows], dtype=np.int64)
            values = np.array([float(row[1]) for row in rows], dtype=np.float64)
        except ValueError:
            raise ScriptError(f"variable {name} atomfile: {args[0]}: IDs must be integers and values "
                              "numbers") from None
        order = np.argsort(ids, kind="stable")
        sets.append((ids[order], values[order]))
        at += 1 + count
    if not sets:
        raise ScriptError(f"variable {name} atomfile: {args[0]} holds no values")
    return sets


def _vector_literal(name, text):
    if not text.endswith("]"):
        raise ScriptError(f"variable {name} vector: expected [v1,v2,...] (got {text})")
    body = text[1:-1].strip()
    words = [w.strip() for w in body.split(",")] if body else []
    return np.array([_number(w, f"variable {name} vector element") for w in words])


def _has_format(body):
    # $(formula:%fmt): a colon followed by a C format at the end
    head, sep, tail = body.rpartition(":")
    return bool(sep) and C_FORMAT.match(tail.strip()) is not None


def _c_format(fmt, value):
    fmt = fmt.strip()
    if not C_FORMAT.match(fmt):
        raise ScriptError(f"{fmt} is not a floating-point format such as %.6g")
    return fmt % value
