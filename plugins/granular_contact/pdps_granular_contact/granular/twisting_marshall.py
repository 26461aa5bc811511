r"""Twisting model ``marshall`` of LAMMPS's pair granular: the twist spring-dashpot-slider of
``pdps_granular_contact.granular.twisting`` with its coefficients from the tangential model and
the contact radius a (Marshall, J. Comput. Phys. 228, 1541 (2009), eq. 32):

.. math::

    k_{twist} = \tfrac12 k_t a^2, \qquad \gamma_{twist} = \tfrac12\eta_t a^2, \qquad
    \mu_{twist} = \tfrac23\mu_s a

(:math:`k_t` the tangential model's stiffness coefficient, 0 for linear_nohistory; :math:`\eta_t`
its damping; :math:`\mu_s` its friction). No coefficients; 1 value of history.

Syntax: ``pair_coeff I J ... twisting marshall`` (LAMMPS's pair granular).
"""

from numba import njit

from pdps_granular_contact.contact_state import CONTACT_RADIUS, GAMMA_T, KT

from .base import GranularSubModel
from .twisting import twist_torque


@njit(cache=True)
def marshall_twist(c, k, hist, h):
    """k: mu_s of the tangential model."""
    a = c[CONTACT_RADIUS]
    twist_torque(c, hist, h, 0.5 * c[KT] * a * a, 0.5 * c[GAMMA_T] * a * a, 2.0 / 3.0 * k[0] * a)


class TwistingMarshall(GranularSubModel):
    kind = "granular.twisting"
    name = "marshall"
    compute = marshall_twist
    history_width = 1
    # the same seen from either sphere: (w_i - w_j) x n and (w_i - w_j).n do not change when i and j swap
    history_transfer = (1,)

    def values(self, law, contact):
        return (law.args("tangential").mu_s,)
