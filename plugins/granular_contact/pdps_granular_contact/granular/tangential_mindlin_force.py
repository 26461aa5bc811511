r"""Tangential model ``mindlin/force`` of LAMMPS's pair granular: mindlin's spring (its formulas,
coefficients and mixing: ``pdps doc granular.tangential mindlin``) that keeps the tangential force
itself as its history (3 values): it grows by :math:`-k_ta\,\mathbf{v}_{tr}\Delta t` and
:math:`\mathbf{F}_t = \boldsymbol\xi - \eta_t\mathbf{v}_{tr}` (Thornton et al., Powder Technol.
233, 30 (2013), eq. 18); cut back at the Coulomb limit to :math:`\mathbf{F}_t + \eta_t\mathbf{v}_{tr}`.

Syntax: ``pair_coeff I J ... tangential mindlin/force k_t|NULL x_gamma_t mu_s`` (LAMMPS's pair granular).
"""

from numba import njit

from .tangential_mindlin import TangentialMindlin, mindlin_spring


@njit(cache=True)
def kept_force(c, k, hist, h):
    mindlin_spring(c, k, hist, h, True, False)


class TangentialMindlinForce(TangentialMindlin):
    name = "mindlin/force"
    compute = kept_force
    history_width = 3
