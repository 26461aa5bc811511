r"""Damping model ``coeff_restitution`` of LAMMPS's pair granular: tsuji's dashpot with the factor of
the linear or Hertzian spring that gives the restitution coefficient e exactly,

.. math::

    \eta_n = \alpha\sqrt{m^* F_{ne}/\delta}, \qquad
    \alpha = \frac{-2\ln e}{\sqrt{\pi^2 + \ln^2 e}}\ \text{(hooke)}, \qquad
    \alpha = \frac{-\sqrt{3/2}\cdot 2\sqrt{5/6}\,\ln e}{\sqrt{\pi^2 + \ln^2 e}}\ \text{(other normal models)}

with the normal model's ``eta_n0`` read as e (dimensionless, 0 < e <= 1). For hooke (a linear
oscillator damped by :math:`\alpha\sqrt{m^*k_n}`) the rebound speed is e times the impact speed
for any speed; for Hertz the factor is LIGGGHTS's (Tsuji's form with e's own β), which makes the
restitution nearly e. Cannot be used with a cohesive normal model, as LAMMPS.

Syntax: ``pair_coeff I J NORMAL ... damping coeff_restitution ...`` (LAMMPS's pair granular).
"""

import math

from .damping_tsuji import DampingTsuji, stiffness_damping


class DampingCoeffRestitution(DampingTsuji):
    name = "coeff_restitution"
    compute = stiffness_damping

    def coefficient(self, law):
        log_e = math.log(law.args("normal").eta_n0)
        alpha = -log_e / math.sqrt(math.pi * math.pi + log_e * log_e)
        if law.name("normal") == "hooke":
            return 2.0 * alpha
        return math.sqrt(1.5) * 2.0 * math.sqrt(5.0 / 6.0) * alpha
