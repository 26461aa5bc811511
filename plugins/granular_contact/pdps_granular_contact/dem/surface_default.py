r"""Surface ``default`` of PDPS's dem contacts: the contact point lies half the overlap inside each
sphere, lever arms :math:`a_{i,j} = R_{i,j} - \delta/2` (so :math:`a_i + a_j = r` and a contact
conserves the total angular momentum exactly); against a wall :math:`a_i = R_i` (as LAMMPS's fix
wall/gran). The contact points move with :math:`\mathbf{v} = \mathbf{v}_i - \mathbf{v}_j -
(a_i\boldsymbol\omega_i + a_j\boldsymbol\omega_j)\times\mathbf{n}`, split into :math:`v_n` and
:math:`\mathbf{v}_t` (``contact_state.slide``). No coefficients, no history.
"""

from numba import njit

from pdps_granular_contact.contact_state import ARM_I, ARM_J, DELTA, RADIUS_I, RADIUS_J, WALL, slide

from .base import DemSubModel


@njit(cache=True)
def contact_point_kinematics(c, k, hist, h):
    wall = c[WALL] > 0.0
    c[ARM_I] = c[RADIUS_I] if wall else c[RADIUS_I] - 0.5 * c[DELTA]
    c[ARM_J] = 0.0 if wall else c[RADIUS_J] - 0.5 * c[DELTA]
    slide(c)


class SurfaceDefault(DemSubModel):
    kind = "dem.surface"
    name = "default"
    compute = contact_point_kinematics
