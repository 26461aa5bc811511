r"""Compute ``slice``: every Nskip-th element, from Nstart on, of global vectors (LAMMPS's and
LIGGGHTS's compute slice).

For each input, the elements :math:`N_\mathrm{start} + k N_\mathrm{skip}` (counted from 1, as
LAMMPS counts them) for :math:`k = 0 \ldots (N_\mathrm{stop} - N_\mathrm{start}) / N_\mathrm{skip} - 1`
(integer division: :math:`N_\mathrm{stop}` itself is left out, and may not exceed the input's
length, as LAMMPS's and LIGGGHTS's check). Inputs:

- ``c_ID``, ``f_ID``: a compute's or fix's global vector;
- ``c_ID[N]``, ``f_ID[N]``: column N (from the dialect's first index) of its global array.

One input gives a global vector (``c_ID[k]``), several an array with a column per input
(``c_ID[k][m]``), in the units of the inputs, read when the compute is.

Syntax::

    compute ID GROUP slice NSTART NSTOP NSKIP input...

Example::

    compute s all reduce sum x y z vx vy vz
    compute v all slice 4 6 1 c_s             # the vx and vy sums
"""

import re

import numpy as np
from pydantic import model_validator

from pdps_core.api import Compute, ScriptError, StyleArgs, param

INPUT = re.compile(r"^(c|f)_([A-Za-z0-9_]+)(?:\[(\d+)\])?$")


class ComputeSlice(Compute):
    name = "slice"
    usage = "compute ID GROUP slice NSTART NSTOP NSKIP input..."

    class Args(StyleArgs):
        nstart: int = param(ge=1, unit="1")
        nstop: int = param(ge=1, unit="1")
        nskip: int = param(ge=1, unit="1")
        inputs: list[str] = param(min_length=1, names="input (c_ID, c_ID[N], f_ID, f_ID[N])")

        @model_validator(mode="after")
        def _range(self):
            if self.nstop < self.nstart:
                raise ValueError(f"nstop {self.nstop} is before nstart {self.nstart}")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.count = (args.nstop - args.nstart) // args.nskip
        if self.count == 0:
            raise ScriptError(f"compute {id} slice: {args.nstart} {args.nstop} {args.nskip} picks no element")
        self.picked = args.nstart - 1 + args.nskip * np.arange(self.count)
        self.inputs = []
        for word in args.inputs:
            match = INPUT.match(word)
            if match is None:
                raise ScriptError(f"compute {id} slice: {word} is not c_ID, c_ID[N], f_ID or f_ID[N]")
            prefix, ident, column = match.groups()
            table = sim.computes if prefix == "c" else sim.fixes
            if ident not in table:
                raise ScriptError(f"compute {id} slice: {'compute' if prefix == 'c' else 'fix'} {ident} is not "
                                  f"defined ({word})")
            self.inputs.append((word, prefix, ident, None if column is None else sim.dialect_index(int(column), word)))

    def _values(self, sim, word, prefix, ident, column):
        style = (sim.computes if prefix == "c" else sim.fixes)[ident]
        reader = "vector" if column is None else "array"
        method = getattr(style, reader, None)
        if method is None:
            raise ScriptError(f"compute {self.id} slice: {word}: {style.kind} {ident} has no global {reader}")
        values = np.asarray(method(sim), dtype=np.float64)
        if column is not None:
            if values.ndim != 2 or column >= values.shape[1]:
                raise ScriptError(f"compute {self.id} slice: {word}: {style.kind} {ident}'s array has shape "
                                  f"{values.shape}")
            values = values[:, column]
        if self.args.nstop > len(values):
            raise ScriptError(f"compute {self.id} slice: {word} has {len(values)} elements, fewer than nstop "
                              f"{self.args.nstop}")
        return values[self.picked]

    def vector(self, sim):
        if len(self.inputs) > 1:
            raise ScriptError(f"compute {self.id} slices {len(self.inputs)} inputs: read c_{self.id}[k][m]")
        return self._values(sim, *self.inputs[0])

    def array(self, sim):
        if len(self.inputs) == 1:
            raise ScriptError(f"compute {self.id} slices one input: read c_{self.id}[k]")
        return np.column_stack([self._values(sim, *entry) for entry in self.inputs])
