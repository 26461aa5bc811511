r"""Computes of molecules (LAMMPS's and LIGGGHTS's com/molecule, gyration/molecule, msd/molecule,
inertia/molecule, atom/molecule and property/molecule): one value, or row, per molecule.

The molecules are those with particles in the compute's group, in the order of their ids (row k,
from the dialect's first index, is the k-th smallest id); only the group's particles count in a
molecule's values. Positions are unwrapped (images counted), masses each particle's own. With
:math:`M` a molecule's mass and :math:`\mathbf{d}_i = \mathbf{x}_i - \mathbf{x}_{cm}`:

- ``com/molecule``: the centre of mass :math:`\mathbf{x}_{cm}` of each (array, 3 columns, distance);
- ``gyration/molecule [tensor]``: :math:`R_g = \sqrt{\sum m_i |\mathbf{d}_i|^2 / M}` (vector,
  distance); with ``tensor`` the array :math:`\sum m_i d_a d_b / M`, xx yy zz xy xz yz (distance^2);
- ``msd/molecule``: the centre of mass's squared displacement since the compute was defined, dx^2
  dy^2 dz^2 and their sum (array, 4 columns, distance^2);
- ``inertia/molecule``: the inertia tensor about the centre of mass, xx yy zz xy yz xz (array,
  mass*distance^2; the off-diagonal ones :math:`-\sum m_i d_a d_b`);
- ``atom/molecule input...``: each per-atom input (``c_ID``, ``c_ID[k]``, ``f_ID``, ``f_ID[k]``,
  ``v_NAME``) summed over the molecule (vector for one input, array for several);
- ``property/molecule mol|count...``: the molecule's id, or its number of particles in the group
  (vector for one, array for several).

Particles need molecule ids (``atom_style molecular``, ``hybrid granular molecular``...); a group
particle of molecule 0 is warned about, as LAMMPS does.

Syntax::

    compute ID GROUP com/molecule
    compute ID GROUP gyration/molecule [tensor]
    compute ID GROUP msd/molecule
    compute ID GROUP inertia/molecule
    compute ID GROUP atom/molecule input...
    compute ID GROUP property/molecule mol|count...

Example::

    compute cm all com/molecule
    thermo_style custom step c_cm[1][1] c_cm[1][3]
"""

from typing import Literal

import numpy as np

from pdps_core.api import Compute, PeratomReference, ScriptError, StyleArgs, observables, param

from .peratom import unwrapped


class MoleculeCompute(Compute):
    """The molecules of the group and each group particle's place among them."""

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not sim.particles.has("molecule"):
            raise ScriptError(f"compute {id} ({self.name}) needs molecule ids (an atom style with molecules)")
        self._told_zero = False

    def molecules(self, sim):
        """(molecule ids of the group, in order; each owned group particle's row; the group mask)."""
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        mol = p.arrays["molecule"][:n]
        mine = np.unique(mol[chosen])
        if 0 in mine and not self._told_zero:
            self._told_zero = True
            sim.warn(f"compute {self.id} ({self.name}): a particle of molecule 0 is in group {self.group} "
                     "(LAMMPS's warning too)")
        top = int(sim.comm.max(int(mine.max()) if len(mine) else -1))
        if top < 0:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), chosen
        present = np.zeros(top + 1)
        present[mine] = 1.0
        ids = np.flatnonzero(np.asarray(sim.comm.sum(present)) > 0)
        rows = np.searchsorted(ids, mol[chosen])
        return ids, rows, chosen

    def sums(self, sim, rows, values, count):
        """Sum of ``values`` (k columns) per molecule over every rank: (count, k)."""
        out = np.zeros((count, values.shape[1]))
        np.add.at(out, rows, values)
        return np.asarray(sim.comm.sum(out), dtype=np.float64).reshape(count, values.shape[1])

    def centres(self, sim):
        """(ids, rows, chosen, masses of the chosen, M per molecule, centre per molecule, d per particle)."""
        ids, rows, chosen = self.molecules(sim)
        mass = np.asarray(observables.masses(sim, chosen), dtype=np.float64)
        x = unwrapped(sim)[chosen]
        moments = self.sums(sim, rows, np.column_stack([mass[:, None] * x, mass]), len(ids))
        total = moments[:, 3]
        centre = np.divide(moments[:, :3], total[:, None], out=np.zeros((len(ids), 3)), where=total[:, None] > 0)
        return ids, rows, mass, total, centre, x - centre[rows]


