r"""Damping model ``mass_velocity`` of LAMMPS's pair granular: a dashpot scaled by the effective mass,

.. math::

    \eta_n = \eta_{n0}\,m^*, \qquad F_{n,damp} = -\eta_n v_n

with the normal model's ``eta_n0`` in 1/time (``pdps_granular_contact.granular.damping``; the
damping of LAMMPS's classic gran/hooke styles).

Syntax: ``pair_coeff I J NORMAL ... damping mass_velocity ...`` (LAMMPS's pair granular).
"""

from numba import njit

from pdps_granular_contact.contact_state import M_EFF

from .damping import DampingModel, add_damping


@njit(cache=True)
def mass_velocity_damping(c, k, hist, h):
    """k: eta_n0, limit_damping, cohesive."""
    add_damping(c, k, k[0] * c[M_EFF])


class DampingMassVelocity(DampingModel):
    kind = "granular.damping"
    name = "mass_velocity"
    compute = mass_velocity_damping
