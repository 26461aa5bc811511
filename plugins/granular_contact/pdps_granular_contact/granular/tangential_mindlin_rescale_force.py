r"""Tangential model ``mindlin_rescale/force`` of LAMMPS's pair granular: mindlin's spring (its
formulas, coefficients and mixing: ``pdps doc granular.tangential mindlin``) that keeps the force as
mindlin/force does and scales it by :math:`a/a_{prev}` while the contact unloads, as
mindlin_rescale does (4 values of history).

Syntax: ``pair_coeff I J ... tangential mindlin_rescale/force k_t|NULL x_gamma_t mu_s`` (LAMMPS's
pair granular).
"""

from numba import njit

from .tangential_mindlin import TangentialMindlin, mindlin_spring


@njit(cache=True)
def mindlin_rescale_force(c, k, hist, h):
    mindlin_spring(c, k, hist, h, True, True)


class TangentialMindlinRescaleForce(TangentialMindlin):
    name = "mindlin_rescale/force"
    compute = mindlin_rescale_force
    history_width = 4
    # the contact radius is the same seen from either sphere (LAMMPS's transfer factor +1)
    history_transfer = (-1, -1, -1, 1)
