r"""Pair style ``gran/hooke``: LAMMPS's Hookean contacts between spheres with velocity damping and
friction, without a tangential spring (LAMMPS's pair gran/hooke; Silbert et al., Phys. Rev. E 64,
051302 (2001); Brilliantov et al., Phys. Rev. E 53, 5382 (1996)).

Spheres i and j touch when :math:`r < R_i + R_j`; with overlap :math:`\delta`, normal
:math:`\mathbf{n}`, normal relative speed :math:`v_n`, sliding velocity of the contact points
:math:`\mathbf{v}_{tr}` and effective mass :math:`m^* = m_im_j/(m_i+m_j)` (pdps_pair_gran.gran):

.. math::

    F_n = k_n\delta - m^*\gamma_n v_n, \qquad
    \mathbf{F}_t = -\min\big(\mu|F_n|,\ m^*\gamma_t|\mathbf{v}_{tr}|\big)\,
    \frac{\mathbf{v}_{tr}}{|\mathbf{v}_{tr}|}

on i (:math:`-\mathbf{F}` on j), and the torques :math:`-R_{i,j}\,\mathbf{n}\times\mathbf{F}_t`
(``pdps_granular_contact.lammps_classic``). With ``limit_damping`` a contact never pulls
(:math:`F_n < 0` set to 0).

Parameters (LAMMPS's units: ``gamma`` is a rate, scaled by the effective mass):

- ``Kn`` normal elastic constant (force/distance, >= 0)
- ``Kt`` tangential elastic constant (force/distance, >= 0, or NULL for 2/7 Kn); read but unused by
  this style, which has no spring
- ``gamma_n`` normal damping (1/time, >= 0)
- ``gamma_t`` tangential damping (1/time, >= 0, or NULL for gamma_n / 2)
- ``xmu`` friction coefficient (0 to 10000)
- ``dampflag`` 1: tangential damping on; 0: off (gamma_t = 0, so no tangential force at all)
- ``limit_damping`` (optional word): the normal force is never attractive
- ``max_contacts N`` (pdps keyword, default 16): accepted for symmetry with the history styles

Syntax::

    pair_style gran/hooke Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]
    pair_coeff * *

``pair_coeff * *`` takes no coefficients (one law for every type pair). Needs ``atom_style
sphere``; ghost particles carry velocities and spins without ``comm_modify vel yes``.

Example::

    pair_style gran/hooke 200000.0 NULL 50.0 NULL 0.5 0
    pair_coeff * *
"""

from pdps_granular_contact import lammps_classic

from .gran import PairGran


class PairGranHooke(PairGran):
    name = "gran/hooke"
    usage = "pair_style gran/hooke Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]"
    coeff_usage = "(no coefficients: pair_coeff * *)"
    model = lammps_classic.HOOKE
