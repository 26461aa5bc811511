r"""Pair style ``gran/hertz/history``: LAMMPS's Hertzian contacts between spheres with a tangential
spring per contact and Coulomb friction (LAMMPS's pair gran/hertz/history; Brilliantov et al., Phys.
Rev. E 53, 5382 (1996); Silbert et al., Phys. Rev. E 64, 051302 (2001); Zhang & Makse, Phys. Rev. E
72, 011301 (2005)).

The law of gran/hooke/history with every term scaled by the "polyhertz" factor
:math:`\sqrt{\delta R^*}`, :math:`R^* = R_iR_j/(R_i + R_j)`:

.. math::

    F_n = \sqrt{\delta R^*}\,(k_n\delta - m^*\gamma_n v_n), \qquad
    \mathbf{F}_t = -\sqrt{\delta R^*}\,(k_t\boldsymbol\xi + m^*\gamma_t\mathbf{v}_{tr}), \quad
    |\mathbf{F}_t| \le \mu|F_n|

with the spring :math:`\boldsymbol\xi` grown, projected and cut back at the Coulomb limit exactly as
in gran/hooke/history (the cut uses :math:`k_t` without the factor, as LAMMPS;
``pdps_granular_contact.lammps_classic``).

Parameters: as gran/hooke/history, except that ``Kn`` and ``Kt`` are in pressure units
(force/area) and are divided by the unit system's ``nktv2p`` (1 in lj and si units), as LAMMPS.
``gamma_n`` and ``gamma_t`` are in 1/(time distance).

Syntax::

    pair_style gran/hertz/history Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]
    pair_coeff * *

The time step is checked against the elastic Hertz contact time of the lightest particle at twice
the largest speed present, :math:`2.868\,(m^{*2}/(R^*E^{*2}v))^{1/5}` with :math:`E^* = 3k_n/4`.

Example::

    pair_style gran/hertz/history 2000000.0 NULL 50.0 NULL 0.5 0 limit_damping
    pair_coeff * *
"""

from pdps_granular_contact import lammps_classic

from .gran import PairGran


class PairGranHertzHistory(PairGran):
    name = "gran/hertz/history"
    usage = "pair_style gran/hertz/history Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]"
    coeff_usage = "(no coefficients: pair_coeff * *)"
    model = lammps_classic.HERTZ_HISTORY
