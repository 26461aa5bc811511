r"""Cohesion model ``washino/capillary/viscous`` of LIGGGHTS 3.8.0: the liquid bridge of two wet
spheres, Rabinovich's capillary force and Nase's viscous force, and the liquid the bridge moves
between the particles. (LIGGGHTS names it after Washino; its manual cites, for the parts, Lian et
al., Nase et al. and Rabinovich et al., as here.)

Bridge. Its volume is a fraction f of both films, :math:`V = f\,(c_iV_{s,i} + c_jV_{s,j})` (c,
:math:`V_s` each sphere's surface liquid content and solid volume, ``liquid_bridge``; f = 0.05, or
``lbVolumeFraction`` with ``modifyLbVolume on``). It forms when the surfaces come closer than
:math:`\min(s_c,\ (R_i + R_j)(\rho_{max} - 1))`, touching or not, and breaks beyond it (Lian,
Thornton & Adams, J. Colloid Interface Sci. 161, 138 (1993)):

.. math::

    s_c = \left(1 + \tfrac{\theta}{2}\right)V^{1/3}

:math:`\rho_{max}` = ``maxSeparationDistanceRatio``, θ the effective contact angle
:math:`\tfrac12\theta_i\theta_j` (radians; LIGGGHTS 3.8.0's code, where its manual and its code after
2021 take the mean). A bridge of :math:`V < 10^{-17}` exerts no force.

Capillary force (Rabinovich, Esayanur & Moudgil, Langmuir 21, 10992 (2005)), :math:`R^* =
R_iR_j/(R_i+R_j)`, σ the surface tension, s the surface distance: while the spheres touch (s =
:math:`-\delta` < 0, eq. A11)

.. math::

    F_{cap} = -2\pi R^*\sigma\cos\theta\left(1 - s\sqrt{\frac{\pi R^*}{2V}}\right)

and apart (s > 0, eqs. 19, 20, A3)

.. math::

    F_{cap} = -2\pi R^*\sigma\left(\frac{\cos\theta}{1 + s/2d} + \sin\alpha\,\sin(\alpha + \theta)\right),
    \quad d = \tfrac{s}{2}\left(\sqrt{1 + \frac{2V}{\pi R^* s^2}} - 1\right), \quad
    \alpha = \sqrt{\frac{2d}{R^*}}

(at s = 0 exactly, the limit :math:`sd^{-1}\to 0`, :math:`2d \to \sqrt{2V/\pi R^*}`). Viscous force:
Nase et al.'s (``liquid_bridge``), at ρ = ``minSeparationDistanceRatio`` while the spheres touch.
Both act on top of the normal and tangential models; with ``tangential_reduce on`` the normal force
the Coulomb limit and the rolling cap read includes :math:`F_{cap} + F_{n,visc}` while the spheres
touch (default off). Spheres apart turn about lever arms of their radii, and the other models'
histories are zeroed there (LIGGGHTS's surfacesClose).

Liquid. A breaking bridge gives its volume back by the solid volumes (``liquid_bridge``), the
content each particle lent it being :math:`f\,c\,V_s`; the liquid volume :math:`\sum cV_s` is
conserved. With ``limitLiquidContent on``, a particle's content is lowered to ``maxLiquidContent``
of its type whenever one of its pairs is evaluated, and :math:`\rho_{max}` is replaced by
:math:`1 + \max_t s_{c,t}/2R_{min}`, :math:`s_{c,t}` the rupture distance of a bridge of
:math:`2f\,c_{max,t}\tfrac43\pi R_{max}^3` at angle :math:`\tfrac12\theta_t^2`, over the radii of the
particles present (a warning gives it; LIGGGHTS also counts particles an insertion will bring, so
pdps refuses it with one). Contents start at surfaceLiquidContentInitial and are kept per atom as
easo/capillary/viscous's (``surfaceLiquidContent``, ``liquidFlux``, ``liquidSource``).

Neighbors: spheres closer than :math:`1.1\rho_{max}(R_i + R_j)` are evaluated (LIGGGHTS's contact
distance factor; the neighbor cutoff covers it).

Material, from ``fix property/global`` (each read at the start of a run):

- ``surfaceLiquidContentInitial scalar c0`` (>= 0, liquid volume per solid volume),
  ``surfaceTension scalar σ`` (force/length, >= 0), ``fluidViscosity scalar η`` (pressure x time,
  >= 0), ``contactAngle peratomtype θ1 ... θN`` (degrees, in [0, 180]),
  ``minSeparationDistanceRatio scalar`` (> 0), ``maxSeparationDistanceRatio scalar`` (> 0);
- with ``limitLiquidContent on``: ``maxLiquidContent peratomtype c1 ... cN`` (in [0, 1]);
- with ``modifyLbVolume on``: ``lbVolumeFraction scalar f`` (in [0, 1]).

Restrictions: pair gran only (LIGGGHTS's manual; fix wall/gran refuses it). A run's setup force
computation makes no new bridge slot (LIGGGHTS marks a bridge there).

Syntax: ``pair_style gran model ... tangential ... cohesion washino/capillary/viscous
[tangential_reduce on|off] [limitLiquidContent on|off] [modifyLbVolume on|off]``

Example (LIGGGHTS, SI units)::

    fix l1 all property/global surfaceLiquidContentInitial scalar 0.01
    fix l2 all property/global surfaceTension scalar 0.072
    fix l3 all property/global fluidViscosity scalar 0.001
    fix l4 all property/global contactAngle peratomtype 30
    fix l5 all property/global minSeparationDistanceRatio scalar 1.01
    fix l6 all property/global maxSeparationDistanceRatio scalar 1.1
    fix l7 all property/global lbVolumeFraction scalar 0.1
    pair_style gran model hertz tangential history cohesion washino/capillary/viscous modifyLbVolume on
    pair_coeff * *
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError
from pdps_granular_contact.contact_state import FN, FN_LIMIT, LIQUID_I, LIQUID_J, R, RADIUS_I, RADIUS_J, R_EFF

from .base import GranSubModel
from .liquid_bridge import (PROPERTIES, SMALLEST_BRIDGE, _finite, contact_angle, liquid_1000, rupture_distance, share_out,
                            viscous_drag)

# LIGGGHTS's default share of both films in a bridge
VOLUME_FRACTION = 0.05
# LIGGGHTS's 2 x 4/3 x 1000, as its code writes it
EIGHT_THIRDS_1000 = 2666.666666


@njit(cache=True)
def washino_liquid(c, k):
    """The liquid of i and of j (x 1000), their contents capped first where k[7] says so."""
    if k[7] != 0.0:
        if c[LIQUID_I] > k[8]:
            c[LIQUID_I] = k[8]
        if c[LIQUID_J] > k[9]:
            c[LIQUID_J] = k[9]
    return liquid_1000(c)


@njit(cache=True)
def washino_touching(c, k, hist, h):
    """k: surface tension, viscosity, effective contact angle (rad), rho_min, rho_max, volume
    fraction, tangential_reduce, limitLiquidContent (1/0), the contents' caps of i's and j's type;
    hist[h]: 1 while a bridge holds."""
    hist[h] = 1.0
    liquid_i, liquid_j = washino_liquid(c, k)
    bond = (liquid_i + liquid_j) * k[5]
    if bond < SMALLEST_BRIDGE:
        return
    r_eff = c[R_EFF]
    distance = c[R] - (c[RADIUS_I] + c[RADIUS_J])
    pull = -2.0 * math.pi * r_eff * k[0] * math.cos(k[2]) * (1.0 - distance * math.sqrt(1000.0 * math.pi * r_eff
                                                                                         / (2.0 * bond)))
    normal = pull + viscous_drag(c, k[1], k[3])
    c[FN] += normal
    if k[6] != 0.0:
        c[FN_LIMIT] += normal


@njit(cache=True)
def rabinovich_force(sigma, theta, r_eff, bond_1000, distance):
    """Rabinovich et al.'s capillary force of spheres apart (module docstring)."""
    if distance > 0.0:
        prefactor = -1.0 + math.sqrt(1.0 + 2.0 * bond_1000 / (math.pi * r_eff * 1000.0 * distance * distance))
        gap = 0.5 * distance * prefactor
        alpha = math.sqrt(distance / r_eff * prefactor)
        neck = math.cos(theta) / (1.0 + distance / (2.0 * gap))
    else:
        alpha = math.sqrt(math.sqrt(2.0 * bond_1000 / (math.pi * r_eff * 1000.0)) / r_eff)
        neck = math.cos(theta)
    return -2.0 * math.pi * r_eff * sigma * (neck + math.sin(alpha) * math.sin(alpha + theta))


