r"""Tangential model ``mindlin_rescale`` of LAMMPS's pair granular: mindlin's spring (its formulas,
coefficients and mixing: ``pdps doc granular.tangential mindlin``) that also keeps the contact
radius of the last step (4 values of history) and scales the spring by :math:`a/a_{prev}` while
the contact unloads (:math:`a < a_{prev}`), so that a shrinking contact does not keep the stretch
of a larger one.

Syntax: ``pair_coeff I J ... tangential mindlin_rescale k_t|NULL x_gamma_t mu_s`` (LAMMPS's pair granular).
"""

from numba import njit

from .tangential_mindlin import TangentialMindlin, mindlin_spring


@njit(cache=True)
def mindlin_rescale(c, k, hist, h):
    mindlin_spring(c, k, hist, h, False, True)


class TangentialMindlinRescale(TangentialMindlin):
    name = "mindlin_rescale"
    compute = mindlin_rescale
    history_width = 4
    # the contact radius is the same seen from either sphere (LAMMPS's transfer factor +1)
    history_transfer = (-1, -1, -1, 1)
