r"""Pair style ``zero``: no forces and no energy, only a neighbor list of the cutoff (LAMMPS's
``pair_style zero``), for computes that need one (rdf, coord/atom) in a scene with no pair forces.

Parameters:

- ``pair_style zero RC [nocoeff]``: ``RC`` the global cutoff (> 0, distance); with ``nocoeff``
  pair_coeff takes only I J.
- ``pair_coeff I J [RC]``: this pair's cutoff.

Example::

    pair_style zero 3.0
    pair_coeff * *
"""

from typing import Literal

from numba import njit
from pdps_core.api import PairLaw, StyleArgs, param

from .mixing import mixed_cutoff


@njit(cache=True, inline="always")
def zero_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    return 0.0, 0.0


class PairZero(PairLaw):
    name = "zero"
    usage = "pair_style zero RC [nocoeff]"
    coeff_usage = "[RC]"
    mix_default = "geometric"
    params = ()
    law = staticmethod(zero_law)

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")
        nocoeff: Literal["nocoeff"] | None = None

    class Coeff(StyleArgs):
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        return self.Coeff(cutoff=mixed_cutoff(self, ci, cj, rule))

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        return (c.cutoff if c.cutoff is not None and self.args.nocoeff is None else self.args.cutoff), ()
