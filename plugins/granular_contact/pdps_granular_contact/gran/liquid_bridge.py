r"""What LIGGGHTS's two capillary cohesion models (``easo/capillary/viscous``,
``washino/capillary/viscous``) share: the liquid a particle carries, the viscous force of the
bridge, the liquid a broken bridge gives back, and the material properties they read.

A particle of radius R carries the surface liquid content c (per-atom ``surfaceLiquidContent``):
its liquid volume is :math:`c\,V_s`, :math:`V_s = \tfrac43\pi R^3` the solid volume. (LIGGGHTS's
manual calls c a percentage of :math:`V_s`; its code takes :math:`cV_s` for the volume, and so does
pdps. LIGGGHTS carries volumes times 1000 with :math:`\tfrac43\cdot 1000` rounded to 1333.333333,
and 8/15 rounded to 0.5333333: pdps computes with the same numbers.)

Viscous force (Nase et al., Powder Technol. 116, 214 (2001), as Shi & McCarthy, Powder Technol.
184, 65 (2008), eqs. 40-41), at surface distance s (:math:`R^* = R_iR_j/(R_i+R_j)`, η the fluid's
viscosity, :math:`v_n` and :math:`\mathbf{v}_t` the normal and sliding velocities of the contact
points):

.. math::

    F_{n,visc} = -6\pi\eta R^*\,\frac{v_n}{\rho}, \qquad
    \mathbf{F}_{t,visc} = -6\pi\eta R^*\left(\tfrac{8}{15}\ln\frac1\rho + 0.9588\right)\mathbf{v}_t,
    \qquad \rho = \max\left(\rho_{min}, \frac{s}{R^*}\right)

with :math:`\rho_{min}` = ``minSeparationDistanceRatio`` (so while the spheres touch, ρ =
:math:`\rho_{min}`). The normal part pushes apart spheres that approach (:math:`v_n < 0`) and pulls
those that part; the tangential part resists sliding. Neither is seen by the tangential model's
Coulomb limit.

When a bridge breaks, its volume V goes back to the two particles in proportion to their solid
volumes, :math:`V\,R_i^3/(R_i^3 + R_j^3)` to i; the bridge had taken :math:`V_{b,i}` from i (the
model's share), so i's content changes by :math:`(V R_i^3/(R_i^3+R_j^3) - V_{b,i})/V_{s,i}`, given as
a flux over one step (``liquidFlux``, content/time) and integrated by pair gran at the end of the
step, as LIGGGHTS's transport equation: :math:`c \leftarrow c + \Delta t\,(\dot c_{flux} +
\dot c_{source})`. The liquid volume :math:`\sum_i c_iV_{s,i}` is conserved.
"""

import math

import numpy as np
from numba import njit

from pdps_granular_contact.contact_state import (DT, FTX, FTY, FTZ, LIQUID_FLUX_I, LIQUID_FLUX_J, LIQUID_I, LIQUID_J,
                                                 RADIUS_I, RADIUS_J, R_EFF, VN, VTX, VTY, VTZ)

# LIGGGHTS's 4/3 x 1000 and 8/15, as its code writes them
FOUR_THIRDS_1000 = 1333.333333
EIGHT_FIFTEENTHS = 0.5333333
# a bridge of less volume (x 1000) pulls nothing (LIGGGHTS's)
SMALLEST_BRIDGE = 1e-14


def _finite(check):
    return lambda value: math.isfinite(value) and check(value)


# the properties both models read, as fix property/global gives them (LIGGGHTS's names)
PROPERTIES = {
    "surfaceLiquidContentInitial": ("scalar", "scalar", _finite(lambda c: c >= 0), ">= 0"),
    "surfaceTension": ("scalar", "scalar", _finite(lambda s: s >= 0), ">= 0"),
    "fluidViscosity": ("scalar", "scalar", _finite(lambda eta: eta >= 0), ">= 0"),
    "contactAngle": ("per_type", "peratomtype", _finite(lambda a: 0 <= a <= 180), "in [0, 180] (degrees)"),
    "minSeparationDistanceRatio": ("scalar", "scalar", _finite(lambda r: r > 0), "> 0"),
}


def contact_angle(material):
    """LIGGGHTS 3.8.0's effective contact angle of each type pair, :math:`\\tfrac12\\theta_i\\theta_j`
    in radians (its code; the manual's, and LIGGGHTS after 2021, the mean :math:`(\\theta_i +
    \\theta_j)/2`)."""
    theta = material.property("contactAngle") * math.pi / 180.0
    return 0.5 * theta[:, None] * theta[None, :]


@njit(cache=True)
def liquid_1000(c):
    """The liquid volumes of i and of j, times 1000 (module docstring)."""
    ri = c[RADIUS_I]
    rj = c[RADIUS_J]
    return (FOUR_THIRDS_1000 * math.pi * ri * ri * ri * c[LIQUID_I],
            FOUR_THIRDS_1000 * math.pi * rj * rj * rj * c[LIQUID_J])


@njit(cache=True)
def rupture_distance(theta, bond_1000):
    """Lian et al.'s rupture distance of a bridge of volume V: :math:`(1 + \\theta/2)V^{1/3}`."""
    return (1.0 + 0.5 * theta) * np.cbrt(bond_1000) * 0.1


@njit(cache=True)
def viscous_drag(c, eta, ratio):
    """The viscous tangential force added to the contact's (FT), and the normal one returned, at
    ρ = ``ratio`` (module docstring)."""
    stokes = -6.0 * math.pi * eta * c[R_EFF]
    along = (EIGHT_FIFTEENTHS * math.log(1.0 / ratio) + 0.9588) * stokes
    c[FTX] += along * c[VTX]
    c[FTY] += along * c[VTY]
    c[FTZ] += along * c[VTZ]
    return stokes * c[VN] / ratio


@njit(cache=True)
def share_out(c, bond_1000, taken_i, taken_j):
    """A broken bridge's liquid back to both particles by their solid volumes, as fluxes over one
    step (``taken_*``: what the bridge took from each, x 1000)."""
    ri = c[RADIUS_I]
    rj = c[RADIUS_J]
    ratio = rj / ri
    split = 1.0 / (1.0 + ratio * ratio * ratio)
    rate = 1.0 / c[DT]
    c[LIQUID_FLUX_I] = rate * (split * bond_1000 - taken_i) / (FOUR_THIRDS_1000 * math.pi * ri * ri * ri)
    c[LIQUID_FLUX_J] = rate * ((1.0 - split) * bond_1000 - taken_j) / (FOUR_THIRDS_1000 * math.pi * rj * rj * rj)
