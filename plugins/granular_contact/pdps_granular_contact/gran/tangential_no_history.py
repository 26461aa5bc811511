r"""Tangential model ``no_history`` of LIGGGHTS: viscous friction capped at Coulomb's limit,

.. math::

    \mathbf{F}_t = -\min(\mu|F_n|,\ \gamma_t|\mathbf{v}_{tr}|)\,\frac{\mathbf{v}_{tr}}{|\mathbf{v}_{tr}|}

with :math:`\gamma_t` of the normal model and :math:`\mu` from ``coefficientFriction
peratomtypepair`` (dimensionless). No history. The force is added to what a cohesion model put in the tangential
force (a liquid bridge's viscous drag).

Syntax: ``pair_style gran model ... tangential no_history``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import FN_LIMIT, FTX, FTY, FTZ, GAMMA_T, VTX, VTY, VTZ

from .base import GranSubModel


@njit(cache=True)
def no_history_force(c, k, hist, h):
    """k: mu."""
    speed = math.sqrt(c[VTX] * c[VTX] + c[VTY] * c[VTY] + c[VTZ] * c[VTZ])
    scale = min(k[0] * abs(c[FN_LIMIT]), c[GAMMA_T] * speed) / speed if speed != 0.0 else 0.0
    # added to a cohesion model's tangential force (a liquid bridge's drag), which the cap does not see
    c[FTX] -= scale * c[VTX]
    c[FTY] -= scale * c[VTY]
    c[FTZ] -= scale * c[VTZ]


class TangentialNoHistory(GranSubModel):
    kind = "gran.tangential"
    name = "no_history"
    compute = no_history_force

    def coefficients(self, material):
        return material.columns(material.property("coefficientFriction"))
