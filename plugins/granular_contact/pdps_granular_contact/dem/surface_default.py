r"""Surface ``default`` of PDPS's dem contacts: the contact point lies half the overlap inside each
sphere, lever arms :math:`a_{i,j} = R_{i,j} - \delta/2` (so :math:`a_i + a_j = r` and a contact
conserves the total angular momentum exactly); against a wall :math:`a_i = R_i` (as LAMMPS's fix
wall/gran). The contact points move with :math:`\mathbf{v} = \mathbf{v}_i - \mathbf{v}_j -
(a_i\boldsymbol\omega_i + a_j\boldsymbol\omega_j)\times\mathbf{n}`, split into :math:`v_n` and
:math:`\mathbf{v}_t`. No coefficients, no history.
"""

from numba import njit

from pdps_granular_contact.contact_state import (ARM_I, ARM_J, DELTA, NX, NY, NZ, RADIUS_I, RADIUS_J, VN, VTX, VTY,
                                                 VTZ, VX, VY, VZ, WALL, WIX, WIY, WIZ, WJX, WJY, WJZ, WRX, WRY, WRZ)

from .base import DemSubModel


@njit(cache=True)
def contact_point_kinematics(c, k, hist, h):
    wall = c[WALL] > 0.0
    c[ARM_I] = c[RADIUS_I] if wall else c[RADIUS_I] - 0.5 * c[DELTA]
    c[ARM_J] = 0.0 if wall else c[RADIUS_J] - 0.5 * c[DELTA]
    w0 = c[ARM_I] * c[WIX] + c[ARM_J] * c[WJX]
    w1 = c[ARM_I] * c[WIY] + c[ARM_J] * c[WJY]
    w2 = c[ARM_I] * c[WIZ] + c[ARM_J] * c[WJZ]
    v0 = c[VX] - (w1 * c[NZ] - w2 * c[NY])
    v1 = c[VY] - (w2 * c[NX] - w0 * c[NZ])
    v2 = c[VZ] - (w0 * c[NY] - w1 * c[NX])
    vn = v0 * c[NX] + v1 * c[NY] + v2 * c[NZ]
    c[VN] = vn
    c[VTX] = v0 - vn * c[NX]
    c[VTY] = v1 - vn * c[NY]
    c[VTZ] = v2 - vn * c[NZ]
    c[WRX] = c[WIX] - c[WJX]
    c[WRY] = c[WIY] - c[WJY]
    c[WRZ] = c[WIZ] - c[WJZ]


class SurfaceDefault(DemSubModel):
    kind = "dem.surface"
    name = "default"
    compute = contact_point_kinematics
