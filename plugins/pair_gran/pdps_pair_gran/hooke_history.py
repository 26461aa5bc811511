r"""Pair style ``gran/hooke/history``: LAMMPS's Hookean contacts between spheres with a tangential
spring per contact and Coulomb friction (LAMMPS's pair gran/hooke/history; Silbert et al., Phys.
Rev. E 64, 051302 (2001); Cundall & Strack, Geotechnique 29, 47 (1979)).

Spheres i and j touch when :math:`r < R_i + R_j`; with overlap :math:`\delta`, normal
:math:`\mathbf{n}`, normal relative speed :math:`v_n`, sliding velocity of the contact points
:math:`\mathbf{v}_{tr}` and effective mass :math:`m^*` (pdps_pair_gran.gran):

.. math::

    F_n = k_n\delta - m^*\gamma_n v_n, \qquad
    \mathbf{F}_t = -(k_t\boldsymbol\xi + m^*\gamma_t\mathbf{v}_{tr}), \quad |\mathbf{F}_t| \le \mu|F_n|

on i (:math:`-\mathbf{F}` on j), torques :math:`-R_{i,j}\,\mathbf{n}\times\mathbf{F}_t`. The spring
:math:`\boldsymbol\xi` grows by :math:`\mathbf{v}_{tr}\Delta t` each step, is projected onto the
current tangent plane (turning with the contact, its length not restored), and is cut back when the
contact slides so that the force sits on the Coulomb limit
(``pdps_granular_contact.lammps_classic``, LAMMPS's formulas). It lives while the spheres touch.

Parameters (LAMMPS's units: ``gamma`` is a rate, scaled by the effective mass):

- ``Kn`` normal elastic constant (force/distance, >= 0)
- ``Kt`` tangential elastic constant (force/distance, >= 0, or NULL for 2/7 Kn)
- ``gamma_n`` normal damping (1/time, >= 0)
- ``gamma_t`` tangential damping (1/time, >= 0, or NULL for gamma_n / 2)
- ``xmu`` friction coefficient (0 to 10000)
- ``dampflag`` 1: tangential damping on; 0: off (gamma_t = 0)
- ``limit_damping`` (optional word): the normal force is never attractive
- ``max_contacts N`` (pdps keyword, default 16): contacts a particle can hold at once

Syntax::

    pair_style gran/hooke/history Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]
    pair_coeff * *

A Hookean contact lasts :math:`t_c = \pi/\sqrt{k_n/m^* - \gamma_n^2/4}`; the run warns when the time
step is more than a tenth of it for the two lightest particles.

Example (the benchmark kit's in.gran_box)::

    pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 1
    pair_coeff * *
"""

from pdps_granular_contact import lammps_classic

from .gran import PairGran


class PairGranHookeHistory(PairGran):
    name = "gran/hooke/history"
    usage = "pair_style gran/hooke/history Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]"
    coeff_usage = "(no coefficients: pair_coeff * *)"
    model = lammps_classic.HOOKE_HISTORY
