r"""Fix ``vector``: the values of computes, fixes and variables stored every N steps, one more row
each time, as a global vector (one value: ``f_ID``, ``f_ID[i]``) or array (several: ``f_ID[i][j]``),
LAMMPS's fix vector. Variables'
special functions read it whole: ``slope(f_ID)``, ``trap(f_ID)``, ``ave(f_ID)``.

A row is stored at every step that is a multiple of NEVERY, the first run's first step too when it
is one (LAMMPS's setup does so); the rows go on growing over later runs. Values: ``c_ID``,
``c_ID[i]``, ``f_ID``, ``f_ID[i]``, ``v_NAME`` (indices from 1 in the LAMMPS dialect, as there).

Syntax::

    fix ID GROUP vector NEVERY value1 [value2 ...]

Example::

    compute msd all msd com yes
    fix 9 all vector 10 c_msd[4]
    variable fitslope equal slope(f_9)/4/(10*dt)
"""

import re

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, param

VALUE = re.compile(r"^(c|f|v)_([A-Za-z0-9_]+)(?:\[(\d+)\])?$")


class FixVector(Fix):
    name = "vector"
    usage = "fix ID GROUP vector NEVERY value1 [value2 ...]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        values: list[str] = param(min_length=1, names="value (c_ID, c_ID[i], f_ID, f_ID[i], v_NAME)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.references = []
        for word in self.args.values:
            match = VALUE.match(word)
            if match is None:
                raise ScriptError(f"value {word}: expected c_ID, c_ID[i], f_ID, f_ID[i] or v_NAME")
            prefix, ident, index = match.groups()
            if prefix == "v" and index is not None:
                raise ScriptError(f"value {word}: a vector-style variable's element is not supported; "
                                  "use an equal-style variable")
            self.references.append((prefix, ident, () if index is None else (int(index),)))
        self.rows = np.zeros((0, len(self.references)))
        self.count = 0
        self.stored_at = None

    def init_run(self, sim):
        for prefix, ident, _ in self.references:
            if prefix == "c":
                sim.compute_needs(ident)        # says which compute is not defined (thermo's own are)
            if prefix == "f" and ident not in sim.fixes and ident not in sim.analyzes:
                raise ScriptError(f"fix {self.id} vector: fix {ident} is not defined")
            if prefix == "v" and ident not in sim.variables:
                raise ScriptError(f"fix {self.id} vector: variable {ident} is not defined")

    def needs(self, step):
        if step % self.args.every:
            return set()
        wanted = set()
        for prefix, ident, _ in self.references:
            if prefix == "c":
                wanted |= self.sim.compute_needs(ident)
            elif prefix == "v":
                wanted |= {"energy", "virial"}
        return wanted

    def setup(self, sim):
        # a run continuing from the step the last row was stored at adds no second row for it
        if sim.step != self.stored_at:
            self.end_of_step(sim)

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        if self.count == len(self.rows):
            grown = np.zeros((max(16, 2 * len(self.rows)), len(self.references)))
            grown[:self.count] = self.rows[:self.count]
            self.rows = grown
        for k, (prefix, ident, indices) in enumerate(self.references):
            if prefix == "c":
                value = sim.compute_value(ident, indices)
            elif prefix == "f":
                value = sim.fix_value(ident, indices)
            else:
                value = sim.variables.value(ident)
            self.rows[self.count, k] = value
        self.count += 1
        self.stored_at = sim.step

    def vector(self, sim):
        if len(self.references) > 1:
            raise ScriptError(f"fix {self.id} vector stores several values, an array: read f_{self.id}[i][j]")
        return self.rows[:self.count, 0].copy()

    def array(self, sim):
        return self.rows[:self.count].copy()
