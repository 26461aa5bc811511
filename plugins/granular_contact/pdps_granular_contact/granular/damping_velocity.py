r"""Damping model ``velocity`` of LAMMPS's pair granular: a constant dashpot,

.. math::

    \eta_n = \eta_{n0}, \qquad F_{n,damp} = -\eta_n v_n

with the normal model's ``eta_n0`` in mass/time (``pdps_granular_contact.granular.damping``).

Syntax: ``pair_coeff I J NORMAL ... damping velocity ...`` (LAMMPS's pair granular).
"""

from numba import njit

from .damping import DampingModel, add_damping


@njit(cache=True)
def velocity_damping(c, k, hist, h):
    """k: eta_n0, limit_damping, cohesive."""
    add_damping(c, k, k[0])


class DampingVelocity(DampingModel):
    kind = "granular.damping"
    name = "velocity"
    compute = velocity_damping
