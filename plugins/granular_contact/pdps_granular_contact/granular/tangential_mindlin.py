r"""Tangential model ``mindlin`` of LAMMPS's pair granular: Mindlin's spring, stiffening with the
contact radius a, with a dashpot and Coulomb's limit,

.. math::

    \mathbf{F}_t = -k_t a\,\boldsymbol\xi - \eta_t\mathbf{v}_{tr}, \quad \eta_t = x_{\gamma,t}\eta_n,
    \qquad |\mathbf{F}_t| \le \mu_s F_{n,crit}

The spring :math:`\boldsymbol\xi` (3 values of history) turns and grows as linear_history's (turned
when :math:`k_ta|\boldsymbol\xi\cdot\mathbf{n}| > 10^{-10}\mu_sF_{n,crit}`, then
:math:`+\mathbf{v}_{tr}\Delta t`) and is cut back at the Coulomb limit to
:math:`-(\mathbf{F}_t + \eta_t\mathbf{v}_{tr})/k_ta`. Coefficients: ``k_t`` (force/area, >= 0,
or NULL: :math:`8G^*` of the normal model's material, :math:`1/G^* = 2(2-\nu)(1+\nu)/E` twice over;
for types mixed, of the mixed E* and ν as LAMMPS computes it), ``x_gamma_t`` (dimensionless),
``mu_s`` (dimensionless); mixed as geometric means (NULL stays NULL). Its variants, each a module of
its own: ``mindlin/force`` keeps the force instead of the displacement
(:math:`\boldsymbol\xi \mathrel{+}= -k_ta\,\mathbf{v}_{tr}\Delta t`, :math:`\mathbf{F}_t =
\boldsymbol\xi - \eta_t\mathbf{v}_{tr}`; Thornton et al., Powder Technol. 233, 30 (2013));
``mindlin_rescale`` and ``mindlin_rescale/force`` also keep the contact radius of the last step (a
4th value) and scale the spring by :math:`a/a_{prev}` while the contact unloads (:math:`a <
a_{prev}`).

Syntax: ``pair_coeff I J ... tangential mindlin k_t|NULL x_gamma_t mu_s`` (LAMMPS's pair granular;
Mindlin, J. Appl. Mech. 16, 259 (1949)).
"""

from numba import njit

from pdps_core.api import ScriptError, param

from pdps_granular_contact.contact_state import (CONTACT_RADIUS, DT, FN_LIMIT, FTX, FTY, FTZ, GAMMA_N, GAMMA_T, KT,
                                                 UPDATE, VTX, VTY, VTZ)
from pdps_granular_contact.lammps_classic import NullableFloat

from .base import GranularSubModel, StyleArgs, effective_shear_modulus, mix_geom
from .frame import EPSILON, along_normal, coulomb_cut, rotate_rescale


@njit(cache=True)
def coulomb_limit(c, hist, h, per_history, x_gamma_t, limit, stiffness):
    """F_t = per_history * hist[h:h+3] - eta_t v_tr into FT, cut back to ``limit`` with the history
    set to the elastic part of the cut force (none for a history of zero length); KT and GAMMA_T
    get the stiffness and eta_t (marshall twisting reads them)."""
    damp = x_gamma_t * c[GAMMA_N]
    c[GAMMA_T] = damp
    c[KT] = stiffness
    dx = -damp * c[VTX]
    dy = -damp * c[VTY]
    dz = -damp * c[VTZ]
    fx, fy, fz = coulomb_cut(hist, h, per_history * hist[h] + dx, per_history * hist[h + 1] + dy,
                             per_history * hist[h + 2] + dz, dx, dy, dz, limit, per_history, True)
    c[FTX] = fx
    c[FTY] = fy
    c[FTZ] = fz


@njit(cache=True)
def mindlin_spring(c, k, hist, h, keeps_force, rescales):
    """k: k_t, x_gamma_t, mu_s."""
    a = c[CONTACT_RADIUS]
    stiffness = k[0] * a
    limit = k[2] * c[FN_LIMIT]
    if rescales:
        before = hist[h + 3]
        if a < before:
            ratio = a / before
            hist[h] *= ratio
            hist[h + 1] *= ratio
            hist[h + 2] *= ratio
    if c[UPDATE] != 0.0:
        along = abs(along_normal(c, hist, h))
        if (along if keeps_force else along * stiffness) > EPSILON * limit:
            rotate_rescale(c, hist, h)
        step = -stiffness * c[DT] if keeps_force else c[DT]
        hist[h] += c[VTX] * step
        hist[h + 1] += c[VTY] * step
        hist[h + 2] += c[VTZ] * step
        if rescales:
            hist[h + 3] = a
    coulomb_limit(c, hist, h, 1.0 if keeps_force else -stiffness, k[1], limit, k[0])


@njit(cache=True)
def mindlin_force(c, k, hist, h):
    mindlin_spring(c, k, hist, h, False, False)


class MindlinCoefficients(StyleArgs):
    k_t: NullableFloat = param(ge=0, unit="pressure")
    x_gamma_t: float = param(ge=0, unit="dimensionless")
    mu_s: float = param(ge=0, unit="dimensionless")


class TangentialMindlin(GranularSubModel):
    kind = "granular.tangential"
    name = "mindlin"
    Args = MindlinCoefficients
    compute = mindlin_force
    history_width = 3

    @classmethod
    def mix(cls, ci, cj):
        k_t = None if ci.k_t is None or cj.k_t is None else mix_geom(ci.k_t, cj.k_t)
        return cls.Args(k_t=k_t, x_gamma_t=mix_geom(ci.x_gamma_t, cj.x_gamma_t), mu_s=mix_geom(ci.mu_s, cj.mu_s))

    @classmethod
    def check(cls, law):
        if law.args("tangential").k_t is None and not getattr(law.parts["normal"][0], "material", False):
            raise ScriptError(f"tangential {cls.name}: k_t NULL takes the stiffness from the normal model's material, "
                              f"which {law.name('normal')} has not (use hertz/material, dmt or jkr, or give k_t)")

    def values(self, law, contact):
        args = law.args("tangential")
        k_t = args.k_t
        if k_t is None:
            normal = law.args("normal")
            k_t = 8.0 * effective_shear_modulus(normal.E, normal.E, normal.nu, normal.nu)
        return (k_t, args.x_gamma_t, args.mu_s)
