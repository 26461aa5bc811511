r"""Compute ``reduce``: per-atom values reduced over a group to one number each (LAMMPS's compute
reduce).

For each input :math:`a` over the particles i of the group G (N of them, on all ranks):

.. math::

    \mathrm{sum} = \sum_{i \in G} a_i, \quad \mathrm{min} = \min_{i \in G} a_i, \quad
    \mathrm{max} = \max_{i \in G} a_i, \quad \mathrm{ave} = \frac{1}{N}\sum_{i \in G} a_i

in the units of the input. One input gives a scalar ``c_ID``; several give a vector, ``c_ID[k]`` the
k-th input (0-based). An empty group gives, as LAMMPS's, 0 for sum and ave, 1e20 for min and
-1e20 for max.

Inputs:

- ``x y z vx vy vz fx fy fz`` (LAMMPS's list; positions wrapped into the box) and any other
  attribute of ``compute property/atom`` (``xu``, ``mass``, ``radius``, ``omegaz``, ...);
- ``c_ID``: a per-atom compute with one value per particle (``ke``, ``property/atom`` of one
  attribute); ``c_ID[k]``: column k (0-based, as every pdps index) of one with several;
- ``f_ID``, ``f_ID[k]``: the same for a fix that offers per-atom values; in LIGGGHTS's dialect
  ``f_NAME`` is also a per-atom property a fix made (``f_Temp`` of fix heat/gran);
- ``v_NAME``: an atom-style variable (LAMMPS's), checked when the compute is read, so that the
  variable may be defined after the compute.

The group of a referenced compute is applied as well: its particles outside that group read 0.

``replace A B`` (LAMMPS's, min and max only, any number of them): value A becomes input A's value
at the particle where input B has its min or max (inputs counted from the dialect's first index),
e.g. ``reduce max c_pe x replace 2 1``: the x of the particle of largest energy.

Or, as LAMMPS's, every input a compute's local data (``c_ID``, ``c_ID[k]`` of ``pair/gran/local``,
``wall/gran/local``: one row per contact): then the rows of all ranks are reduced, whatever the
group, and ``ave`` divides by the row count. Per-atom and local inputs do not mix.

Syntax::

    compute ID GROUP reduce sum|min|max|ave input... [replace A B]...

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

from pdps_core.api import Compute, PeratomReference, ScriptError, StyleArgs, keyword, param

from .peratom import ATTRIBUTES, REFERENCE, attribute, check_attribute, provides_peratom

# what min and max of nothing are (LAMMPS's BIG)
EMPTY = 1.0e20
VARIABLE = re.compile(r"^v_([A-Za-z_][A-Za-z0-9_]*)$")


def _local_compute(sim, word):
    """The compute a ``c_ID``/``c_ID[k]`` input names when it offers local data and no per-atom
    values, else None."""
    match = REFERENCE.match(word)
    if not match or match.group(1) != "c":
        return None
    compute = sim.computes.get(match.group(2))
    if compute is None or type(compute).local is Compute.local or provides_peratom(compute):
        return None
    return compute


class ComputeReduce(Compute):
    name = "reduce"
    usage = "compute ID GROUP reduce sum|min|max|ave input... [replace A B]..."

    class Args(StyleArgs):
        mode: Literal["sum", "min", "max", "ave"]
        inputs: list[str] = param(min_length=1, names="input (x, c_ID, c_ID[i], f_ID, v_NAME, ...)")
        replaced: list[tuple[Literal["replace"], int, int]] = keyword(default_factory=list, spelled_by_entries=True,
                                                                  unit="1")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.extensive = args.mode == "sum"     # LAMMPS: a sum is extensive, thermo normalises it
        what = f"compute {id} reduce"
        local = [_local_compute(sim, word) is not None for word in args.inputs]
        self.local = all(local)
        if any(local) and not self.local:
            raise ScriptError(f"{what}: inputs are per-atom values or local data, not both "
                              f"({' '.join(args.inputs)})")
        self.replacements = []
        for _, a, b in args.replaced:
            if args.mode not in ("min", "max"):
                raise ScriptError(f"{what}: replace needs min or max (got {args.mode})")
            shown = f"replace {a} {b}"
            ka, kb = sim.dialect_index(a, shown), sim.dialect_index(b, shown)
            if not (0 <= ka < len(args.inputs) and 0 <= kb < len(args.inputs)) or ka == kb:
                raise ScriptError(f"{what}: {shown}: needs two different inputs of the {len(args.inputs)}")
            self.replacements.append((ka, kb))
        self.references = {}
        for word in args.inputs:
            if self.local:
                continue
            if REFERENCE.match(word):
                # the core's reader: c_ID, f_ID and, in LIGGGHTS's dialect, f_NAME of a per-atom property
                self.references[word] = PeratomReference(sim, word, f"{what}: {word}")
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
        return self.references[word].values(sim)

    def selected(self, sim):
        """The owned particles reduced over: the group's."""
        return sim.groups.select(sim, self.group)

    def _local_input(self, sim, word):
        compute = _local_compute(sim, word)
        values = np.asarray(compute.local(sim), dtype=np.float64)
        column = REFERENCE.match(word).group(3)
        if values.ndim == 1:
            if column is not None:
                raise ScriptError(f"compute {self.id} reduce: compute {compute.id} has one local value per row; "
                                  f"drop the [k] ({word})")
            return values
        if column is None:
            raise ScriptError(f"compute {self.id} reduce: compute {compute.id} has {values.shape[1]} local "
                              f"values per row: name one as c_{compute.id}[k] ({word})")
        k = sim.dialect_index(int(column), word)
        if k >= values.shape[1]:
            raise ScriptError(f"compute {self.id} reduce: {word} is out of range (compute {compute.id} has "
                              f"{values.shape[1]} local values per row)")
        return values[:, k]

    def vector(self, sim):
        if self.local:
            values = [self._local_input(sim, word) for word in self.args.inputs]
            count = int(sim.comm.sum(len(values[0])))
        else:
            chosen = self.selected(sim)
            values = [self._input(sim, word)[chosen] for word in self.args.inputs]
            count = int(sim.comm.sum(int(chosen.sum())))
        mode = self.args.mode
        if count == 0:
            return np.full(len(values), {"min": EMPTY, "max": -EMPTY}.get(mode, 0.0))
        if mode in ("sum", "ave"):
            local = np.array([float(a.sum()) for a in values])
            total = np.asarray(sim.comm.sum(local), dtype=np.float64)
            return total / count if mode == "ave" else total
        pick = sim.comm.min if mode == "min" else sim.comm.max
        empty = np.inf if mode == "min" else -np.inf
        out = np.array([pick(float(a.min() if mode == "min" else a.max()) if len(a) else empty) for a in values])
        for ka, kb in self.replacements:
            # the value of input A where input B has its extreme: the rank holding it gives it
            b = values[kb]
            here = len(b) > 0 and (b.min() if mode == "min" else b.max()) == out[kb]
            mine = float(values[ka][int(np.argmin(b) if mode == "min" else np.argmax(b))]) if here else -np.inf
            out[ka] = sim.comm.max(mine)
        return out

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
        replaced: list[tuple[Literal["replace"], int, int]] = keyword(default_factory=list, spelled_by_entries=True,
                                                                  unit="1")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.region(args.region)

    def selected(self, sim):
        p = sim.particles
        inside = np.asarray(sim.region(self.args.region).match(p.x[:p.nlocal]), dtype=bool)
        return sim.groups.select(sim, self.group) & inside

