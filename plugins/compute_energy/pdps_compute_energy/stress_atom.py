r"""Compute ``stress/atom``: the stress tensor of each particle times its volume (LAMMPS's compute
stress/atom), six values per particle, xx yy zz xy xz yz:

.. math::

    S_{i,ab} = -\left[m_i v_{i,a} v_{i,b} + \tfrac12 \sum_j r_{ij,a} F_{ij,b}\right]

in pressure*volume units (times ``nktv2p``; the kinetic term times ``mvv2e``): each pair's virial split
half to each particle. Summed over particles, the trace of the virial part is minus the virial of
the system, so -(S_xx + S_yy + S_zz) / 3V summed is the pressure's virial part (the kinetic part with
all 3N degrees of freedom, not N_dof). Keywords: ``ke`` (the kinetic term), ``pair``, ``virial`` (every
term but ke), ``fix`` and LAMMPS's ``bond angle dihedral improper kspace`` (0 in pdps); none means
all. The temperature, when given, must be ``NULL`` (no velocity bias); LIGGGHTS's syntax has none.
Syntax::

    compute ID GROUP stress/atom [NULL] [ke] [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix] [virial]

Example::

    compute s all stress/atom NULL
    dump 1 all custom 100 s.dump id c_s[1] c_s[2] c_s[3]
"""

from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import Compute, StyleArgs, observables, param

TERMS = ("ke", "pair", "bond", "angle", "dihedral", "improper", "kspace", "fix", "virial")


class ComputeStressAtom(Compute):
    name = "stress/atom"
    usage = ("compute ID GROUP stress/atom [NULL] [ke] [pair] [bond] [angle] [dihedral] [improper] [kspace] "
             "[fix] [virial]")
    needs_virial = True
    peratom_tally = True

    class Args(StyleArgs):
        # LAMMPS's temperature ID (only NULL here); LIGGGHTS's syntax has none
        temperature: Literal["NULL"] | None = param(None)
        terms: list[Literal[TERMS]] = param(default_factory=list)

        @model_validator(mode="before")
        @classmethod
        def _temperature_ids_are_not_taken(cls, values):
            first = (values.get("terms") or [None])[0]
            if values.get("temperature") is None and first is not None and first not in TERMS:
                raise ValueError(f"temperature {first}: only NULL (no velocity bias) is supported")
            return values

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        terms = set(args.terms or TERMS)
        self.ke = "ke" in terms
        self.pair = bool(terms & {"pair", "virial"})

    def peratom(self, sim):
        tally = self.pair_tally(sim)
        n = len(tally)
        stress = tally[:, 1:7].copy() if self.pair else np.zeros((n, 6))
        if self.ke:
            v = sim.particles.v[:n]
            onemass = sim.units.mvv2e * observables.masses(sim)
            for column, (a, b) in enumerate(((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))):
                stress[:, column] += onemass * v[:, a] * v[:, b]
        stress *= -sim.units.nktv2p
        chosen = sim.groups.select(sim, self.group)
        stress[~chosen] = 0.0
        return stress
