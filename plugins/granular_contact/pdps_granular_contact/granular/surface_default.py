r"""Surface ``default`` of LAMMPS's pair granular: spheres. The contact points slide at

.. math::

    \mathbf{v}_{tr} = \mathbf{v}_t - (R_i\boldsymbol\omega_i + R_j\boldsymbol\omega_j)\times\mathbf{n},
    \qquad v_n = (\mathbf{v}_i - \mathbf{v}_j)\cdot\mathbf{n}

(the radii as lever arms, LAMMPS's GranularModel::calculate_forces), while the tangential force
turns each sphere about the contact point: torque arms :math:`R_{i,j} - \delta/2` between spheres,
:math:`R_i` against a wall. The relative spin :math:`\boldsymbol\omega_i - \boldsymbol\omega_j`
(``WR``) is what rolling and twisting read. No coefficients, no history; always composed (LAMMPS has
no other surface).
"""

from numba import njit

from pdps_granular_contact.contact_state import (ARM_I, ARM_J, DELTA, RADIUS_I, RADIUS_J, WALL, WIX, WIY, WIZ, WJX,
                                                 WJY, WJZ, WRX, WRY, WRZ, slide)

from .base import GranularSubModel


@njit(cache=True)
def sphere_kinematics(c, k, hist, h):
    c[ARM_I] = c[RADIUS_I]
    c[ARM_J] = c[RADIUS_J]
    slide(c)
    half = 0.5 * c[DELTA]
    if c[WALL] > 0.0:
        c[ARM_J] = 0.0
    else:
        c[ARM_I] = c[RADIUS_I] - half
        c[ARM_J] = c[RADIUS_J] - half
    c[WRX] = c[WIX] - c[WJX]
    c[WRY] = c[WIY] - c[WJY]
    c[WRZ] = c[WIZ] - c[WJZ]


class SurfaceDefault(GranularSubModel):
    kind = "granular.surface"
    name = "default"
    compute = sphere_kinematics
