r"""Surface ``default`` of LAMMPS's classic granular styles: the lever arms are the radii (not the
distances to the contact point, as LAMMPS's pair_gran_*.cpp), so the contact points slide at
:math:`\mathbf{v}_{tr} = \mathbf{v}_t - (R_i\boldsymbol\omega_i + R_j\boldsymbol\omega_j)\times
\mathbf{n}` (:math:`R_j = 0` against a wall), with :math:`v_n = (\mathbf{v}_i - \mathbf{v}_j)
\cdot\mathbf{n}`. No coefficients, no history.
"""

from numba import njit

from pdps_granular_contact.contact_state import ARM_I, ARM_J, RADIUS_I, RADIUS_J, slide

from .base import ClassicSubModel


@njit(cache=True)
def radius_kinematics(c, k, hist, h):
    c[ARM_I] = c[RADIUS_I]
    c[ARM_J] = c[RADIUS_J]
    slide(c)


class SurfaceDefault(ClassicSubModel):
    kind = "classic.surface"
    name = "default"
    compute = radius_kinematics
    names = ()
