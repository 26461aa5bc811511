r"""Compute ``reduce``: per-atom values reduced over a group to one number each (LAMMPS's compute
reduce).

For each input :math:`a` over the particles i of the group G (N of them, on all ranks):

.. math::

    \mathrm{sum} = \sum_{i \in G} a_i, \quad \mathrm{min} = \min_{i \in G} a_i, \quad
    \mathrm{max} = \max_{i \in G} a_i, \quad \mathrm{ave} = \frac{1}{N}\sum_{i \in G} a_i

in the units of the input. One input gives a scalar ``c_ID``; several give a vector, ``c_ID[k]`` the
k-th input (0-based). An empty group gives 0 (LAMMPS: 0 for sum and ave, ±1e20 for min and max).

Inputs:

- ``x y z vx vy vz fx fy fz`` (LAMMPS's list; positions wrapped into the box) and any other
  attribute of ``compute property/atom`` (``xu``, ``mass``, ``radius``, ``omegaz``, ...);
- ``c_ID``: a per-atom compute with one value per particle (``ke``, ``property/atom`` of one
  attribute); ``c_ID[k]``: column k (0-based, as every pdps index) of one with several;
- ``f_ID``, ``f_ID[k]``: the same for a fix that offers per-atom values;
- ``v_NAME``: an atom-style variable (LAMMPS's), checked when the compute is read, so that the
  variable may be defined after the compute.

The group of a referenced compute is applied as well: its particles outside that group read 0.

Syntax::

    compute ID GROUP reduce sum|min|max|ave input...

Examples::

    compute zmax all reduce max z
    compute p all property/atom vx radius
    compute r all reduce ave c_p[0] c_p[1]       # c_r[0], c_r[1]
    compute k all ke
    compute kmax all reduce max c_k
    variable vx2 atom vx*vx
    compute s all reduce sum v_vx2
"""

import re
from typing import Literal

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, param, peratom_column

from .peratom import ATTRIBUTES, REFERENCE, attribute, check_attribute, find_peratom

VARIABLE = re.compile(r"^v_([A-Za-z_][A-Za-z0-9_]*)$")


class ComputeReduce(Compute):
    name = "reduce"
    usage = "compute ID GROUP reduce sum|min|max|ave input..."

    class Args(StyleArgs):
        mode: Literal["sum", "min", "max", "ave"]
        inputs: list[str] = param(min_length=1, names="input (x, c_ID, c_ID[i], f_ID, v_NAME, ...)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.extensive = args.mode == "sum"     # LAMMPS: a sum is extensive, thermo normalises it
        what = f"compute {id} reduce"
        for word in args.inputs:
            if REFERENCE.match(word):
                find_peratom(sim, word, what)
            elif word in ATTRIBUTES:
                check_attribute(sim, word, what)
            elif not VARIABLE.match(word):
                raise ScriptError(f"{what}: unknown input {word} (x y z vx vy vz fx fy fz, another "
                                  "property/atom attribute, c_ID, c_ID[k], f_ID, f_ID[k] or v_NAME)")

    def _input(self, sim, word):
        if word in ATTRIBUTES:
            return attribute(sim, word)
        variable = VARIABLE.match(word)
        if variable:
            name = variable.group(1)
            if name not in sim.variables:
                raise ScriptError(f"compute {self.id} reduce: variable {name} is not defined ({word})")
            if sim.variables.style(name) != "atom":
                raise ScriptError(f"compute {self.id} reduce: variable {name} is "
                                  f"{sim.variables.style(name)}-style, not atom-style ({word})")
            return sim.variables.atom_values(name)
        style, column = find_peratom(sim, word, f"compute {self.id} reduce")
        return peratom_column(sim, style, column, word)

    def selected(self, sim):
        """The owned particles reduced over: the group's."""
        return sim.groups.select(sim, self.group)

    def vector(self, sim):
        chosen = self.selected(sim)
        values = [self._input(sim, word)[chosen] for word in self.args.inputs]
        mode = self.args.mode
        count = int(sim.comm.sum(int(chosen.sum())))
        if count == 0:
            return np.zeros(len(values))
        if mode in ("sum", "ave"):
            local = np.array([float(a.sum()) for a in values])
            total = np.asarray(sim.comm.sum(local), dtype=np.float64)
            return total / count if mode == "ave" else total
        if mode == "min":
            return np.array([sim.comm.min(float(a.min()) if len(a) else np.inf) for a in values])
        return np.array([sim.comm.max(float(a.max()) if len(a) else -np.inf) for a in values])

    def scalar(self, sim):
        if len(self.args.inputs) > 1:
            raise ScriptError(f"compute {self.id} reduces {len(self.args.inputs)} inputs: read one with "
                              f"c_{self.id}[k], k from 0")
        return float(self.vector(sim)[0])


class ComputeReduceRegion(ComputeReduce):
    """Compute ``reduce/region``: as reduce, over the group's particles inside a region at the time
    of reading (LAMMPS's and LIGGGHTS's compute reduce/region)::

        compute ID GROUP reduce/region REGION sum|min|max|ave input...
    """
    name = "reduce/region"
    usage = "compute ID GROUP reduce/region REGION sum|min|max|ave input..."

    class Args(StyleArgs):
        region: str = param(names="region ID")
        mode: Literal["sum", "min", "max", "ave"]
        inputs: list[str] = param(min_length=1, names="input (x, c_ID, c_ID[i], f_ID, v_NAME, ...)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.region(args.region)

    def selected(self, sim):
        p = sim.particles
        inside = np.asarray(sim.region(self.args.region).match(p.x[:p.nlocal]), dtype=bool)
        return sim.groups.select(sim, self.group) & inside

