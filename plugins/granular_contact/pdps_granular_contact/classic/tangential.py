r"""Tangential models ``history`` and ``no_history`` of LAMMPS's classic granular styles (formulas:
``pdps_granular_contact.lammps_classic``): with :math:`s` the normal model's scale (1 or
:math:`\sqrt{\delta R^*}`),

- ``no_history``: :math:`\mathbf{F}_t = -\min(\mu|F_n|,\ s\,m^*\gamma_t|\mathbf{v}_{tr}|)\,
  \mathbf{v}_{tr}/|\mathbf{v}_{tr}|`;
- ``history`` (3 values): the spring grows by :math:`\mathbf{v}_{tr}\Delta t`, is projected onto the
  tangent plane (its length not restored), :math:`\mathbf{F}_t = -(s\,k_t\boldsymbol\xi +
  s\,m^*\gamma_t\mathbf{v}_{tr})` and is cut back at the Coulomb limit; against a wall (LAMMPS's fix
  wall/gran) the spring's stiffness is :math:`k_t\sqrt{\delta R^*}` for hooke too and the cut-back
  spring is divided by :math:`k_t` alone. In a run's setup the spring is neither grown nor projected.
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (DELTA, DT, FN_LIMIT, FTX, FTY, FTZ, M_EFF, NX, NY, NZ, R_EFF,
                                                 UPDATE, VTX, VTY, VTZ, WALL)

from .base import ClassicSubModel


@njit(cache=True)
def no_history_force(c, k, hist, h):
    """k: gamma_t, xmu, hertz (1/0)."""
    overlap = c[DELTA]
    scale = math.sqrt(overlap * c[R_EFF]) if k[2] != 0.0 else 1.0
    fn_limit = k[1] * abs(c[FN_LIMIT])
    damping = c[M_EFF] * k[0] * scale
    vrel = math.sqrt(c[VTX] * c[VTX] + c[VTY] * c[VTY] + c[VTZ] * c[VTZ])
    ft = min(fn_limit, damping * vrel) / vrel if vrel != 0.0 else 0.0
    c[FTX] = -ft * c[VTX]
    c[FTY] = -ft * c[VTY]
    c[FTZ] = -ft * c[VTZ]


@njit(cache=True)
def history_force(c, k, hist, h):
    """k: kt, gamma_t, xmu, hertz (1/0)."""
    overlap = c[DELTA]
    root = math.sqrt(overlap * c[R_EFF])
    scale = root if k[3] != 0.0 else 1.0
    fn_limit = k[2] * abs(c[FN_LIMIT])
    damping = c[M_EFF] * k[1] * scale
    wall = c[WALL] > 0.0
    stiffness = k[0] * root if wall else k[0] * scale
    relaxed = k[0] if wall else k[0] * scale
    update = c[UPDATE] != 0.0
    if update:
        dt = c[DT]
        hist[h] += c[VTX] * dt
        hist[h + 1] += c[VTY] * dt
        hist[h + 2] += c[VTZ] * dt
    length = math.sqrt(hist[h] * hist[h] + hist[h + 1] * hist[h + 1] + hist[h + 2] * hist[h + 2])
    if update:
        along = hist[h] * c[NX] + hist[h + 1] * c[NY] + hist[h + 2] * c[NZ]
        hist[h] -= along * c[NX]
        hist[h + 1] -= along * c[NY]
        hist[h + 2] -= along * c[NZ]
    ft0 = -(stiffness * hist[h] + damping * c[VTX])
    ft1 = -(stiffness * hist[h + 1] + damping * c[VTY])
    ft2 = -(stiffness * hist[h + 2] + damping * c[VTZ])
    fs = math.sqrt(ft0 * ft0 + ft1 * ft1 + ft2 * ft2)
    if fs > fn_limit:
        if length != 0.0:
            ratio = fn_limit / fs
            ft0 *= ratio
            ft1 *= ratio
            ft2 *= ratio
            hist[h] = -(ft0 + damping * c[VTX]) / relaxed if relaxed > 0.0 else 0.0
            hist[h + 1] = -(ft1 + damping * c[VTY]) / relaxed if relaxed > 0.0 else 0.0
            hist[h + 2] = -(ft2 + damping * c[VTZ]) / relaxed if relaxed > 0.0 else 0.0
        else:
            ft0 = 0.0
            ft1 = 0.0
            ft2 = 0.0
    c[FTX] = ft0
    c[FTY] = ft1
    c[FTZ] = ft2


class TangentialNoHistory(ClassicSubModel):
    kind = "classic.tangential"
    name = "no_history"
    compute = no_history_force
    names = ("gamma_t", "xmu", "hertz")


class TangentialHistory(ClassicSubModel):
    kind = "classic.tangential"
    name = "history"
    history_width = 3
    compute = history_force
    names = ("kt", "gamma_t", "xmu", "hertz")
