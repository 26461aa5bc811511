r"""Heat model ``conduction`` of LIGGGHTS's granular contacts: the heat flux of fix heat/gran
(Chaudhuri et al., Chem. Eng. Sci. 61, 6348 (2006)), through the contact spot of two spheres,

.. math::

    Q_{ij} = \frac{4k_ik_j}{k_i + k_j}\sqrt{A_{ij}}\,(T_j - T_i)

into i (:math:`-Q_{ij}` into j), k the thermal conductivity of each particle's type (``fix
property/global thermalConductivity peratomtype``, energy/(time distance temperature); 0 for either:
no flux), A the contact area: ``overlap`` the circle where the spheres intersect (the smaller
sphere's cross-section once its centre is inside the other), ``projection`` :math:`\pi\max(R_i,
R_j)^2`, ``constant`` a given area. No history. Composed into pair gran's contacts by fix heat/gran
(``pdps doc fix heat/gran``), which integrates the temperatures; not a word of pair gran's.
"""

import math

import numpy as np
from numba import njit

from pdps_granular_contact.contact_state import HEAT, R, RADIUS_I, RADIUS_J, TEMPERATURE_I, TEMPERATURE_J

from .base import GranSubModel
from .cohesion_sjkr import sjkr_area

OVERLAP, CONSTANT, PROJECTION = 0, 1, 2
AREAS = {"overlap": OVERLAP, "constant": CONSTANT, "projection": PROJECTION}


@njit(cache=True)
def conduction_heat(c, k, hist, h):
    """k: 4 k_i k_j / (k_i + k_j) (0: no flux), area model, constant area."""
    if k[0] <= 0.0:
        return
    if k[1] == OVERLAP:
        area = sjkr_area(c[R], c[RADIUS_I], c[RADIUS_J], False)
    elif k[1] == CONSTANT:
        area = k[2]
    else:
        area = math.pi * max(c[RADIUS_I], c[RADIUS_J]) ** 2
    if area > 0.0:
        c[HEAT] = k[0] * math.sqrt(area) * (c[TEMPERATURE_J] - c[TEMPERATURE_I])


class HeatConduction(GranSubModel):
    kind = "gran.heat"
    name = "conduction"
    compute = conduction_heat
    settings_read = {"contact_area": "overlap", "area": 0.0}
    conductivity = None     # per type, as the composing fix read it (else from the material)

    def coefficients(self, material):
        k = material.property("thermalConductivity") if self.conductivity is None else self.conductivity
        n = material.ntypes + 1
        factor = np.zeros((n, n))
        for i in range(1, n):
            for j in range(1, n):
                if k[i] > 0.0 and k[j] > 0.0:
                    factor[i, j] = 4.0 * k[i] * k[j] / (k[i] + k[j])
        return material.columns(factor, float(AREAS[self.settings["contact_area"]]), float(self.settings["area"]))
