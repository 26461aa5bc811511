r"""Cohesion model ``easo/capillary/viscous`` of LIGGGHTS 3.8.0: the liquid bridge of two wet
spheres, a capillary and a viscous force, as composed by Easo & Wassgren (Comparison of Liquid
Bridge Volume Models in DEM Simulations, AIChE Annual Meeting (2013)), and the liquid the bridge
moves between the particles.

Bridge. It forms when the spheres touch and lasts until their surfaces are s apart with

.. math::

    s \ge \min\left(s_c,\ (R_i + R_j)(\rho_{max} - 1)\right), \qquad
    s_c = \left(1 + \tfrac{\theta}{2}\right)V^{1/3}

(Lian, Thornton & Adams, J. Colloid Interface Sci. 161, 138 (1993)), :math:`\rho_{max}` =
``maxSeparationDistanceRatio``. Its volume is what each particle's film holds in the cap the other
sphere covers,

.. math::

    V = \tfrac12 c_iV_{s,i}\Big(1 - \sqrt{1 - R_j^2/(R_i+R_j)^2}\Big)
      + \tfrac12 c_jV_{s,j}\Big(1 - \sqrt{1 - R_i^2/(R_i+R_j)^2}\Big)

(LIGGGHTS's code; its manual says :math:`0.05\,(c_iV_{s,i} + c_jV_{s,j})`), with c, :math:`V_s` the
surface liquid content and solid volume of each sphere (``liquid_bridge``), θ the effective contact
angle :math:`\tfrac12\theta_i\theta_j` (radians; LIGGGHTS 3.8.0's code, where its manual and its
code after 2021 take the mean of the two). A bridge of :math:`V < 10^{-17}` exerts no force.

Capillary force (Soulié et al., Int. J. Numer. Anal. Methods Geomech. 30, 213 (2006)), along the
normal, at surface distance s (0 while the spheres touch), :math:`R_2 = \max(R_i, R_j)`,
:math:`\hat V = V/R_2^3`:

.. math::

    F_{cap} = -\pi\sigma\sqrt{R_iR_j}\,\left(e^{As/R_2 + B} + C\right), \quad
    A = -1.1\hat V^{-0.53}, \quad B = (-0.148\ln\hat V - 0.96)\theta^2 - 0.0082\ln\hat V + 0.48,
    \quad C = 0.0018\ln\hat V + 0.078

Viscous force: Nase et al.'s (``liquid_bridge``), at ρ = ``minSeparationDistanceRatio`` while the
spheres touch. Both act on top of the normal and tangential models; with ``tangential_reduce on``
the normal force the Coulomb limit and the rolling cap read includes :math:`F_{cap} + F_{n,visc}`
while the spheres touch (default off: it does not). Spheres apart turn about lever arms of their
radii, and the other models' histories are zeroed there (LIGGGHTS's surfacesClose).

Liquid. When the bridge breaks, its volume goes back to both particles by their solid volumes
(``liquid_bridge``; the liquid volume :math:`\sum c V_s` is conserved). Each particle's content
starts at surfaceLiquidContentInitial (as LIGGGHTS prints it, %e: seven significant digits) and is kept in the
per-atom ``surfaceLiquidContent`` (``f_surfaceLiquidContent`` or ``f_surfaceLiquidContent[0]`` in a
LIGGGHTS script), with ``liquidFlux`` (content/time, this step's) and ``liquidSource``
(content/time, 0 unless ``set property/atom liquidSource`` gives one).

Neighbors: spheres closer than :math:`1.1\rho_{max}(R_i + R_j)` are evaluated (LIGGGHTS's contact
distance factor; the neighbor cutoff covers it).

Material, from ``fix property/global`` (each read at the start of a run):

- ``surfaceLiquidContentInitial scalar c0``: the content of every particle at first (>= 0, volume
  of liquid per volume of solid);
- ``surfaceTension scalar σ``: force/length (>= 0);
- ``fluidViscosity scalar η``: pressure x time (>= 0);
- ``contactAngle peratomtype θ1 ... θN``: degrees, in [0, 180];
- ``minSeparationDistanceRatio scalar``: :math:`\rho_{min}` (> 0; LIGGGHTS suggests 1.01);
- ``maxSeparationDistanceRatio scalar``: :math:`\rho_{max}` (>= 1, as LIGGGHTS requires; it
  suggests 1.1).

Restrictions: pair gran only (LIGGGHTS's manual; fix wall/gran refuses it). A run's setup force
computation makes no new bridge slot (LIGGGHTS marks a bridge of spheres touching then).

Syntax: ``pair_style gran model ... tangential ... cohesion easo/capillary/viscous
[tangential_reduce on|off]``

Example (LIGGGHTS, SI units)::

    fix l1 all property/global surfaceLiquidContentInitial scalar 0.01
    fix l2 all property/global surfaceTension scalar 0.072
    fix l3 all property/global fluidViscosity scalar 0.001
    fix l4 all property/global contactAngle peratomtype 30
    fix l5 all property/global minSeparationDistanceRatio scalar 1.01
    fix l6 all property/global maxSeparationDistanceRatio scalar 1.1
    pair_style gran model hertz tangential history cohesion easo/capillary/viscous
    pair_coeff * *
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import FN, FN_LIMIT, R, RADIUS_I, RADIUS_J, R_EFF

from .base import GranSubModel
from .liquid_bridge import (PROPERTIES, SMALLEST_BRIDGE, _finite, contact_angle, liquid_1000, rupture_distance, share_out,
                            viscous_drag)


@njit(cache=True)
def easo_shares(c):
    """What each sphere's film gives the bridge (x 1000): the cap the other sphere covers, halved."""
    ri = c[RADIUS_I]
    rj = c[RADIUS_J]
    radsum = ri + rj
    liquid_i, liquid_j = liquid_1000(c)
    return (0.5 * liquid_i * (1.0 - math.sqrt(1.0 - rj * rj / (radsum * radsum))),
            0.5 * liquid_j * (1.0 - math.sqrt(1.0 - ri * ri / (radsum * radsum))))


