r"""Surface ``default`` of LIGGGHTS's granular models: spheres. The contact point lies half the
overlap inside each surface, so the lever arms from the centres are :math:`a_{i,j} = R_{i,j} -
\delta/2` (:math:`a_j = 0` against a wall, which does not turn), and the contact points slide at

.. math::

    \mathbf{v}_{tr} = \mathbf{v}_t - (a_i\boldsymbol\omega_i + a_j\boldsymbol\omega_j)\times\mathbf{n},
    \qquad v_n = (\mathbf{v}_i - \mathbf{v}_j)\cdot\mathbf{n}

with the relative spin :math:`\boldsymbol\omega_r = \boldsymbol\omega_i - \boldsymbol\omega_j`
that the rolling models read; against a wall at distance r from i's centre LIGGGHTS gives them
:math:`\boldsymbol\omega_r = \frac{R_i - \delta/2}{r}\boldsymbol\omega_i` (its surface model's
``wr``; read from LIGGGHTS's surface_model_default.h). No coefficients, no history. Syntax: ``surface default`` (LIGGGHTS's default; the only surface).
"""

from numba import njit

from pdps_granular_contact.contact_state import (ARM_I, ARM_J, DELTA, R, RADIUS_I, RADIUS_J, WALL, WIX, WIY, WIZ, WJX,
                                                 WJY, WJZ, WRX, WRY, WRZ, slide)

from .base import GranSubModel


@njit(cache=True)
def sphere_kinematics(c, k, hist, h):
    half = 0.5 * c[DELTA]
    c[ARM_I] = c[RADIUS_I] - half
    c[ARM_J] = 0.0 if c[WALL] > 0.0 else c[RADIUS_J] - half
    slide(c)
    if c[WALL] > 0.0:
        scale = c[ARM_I] / c[R]
        c[WRX] = scale * c[WIX]
        c[WRY] = scale * c[WIY]
        c[WRZ] = scale * c[WIZ]
    else:
        c[WRX] = c[WIX] - c[WJX]
        c[WRY] = c[WIY] - c[WJY]
        c[WRZ] = c[WIZ] - c[WJZ]


class SurfaceDefault(GranSubModel):
    kind = "gran.surface"
    name = "default"
    compute = sphere_kinematics
