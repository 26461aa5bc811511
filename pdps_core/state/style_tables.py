"""The styles part of a simulation: the pair style and its list, the fixes, computes and analyze
styles in script order (LAMMPS's Force and Modify), the states read_restart holds for them until
they are defined again, and how a script reads their values (c_ID, f_ID)."""

import numpy as np

from ..errors import ScriptError


class StyleTables:
    __slots__ = ("sim", "pair", "bond", "pair_list", "fixes", "computes", "analyzes", "restored_states")

    def __init__(self, sim):
        self.sim = sim                  # for the dialect's index base
        self.pair = None
        self.bond = None                # the bond style (commands/bonds.py BondStyles), or None
        self.pair_list = None           # the pair style's NeighborList, once a run set it up
        self.fixes = {}
        self.computes = {}
        self.analyzes = {}
        self.restored_states = {}       # (kind, id) -> (style, state, instance) from read_restart

    def find_compute(self, ident):
        """The compute of that ID: the script's, else one of thermo's own that every LAMMPS run
        defines (thermo_temp, thermo_press, thermo_pe), else None."""
        from ..output.thermo import THERMO_COMPUTES
        return self.computes.get(ident) or THERMO_COMPUTES.get(ident)

    def compute_value(self, ident, indices=()):
        """``c_ID``, ``c_ID[i]``, ``c_ID[i][j]``: a compute's scalar, vector element or array element."""
        compute = self.find_compute(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined")
        return self._style_value("c", compute, ident, indices)

    def fix_value(self, ident, indices=()):
        """``f_ID[...]``: what a fix or analyze style offers through scalar/vector/array, as LAMMPS's
        f_ references (analyze styles share the prefix: their IDs are in the same script namespace)."""
        style = self.fixes.get(ident) or self.analyzes.get(ident)
        if style is None:
            raise ScriptError(f"fix {ident} is not defined")
        return self._style_value("f", style, ident, indices)

    def _style_value(self, prefix, style, ident, indices):
        sim = self.sim
        reader = {0: "scalar", 1: "vector"}.get(len(indices), "array")
        method = getattr(style, reader, None)
        if method is None:
            raise ScriptError(f"{prefix}_{ident}: {style.kind} {ident} ({style.name}) has no {reader} value")
        if len(indices) == 0:
            return float(method(sim))
        values = method(sim)
        shown = f"{prefix}_{ident}{''.join(f'[{i}]' for i in indices)}"
        position = tuple(sim.dialect_index(i, shown) for i in indices)
        shape = np.shape(values)
        if style.array_rows_vary and len(position) == 2 == len(shape) and position[0] >= shape[0] \
                and position[1] < shape[1]:
            return 0.0
        try:
            return float(values[position])
        except IndexError:
            raise ScriptError(f"{shown} is out of range ({style.kind} {ident} has shape {np.shape(values)}; "
                              f"indices count from {sim.dialect.index_base})") from None

    def compute_needs(self, ident):
        """{'energy', 'virial'}: what compute ``ident`` reads."""
        compute = self.find_compute(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined")
        return ({"energy"} if compute.needs_energy else set()) | ({"virial"} if compute.needs_virial else set())