class ComputeCOMMolecule(MoleculeCompute):
    name = "com/molecule"
    usage = "compute ID GROUP com/molecule"

    def array(self, sim):
        return self.centres(sim)[4]


class ComputeGyrationMolecule(MoleculeCompute):
    name = "gyration/molecule"
    usage = "compute ID GROUP gyration/molecule [tensor]"

    class Args(StyleArgs):
        tensor: Literal["tensor"] | None = param(None)

    def _moments(self, sim):
        ids, rows, mass, total, _, d = self.centres(sim)
        pairs = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
        second = self.sums(sim, rows, np.column_stack([mass * d[:, a] * d[:, b] for a, b in pairs]), len(ids))
        return np.divide(second, total[:, None], out=np.zeros_like(second), where=total[:, None] > 0)

    def vector(self, sim):
        if self.args.tensor:
            raise ScriptError(f"compute {self.id} gyration/molecule tensor is an array: read c_{self.id}[i][j]")
        return np.sqrt(self._moments(sim)[:, :3].sum(axis=1))

    def array(self, sim):
        if not self.args.tensor:
            raise ScriptError(f"compute {self.id} gyration/molecule is a vector: read c_{self.id}[i]")
        return self._moments(sim)


class ComputeMSDMolecule(MoleculeCompute):
    name = "msd/molecule"
    usage = "compute ID GROUP msd/molecule"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        ids, _, _, _, centre, _ = self.centres(sim)
        self.origin_ids, self.origin = ids, centre

    def array(self, sim):
        ids, _, _, _, centre, _ = self.centres(sim)
        if not np.array_equal(ids, self.origin_ids):
            raise ScriptError(f"compute {self.id} (msd/molecule): the group's molecules changed since it was "
                              "defined")
        delta = centre - self.origin
        squares = delta * delta
        return np.column_stack([squares, squares.sum(axis=1)])


class ComputeInertiaMolecule(MoleculeCompute):
    name = "inertia/molecule"
    usage = "compute ID GROUP inertia/molecule"

    def array(self, sim):
        ids, rows, mass, _, _, d = self.centres(sim)
        dx, dy, dz = d[:, 0], d[:, 1], d[:, 2]
        terms = np.column_stack([mass * (dy * dy + dz * dz), mass * (dx * dx + dz * dz), mass * (dx * dx + dy * dy),
                                 -mass * dx * dy, -mass * dy * dz, -mass * dx * dz])
        return self.sums(sim, rows, terms, len(ids))


class ComputeAtomMolecule(MoleculeCompute):
    name = "atom/molecule"
    usage = "compute ID GROUP atom/molecule input..."

    class Args(StyleArgs):
        inputs: list[str] = param(min_length=1, names="input (c_ID, c_ID[k], f_ID, f_ID[k], v_NAME)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.references = [PeratomReference(sim, word, f"compute {id} atom/molecule: {word}") for word in args.inputs]

    def _sums(self, sim):
        ids, rows, chosen = self.molecules(sim)
        values = np.column_stack([np.asarray(r.values(sim), dtype=np.float64)[chosen] for r in self.references])
        return self.sums(sim, rows, values, len(ids))

    def vector(self, sim):
        if len(self.references) > 1:
            raise ScriptError(f"compute {self.id} atom/molecule sums {len(self.references)} inputs: read "
                              f"c_{self.id}[i][j]")
        return self._sums(sim)[:, 0]

    def array(self, sim):
        return self._sums(sim)


class ComputePropertyMolecule(MoleculeCompute):
    name = "property/molecule"
    usage = "compute ID GROUP property/molecule mol|count..."

    class Args(StyleArgs):
        properties: list[Literal["mol", "count"]] = param(min_length=1)

    def _values(self, sim):
        ids, rows, _ = self.molecules(sim)
        counts = self.sums(sim, rows, np.ones((len(rows), 1)), len(ids))[:, 0]
        return np.column_stack([ids.astype(np.float64) if word == "mol" else counts for word in self.args.properties])

    def vector(self, sim):
        if len(self.args.properties) > 1:
            raise ScriptError(f"compute {self.id} property/molecule gives {len(self.args.properties)} values: read "
                              f"c_{self.id}[i][j]")
        return self._values(sim)[:, 0]

    def array(self, sim):
        return self._values(sim)
