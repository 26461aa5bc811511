r"""Compute ``pe/atom``: the potential energy of each particle (LAMMPS's compute pe/atom).

Each pair's energy is split half to each of its two particles, so the values sum to the pair
style's energy (without the tail correction, which belongs to no particle):

.. math::

    e_i = \tfrac12 \sum_{j} E(r_{ij})

in energy units; 0 for particles outside the group. Keywords as LAMMPS's: ``pair``, ``fix`` and
``bond angle dihedral improper kspace`` (no term in pdps; nor does any pdps fix tally per-particle
energy, so ``fix`` adds 0); none given means all. The pair style tallies per particle on the steps
something reads this compute (thermo or dump steps); force-law pair styles (``PairLaw``) do.
Syntax::

    compute ID GROUP pe/atom [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix]

Example::

    compute e all pe/atom
    dump 1 all custom 100 pe.dump id c_e
"""

from typing import Literal

import numpy as np

from pdps_core.api import Compute, StyleArgs, param

from .pe import TERMS


class ComputePEAtom(Compute):
    name = "pe/atom"
    usage = "compute ID GROUP pe/atom [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix]"
    needs_energy = True
    peratom_tally = True

    class Args(StyleArgs):
        terms: list[Literal[TERMS]] = param(default_factory=list)

    def peratom(self, sim):
        terms = set(self.args.terms or TERMS)
        tally = self.pair_tally(sim)
        chosen = sim.groups.select(sim, self.group)
        energy = tally[:, 0] if "pair" in terms else np.zeros(len(tally))
        return np.where(chosen, energy, 0.0)
