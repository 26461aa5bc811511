r"""Compute ``pe``: the potential energy of the whole system, a scalar ``c_ID`` (LAMMPS's compute pe).

.. math::

    PE = E_\mathrm{pair} + E_\mathrm{tail} + \sum_\mathrm{fixes} E_\mathrm{fix}

in energy units: the pair style's energy with its tail correction (``pair_modify tail yes``) and the
energies of fixes switched on with ``fix_modify ID energy yes``. Keywords choose the terms: ``pair``,
``fix``, and LAMMPS's ``bond angle dihedral improper kspace`` (0 in pdps, which has none of them); none
given means all. The group must be ``all``. Extensive: thermo prints it divided by the particle count
when it normalises energies (lj units). Syntax::

    compute ID all pe [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix]

Example::

    compute p all pe pair
    thermo_style custom step c_p pe
"""

from typing import Literal

from pdps_core.api import Compute, ScriptError, StyleArgs, observables, param

TERMS = ("pair", "bond", "angle", "dihedral", "improper", "kspace", "fix")


class ComputePE(Compute):
    name = "pe"
    usage = "compute ID all pe [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix]"
    extensive = True
    needs_energy = True

    class Args(StyleArgs):
        terms: list[Literal[TERMS]] = param(default_factory=list)

    def __init__(self, sim, id, group, args):
        if group != "all":
            raise ScriptError(f"compute pe must use group all (got {group})")
        super().__init__(sim, id, group, args)
        self.terms = set(args.terms or TERMS)

    def scalar(self, sim):
        total = observables.potential_energy(sim)
        pair = observables.pair_energy(sim)
        return (pair if "pair" in self.terms else 0.0) + (total - pair if "fix" in self.terms else 0.0)
