r"""Surface ``default`` of LAMMPS's classic granular styles: the lever arms are the radii (not the
distances to the contact point, as LAMMPS's pair_gran_*.cpp), so the contact points slide at
:math:`\mathbf{v}_{tr} = \mathbf{v}_t - (R_i\boldsymbol\omega_i + R_j\boldsymbol\omega_j)\times
\mathbf{n}` (:math:`R_j = 0` against a wall), with :math:`v_n = (\mathbf{v}_i - \mathbf{v}_j)
\cdot\mathbf{n}`. No coefficients, no history.
"""

from numba import njit

from pdps_granular_contact.contact_state import (ARM_I, ARM_J, NX, NY, NZ, RADIUS_I, RADIUS_J, VN, VTX, VTY, VTZ, VX,
                                                 VY, VZ, WIX, WIY, WIZ, WJX, WJY, WJZ)

from .base import ClassicSubModel


@njit(cache=True)
def radius_kinematics(c, k, hist, h):
    c[ARM_I] = c[RADIUS_I]
    c[ARM_J] = c[RADIUS_J]
    vn = c[VX] * c[NX] + c[VY] * c[NY] + c[VZ] * c[NZ]
    c[VN] = vn
    w0 = c[RADIUS_I] * c[WIX] + c[RADIUS_J] * c[WJX]
    w1 = c[RADIUS_I] * c[WIY] + c[RADIUS_J] * c[WJY]
    w2 = c[RADIUS_I] * c[WIZ] + c[RADIUS_J] * c[WJZ]
    c[VTX] = c[VX] - vn * c[NX] - (w1 * c[NZ] - w2 * c[NY])
    c[VTY] = c[VY] - vn * c[NY] - (w2 * c[NX] - w0 * c[NZ])
    c[VTZ] = c[VZ] - vn * c[NZ] - (w0 * c[NY] - w1 * c[NX])


class SurfaceDefault(ClassicSubModel):
    kind = "classic.surface"
    name = "default"
    compute = radius_kinematics
    names = ()