@njit(cache=True)
def washino_apart(c, k, hist, h):
    """The spheres apart: a bridge holds (or forms) while shorter than its rupture distance and the
    cap, else one that held breaks and shares its liquid out."""
    liquid_i, liquid_j = washino_liquid(c, k)
    bond = (liquid_i + liquid_j) * k[5]
    radsum = c[RADIUS_I] + c[RADIUS_J]
    distance = c[R] - radsum
    if distance < rupture_distance(k[2], bond) and distance < (k[4] - 1.0) * radsum:
        hist[h] = 1.0
        if bond < SMALLEST_BRIDGE:
            return
        ratio = max(k[3], distance / c[R_EFF])
        c[FN] += rabinovich_force(k[0], k[2], c[R_EFF], bond, distance) + viscous_drag(c, k[1], ratio)
    elif hist[h] > 0.5:
        hist[h] = 0.0
        share_out(c, bond, k[5] * liquid_i, k[5] * liquid_j)


class CohesionWashinoCapillaryViscous(GranSubModel):
    kind = "gran.cohesion"
    name = "washino/capillary/viscous"
    compute = washino_touching
    close = washino_apart
    wet = True
    history_width = 1
    history_transfer = (1,)
    settings_read = {"tangential_reduce": "off", "limitLiquidContent": "off", "modifyLbVolume": "off"}
    properties = {**PROPERTIES,
                  "maxSeparationDistanceRatio": ("scalar", "scalar", _finite(lambda r: r > 0), "> 0"),
                  "maxLiquidContent": ("per_type", "peratomtype", _finite(lambda c: 0 <= c <= 1), "in [0, 1]"),
                  "lbVolumeFraction": ("scalar", "scalar", _finite(lambda f: 0 <= f <= 1), "in [0, 1]")}

    def coefficients(self, material):
        n = material.ntypes + 1
        material.property("surfaceLiquidContentInitial")
        theta = contact_angle(material)
        fraction = material.property("lbVolumeFraction") if self.on("modifyLbVolume") else VOLUME_FRACTION
        self.max_ratio = material.property("maxSeparationDistanceRatio")
        caps = np.zeros(n)
        if self.on("limitLiquidContent"):
            caps = material.property("maxLiquidContent")
            self.max_ratio = self.limited_ratio(material, caps, fraction)
        return material.columns(material.property("surfaceTension"), material.property("fluidViscosity"), theta,
                                material.property("minSeparationDistanceRatio"), self.max_ratio, fraction,
                                self.on("tangential_reduce"), self.on("limitLiquidContent"),
                                np.repeat(caps[:, None], n, axis=1), np.repeat(caps[None, :], n, axis=0))

    def limited_ratio(self, material, caps, fraction):
        """LIGGGHTS's maxSeparationDistanceRatio under limitLiquidContent (module docstring)."""
        sim = material.sim
        if any(fix.inserted_radius(t) > 0.0 for fix in sim.fixes.values() for t in range(1, material.ntypes + 1)):
            raise ScriptError("cohesion washino/capillary/viscous: limitLiquidContent with particles inserted during "
                              "the run is not supported (LIGGGHTS sizes the bridges by the smallest radius an "
                              "insertion will bring)")
        p = sim.particles
        radius = p.radius[:p.nlocal]
        largest = sim.comm.max(float(radius.max()) if len(radius) else -1.0)
        smallest = sim.comm.min(float(radius.min()) if len(radius) else math.inf)
        theta = material.property("contactAngle") * math.pi / 180.0
        ratio = 0.0
        for t in range(1, material.ntypes + 1):
            bond = EIGHT_THIRDS_1000 * math.pi * largest * largest * largest * caps[t] * fraction
            longest = (1.0 + 0.5 * (0.5 * theta[t] * theta[t])) * float(np.cbrt(bond)) * 0.1
            ratio = max(0.5 * longest / smallest, ratio)
        given = material.property("maxSeparationDistanceRatio")
        sim.warn(f"maxLiquidContent was specified, resulting in maxSeparationDistanceRatio being overwritten by "
                 f"{1.0 + ratio:e} (was {given:e})")
        return 1.0 + ratio

    def reach(self, material):
        return 1.1 * self.max_ratio
