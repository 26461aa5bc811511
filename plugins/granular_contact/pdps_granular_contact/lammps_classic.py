r"""LAMMPS's classic granular contact laws, in LAMMPS's own formulas (their sub-models are
``pdps_granular_contact.classic``; ``contact_model`` composes them): the law of ``pair_style
gran/hooke``, ``gran/hooke/history`` and ``gran/hertz/history`` (Silbert et al., Phys. Rev. E 64,
051302 (2001); Brilliantov et al., Phys. Rev. E 53, 5382 (1996); Zhang & Makse, Phys. Rev. E 72,
011301 (2005)) and of ``fix wall/gran`` with those styles.

A contact of body i with body j (a sphere or a wall) with overlap :math:`\delta > 0`, unit normal
:math:`\mathbf{n}` from j to i, effective radius :math:`R^*` and effective mass :math:`m^*`; the
relative velocity :math:`\mathbf{v}_i - \mathbf{v}_j` has the normal part :math:`v_n` along
:math:`\mathbf{n}` and the tangential part :math:`\mathbf{v}_t`, and with the spins the contact
points slide at :math:`\mathbf{v}_{tr} = \mathbf{v}_t - (R_i\boldsymbol\omega_i +
R_j\boldsymbol\omega_j)\times\mathbf{n}` (classic.surface_default computes it: lever arms are the radii, as
LAMMPS). With :math:`s = 1` (Hooke) or :math:`s = \sqrt{\delta R^*}` (Hertz, LAMMPS's "polyhertz"):

.. math::

    F_n = s\,(k_n\delta - m^*\gamma_n v_n), \qquad F_n \leftarrow \max(F_n, 0)
    \text{ with limit\_damping}

- ``HOOKE`` (no history): :math:`\mathbf{F}_t = -\min(\mu|F_n|,\ m^*\gamma_t|\mathbf{v}_{tr}|)\,
  \mathbf{v}_{tr}/|\mathbf{v}_{tr}|`.
- ``HOOKE_HISTORY``, ``HERTZ_HISTORY``: the tangential spring :math:`\boldsymbol\xi` of the contact
  grows by :math:`\mathbf{v}_{tr}\Delta t` and is then projected onto the current tangent plane
  (:math:`\boldsymbol\xi \leftarrow \boldsymbol\xi - (\boldsymbol\xi\cdot\mathbf{n})\mathbf{n}`,
  without restoring its length: the rolling of the contact frame as LAMMPS does it), and

  .. math::

      \mathbf{F}_t = -s\,(k_t\boldsymbol\xi + m^*\gamma_t\mathbf{v}_{tr}); \quad
      |\mathbf{F}_t| > \mu|F_n| \Rightarrow
      \boldsymbol\xi \leftarrow \frac{\mu|F_n|}{|\mathbf{F}_t|}\Big(\boldsymbol\xi +
      \frac{m^*\gamma_t}{k_t}\mathbf{v}_{tr}\Big) - \frac{m^*\gamma_t}{k_t}\mathbf{v}_{tr},\
      \mathbf{F}_t \leftarrow \frac{\mu|F_n|}{|\mathbf{F}_t|}\mathbf{F}_t

  (a spring of zero length, :math:`|\boldsymbol\xi| = 0` before the projection, gives
  :math:`\mathbf{F}_t = 0` instead). In the setup force computation of a run (``update`` False) the
  spring is neither grown nor projected, only rescaled at the Coulomb limit, as LAMMPS.

- Walls (``wall=True``): LAMMPS's fix wall/gran computes the history styles with its granular
  sub-models, which differ from the pair styles in two places, reproduced here: the spring's
  stiffness is :math:`k_t\sqrt{\delta R^*}` for hooke/history as well as hertz/history (the damping
  keeps :math:`s`), and the spring cut back at the Coulomb limit is divided by :math:`k_t` alone:

  .. math::

      \mathbf{F}_t = -(k_t\sqrt{\delta R^*}\,\boldsymbol\xi + s\,m^*\gamma_t\mathbf{v}_{tr}), \qquad
      \boldsymbol\xi \leftarrow -\big(\tfrac{\mu|F_n|}{|\mathbf{F}_t|}\mathbf{F}_t +
      s\,m^*\gamma_t\mathbf{v}_{tr}\big)/k_t

Units as LAMMPS: :math:`k_n, k_t` force/distance (Hooke) or pressure (Hertz, the caller divides by
``nktv2p``), :math:`\gamma_n, \gamma_t` 1/time, :math:`\mu` dimensionless. Where LAMMPS would divide
by :math:`k_t = 0` at the Coulomb limit (and so fill the spring with NaN), the spring is set to
zero: with no stiffness it carries no force.
"""

