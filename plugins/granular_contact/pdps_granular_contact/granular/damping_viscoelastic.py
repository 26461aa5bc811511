r"""Damping model ``viscoelastic`` of LAMMPS's pair granular (its default): a dashpot growing with
the contact area,

.. math::

    \eta_n = \eta_{n0}\,m^* a, \qquad F_{n,damp} = -\eta_n v_n

with the contact radius a of the normal model and its ``eta_n0`` in 1/(time distance)
(``pdps_granular_contact.granular.damping``; the damping of LAMMPS's gran/hertz/history).

Syntax: ``pair_coeff I J NORMAL ... [damping viscoelastic] ...`` (LAMMPS's pair granular).
"""

from numba import njit

from pdps_granular_contact.contact_state import CONTACT_RADIUS, M_EFF

from .damping import DampingModel, add_damping


@njit(cache=True)
def viscoelastic_damping(c, k, hist, h):
    """k: eta_n0, limit_damping, cohesive."""
    add_damping(c, k, k[0] * c[M_EFF] * c[CONTACT_RADIUS])


class DampingViscoelastic(DampingModel):
    kind = "granular.damping"
    name = "viscoelastic"
    compute = viscoelastic_damping
