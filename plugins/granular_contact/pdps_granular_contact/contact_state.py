r"""The quantities of one granular contact, as the slots of one float64 array ``c`` that the contact
loop fills and every sub-model reads and writes (LAMMPS's GranularModel members, LIGGGHTS's
SurfacesIntersectData). A sub-model reads the slots of the kinds called before it and writes its own:

    from pdps_granular_contact.contact_state import DELTA, R_EFF, FN

    @njit(cache=True)
    def hertz_force(c, k, hist, h):
        c[FN] = k[0] * math.sqrt(c[R_EFF] * c[DELTA]) * c[DELTA]

Body i is a particle, body j a particle or a wall (``WALL`` 1, ``RADIUS_J`` and ``MASS_J`` 0). The
normal :math:`\mathbf{n}` points from j to i; forces are those on i (j gets their negatives),
torques are i's; units are the run's.

Filled by the loop, before any sub-model:

- ``R``: distance of the centres (of i's centre from the wall's surface); ``DELTA``: overlap
  :math:`\delta = R_i + R_j - r` (:math:`R_i - r` against a wall), > 0
- ``RADIUS_I``, ``RADIUS_J``, ``MASS_I``, ``MASS_J``; ``R_EFF`` :math:`R_iR_j/(R_i+R_j)` (:math:`R_i`
  against a wall); ``M_EFF`` :math:`m_im_j/(m_i+m_j)`, the other body's mass when one is held at
  rest (fix freeze), a rigid body's mass for a particle in one, :math:`m_i` against a wall
- ``NX``..``NZ`` the normal; ``VX``..``VZ`` :math:`\mathbf{v}_i - \mathbf{v}_j` (the wall's
  velocity at the contact point for a wall); ``WIX``..``WIZ``, ``WJX``..``WJZ`` the spins
- ``DT`` the timestep; ``UPDATE`` 1 when the contact's history advances (0 in a run's setup force
  computation, which reads the history and changes nothing: LAMMPS's and LIGGGHTS's
  ``shearupdate``); ``DIMENSION`` 2 or 3; ``TEMPERATURE_I``, ``TEMPERATURE_J`` where heat is
  conducted
- ``LIQUID_I``, ``LIQUID_J``: the surface liquid content of each particle (per-atom
  ``surfaceLiquidContent``) where a wet sub-model (``ContactSubModel.wet``: a liquid bridge) is
  composed; such a model may lower them (LIGGGHTS's limitLiquidContent), and the loop writes them
  back to the particles

Written by the sub-models, in the order the loop calls them (surface, normal, damping, cohesion,
tangential, rolling, twisting, heat):

- surface: ``ARM_I``, ``ARM_J`` (centre to contact point), ``VN`` :math:`(\mathbf{v}_i -
  \mathbf{v}_j)\cdot\mathbf{n}`, ``VTX``..``VTZ`` the sliding velocity of the contact points,
  ``WRX``..``WRZ`` the relative spin :math:`\boldsymbol\omega_i - \boldsymbol\omega_j`
- normal (and damping, cohesion): ``FN`` the normal force along n; ``FN_LIMIT`` the normal force
  the tangential Coulomb limit and the rolling cap read; ``KN``, ``KT``, ``GAMMA_N``, ``GAMMA_T``
  the stiffnesses and dampings of this overlap (LIGGGHTS's normal models give the tangential ones)
- tangential: ``FTX``..``FTZ`` the tangential force; its torque on each body is the loop's
  (:math:`-a\,\mathbf{n}\times\mathbf{F}_t` with the arm a of the body). A cohesion model may put
  a tangential force of its own there (a liquid bridge's viscous drag), which LIGGGHTS's tangential
  models add theirs to and their Coulomb limit does not see
- rolling, twisting: ``MRX``..``MRZ``, ``MTX``..``MTZ``: torques :math:`\mathbf{M}`, i gets
  :math:`-\mathbf{M}` and j :math:`+\mathbf{M}`
- heat: ``HEAT`` the heat flow into i (power)
- ``LIQUID_FLUX_I``, ``LIQUID_FLUX_J``: the rate at which a wet model moves surface liquid content
  into i and into j (content/time: a bridge that breaks shares its liquid out); the loop adds them
  to the per-atom ``liquidFlux``
- ``CONTACT_RADIUS``: the radius a of the contact area, where a normal model defines one (LAMMPS's
  pair granular: :math:`\sqrt{\delta R^*}`, JKR's own), which its damping, tangential, rolling,
  twisting and heat models read

Every slot a sub-model writes is zeroed by the loop before the first sub-model of each contact, so
a kind no model fills contributes nothing.

Bodies apart but within a sub-model's reach (``ContactSubModel.close``: LIGGGHTS's surfacesClose,
a liquid bridge stretched beyond touching) are filled the same way, ``DELTA`` < 0, with the radii
as lever arms (``ARM_I``, ``ARM_J``) and ``VN``, ``VT`` from them (``slide``).
"""

from numba import njit

(R, DELTA, RADIUS_I, RADIUS_J, MASS_I, MASS_J, R_EFF, M_EFF, WALL,
 NX, NY, NZ, VX, VY, VZ, WIX, WIY, WIZ, WJX, WJY, WJZ, DT, UPDATE, DIMENSION, TEMPERATURE_I, TEMPERATURE_J,
 LIQUID_I, LIQUID_J,
 ARM_I, ARM_J, VN, VTX, VTY, VTZ, WRX, WRY, WRZ,
 FN, FN_LIMIT, KN, KT, GAMMA_N, GAMMA_T,
 FTX, FTY, FTZ, MRX, MRY, MRZ, MTX, MTY, MTZ, HEAT, CONTACT_RADIUS, LIQUID_FLUX_I, LIQUID_FLUX_J) = range(56)

SIZE = 56
# the slots the sub-models write, zeroed before each contact
FIRST_OUTPUT = ARM_I


@njit(cache=True)
def slide(c):
    """What every surface model computes once it set the lever arms ARM_I, ARM_J: v_n =
    (v_i - v_j).n into VN and the sliding velocity of the contact points, v_t - (a_i w_i + a_j w_j)
    x n, into VT."""
    vn = c[VX] * c[NX] + c[VY] * c[NY] + c[VZ] * c[NZ]
    c[VN] = vn
    w0 = c[ARM_I] * c[WIX] + c[ARM_J] * c[WJX]
    w1 = c[ARM_I] * c[WIY] + c[ARM_J] * c[WJY]
    w2 = c[ARM_I] * c[WIZ] + c[ARM_J] * c[WJZ]
    c[VTX] = c[VX] - vn * c[NX] - (w1 * c[NZ] - w2 * c[NY])
    c[VTY] = c[VY] - vn * c[NY] - (w2 * c[NX] - w0 * c[NZ])
    c[VTZ] = c[VZ] - vn * c[NZ] - (w0 * c[NY] - w1 * c[NX])