import math
from typing import Annotated

from pydantic import BeforeValidator

from pdps_core.api import StyleArgs, param

HOOKE, HOOKE_HISTORY, HERTZ_HISTORY = 0, 1, 2
MODELS = {"hooke": HOOKE, "hooke/history": HOOKE_HISTORY, "hertz/history": HERTZ_HISTORY}


def _null(word):
    return None if word == "NULL" else word


# a number, or NULL for the default LAMMPS gives that argument
NullableFloat = Annotated[float | None, BeforeValidator(_null)]


class ClassicLaw(StyleArgs):
    """The law's script words as LAMMPS's pair gran/* and fix wall/gran take them:
    ``Kn Kt gamma_n gamma_t xmu dampflag`` (Kt NULL: 2/7 Kn; gamma_t NULL: gamma_n / 2)."""
    kn: float = param(ge=0, unit="force/distance", alias="Kn")
    kt: NullableFloat = param(ge=0, unit="force/distance", alias="Kt")
    gamma_n: float = param(ge=0, unit="1/time")
    gamma_t: NullableFloat = param(ge=0, unit="1/time")
    xmu: float = param(ge=0, le=10000, unit="dimensionless")
    dampflag: int = param(ge=0, le=1, unit="dimensionless")

    def constants(self, model, nktv2p):
        """(kn, kt, gamma_n, gamma_t) for ``model``: LAMMPS's defaults for NULL, no tangential
        damping with dampflag 0, and the Hertz stiffnesses from pressure to force/distance^2."""
        kt = 2.0 / 7.0 * self.kn if self.kt is None else self.kt
        gamma_t = 0.5 * self.gamma_n if self.gamma_t is None else self.gamma_t
        if self.dampflag == 0:
            gamma_t = 0.0
        kn = self.kn
        if model == HERTZ_HISTORY:
            kn, kt = kn / nktv2p, kt / nktv2p
        return kn, kt, self.gamma_n, gamma_t


def contact_model(model):
    """The classic law ``model`` composed of pdps_granular_contact.classic's sub-models."""
    from .composition import ContactModel
    return ContactModel("classic", {"normal": "hertz" if model == HERTZ_HISTORY else "hooke",
                                    "tangential": "no_history" if model == HOOKE else "history"})


def constants(model, kn, kt, gamma_n, gamma_t, xmu, limit_damping, ntypes):
    """The classic sub-models' coefficients (the same for every type pair)."""
    from .classic.base import Constants
    return Constants(ntypes, kn=kn, kt=kt, gamma_n=gamma_n, gamma_t=gamma_t, xmu=xmu, limit_damping=limit_damping,
                     hertz=model == HERTZ_HISTORY)


def contact_time(kn, gamma_n, m_eff):
    """Duration of a Hooke contact of LAMMPS's form (damping m* gamma_n): pi / sqrt(kn/m* -
    gamma_n^2/4); an overdamped one counts with its undamped pi sqrt(m*/kn)."""
    rate = kn / m_eff - 0.25 * gamma_n * gamma_n
    return math.pi / math.sqrt(rate) if rate > 0.0 else math.pi * math.sqrt(m_eff / kn)