@njit(cache=True)
def soulie_force(sigma, theta, ri, rj, bond_1000, distance):
    """Soulié et al.'s capillary force of a bridge of volume bond_1000 / 1000 at surface distance
    ``distance`` (module docstring)."""
    larger = ri if ri >= rj else rj
    inverse = 1.0 / larger
    scaled = bond_1000 * inverse * 0.001 * inverse * inverse
    log_v = math.log(scaled)
    a = -1.1 * scaled ** -0.53
    b = (-0.148 * log_v - 0.96) * theta * theta - 0.0082 * log_v + 0.48
    offset = 0.0018 * log_v + 0.078
    return -math.pi * sigma * math.sqrt(ri * rj) * (math.exp(a * distance / larger + b) + offset)


@njit(cache=True)
def easo_touching(c, k, hist, h):
    """k: surface tension, viscosity, effective contact angle (rad), rho_min, rho_max,
    tangential_reduce (1/0); hist[h]: 1 while a bridge holds."""
    hist[h] = 1.0
    share_i, share_j = easo_shares(c)
    bond = share_i + share_j
    if bond < SMALLEST_BRIDGE:
        return
    normal = soulie_force(k[0], k[2], c[RADIUS_I], c[RADIUS_J], bond, 0.0) + viscous_drag(c, k[1], k[3])
    c[FN] += normal
    if k[5] != 0.0:
        c[FN_LIMIT] += normal


@njit(cache=True)
def easo_apart(c, k, hist, h):
    """The spheres apart: a bridge made at contact holds while shorter than its rupture distance
    and the cap, else it breaks and shares its liquid out."""
    if hist[h] < 0.5:
        return
    radsum = c[RADIUS_I] + c[RADIUS_J]
    distance = c[R] - radsum
    share_i, share_j = easo_shares(c)
    bond = share_i + share_j
    if distance < rupture_distance(k[2], bond) and distance < (k[4] - 1.0) * radsum:
        if bond < SMALLEST_BRIDGE:
            return
        ratio = max(k[3], distance / c[R_EFF])
        c[FN] += soulie_force(k[0], k[2], c[RADIUS_I], c[RADIUS_J], bond, distance) + viscous_drag(c, k[1], ratio)
    else:
        hist[h] = 0.0
        share_out(c, bond, share_i, share_j)


class CohesionEasoCapillaryViscous(GranSubModel):
    kind = "gran.cohesion"
    name = "easo/capillary/viscous"
    compute = easo_touching
    close = easo_apart
    wet = True
    history_width = 1
    history_transfer = (1,)
    settings_read = {"tangential_reduce": "off"}
    properties = {**PROPERTIES,
                  "maxSeparationDistanceRatio": ("scalar", "scalar", _finite(lambda r: r >= 1.0), ">= 1")}

    def coefficients(self, material):
        self.max_ratio = material.property("maxSeparationDistanceRatio")
        material.property("surfaceLiquidContentInitial")
        return material.columns(material.property("surfaceTension"), material.property("fluidViscosity"),
                                contact_angle(material), material.property("minSeparationDistanceRatio"),
                                self.max_ratio, self.on("tangential_reduce"))

    def reach(self, material):
        return 1.1 * self.max_ratio
