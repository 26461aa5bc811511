r"""Normal model ``hertz/material`` of LAMMPS's pair granular: Hertz's force of two elastic spheres,

.. math::

    F_{ne} = \tfrac43 E^* a\delta, \qquad a = \sqrt{\delta R^*}, \qquad
    \frac{1}{E^*} = \frac{1-\nu_i^2}{E_i} + \frac{1-\nu_j^2}{E_j}

For one type (and against a wall) :math:`E^* = E/2(1-\nu^2)`; between two types whose
``pair_coeff I J`` is not given, E* of the two materials and the geometric means of η_n0 and ν
(LAMMPS's mixing; a mixed ν is what a Mindlin stiffness of NULL reads with that E*).
Coefficients: ``E`` Young's modulus (pressure, > 0), ``eta_n0`` (the damping coefficient, in the
damping model's unit), ``nu`` Poisson's ratio (dimensionless, -1 < ν <= 0.5).

Syntax: ``pair_coeff I J hertz/material E eta_n0 nu damping ... tangential ...``
(LAMMPS's pair granular; Johnson, Contact Mechanics (1985)).
"""

from pdps_core.api import param

from pdps_granular_contact.contact_models import hertz_contact_time

from .base import GranularSubModel, StyleArgs, effective_modulus, mix_geom
from .normal_hertz import hertz_force


class MaterialCoefficients(StyleArgs):
    E: float = param(gt=0, unit="pressure")
    eta_n0: float = param(ge=0, unit="as the formula")
    nu: float = param(gt=-1, le=0.5, unit="dimensionless")


def modulus(law):
    """E* of the law's normal model: its E when mixed (LAMMPS keeps the mixed E* there), else that
    of two spheres of its material."""
    args = law.args("normal")
    return args.E if law.mixed else effective_modulus(args.E, args.E, args.nu, args.nu)


def material_time(self, law, m_eff, r_eff, speed):
    """Hertz's 2.868 (m*^2 / (R* E*^2 v))^(1/5) of the material's E* (an undamped contact)."""
    return None if speed <= 0.0 else hertz_contact_time(modulus(law), r_eff, m_eff, speed)


def mix_material(cls, ci, cj):
    """E* of the two materials in place of E, the geometric mean of the other coefficients."""
    values = {name: mix_geom(getattr(ci, name), getattr(cj, name)) for name in cls.Args.model_fields}
    values["E"] = effective_modulus(ci.E, cj.E, ci.nu, cj.nu)
    return cls.Args(**values)


class NormalHertzMaterial(GranularSubModel):
    kind = "granular.normal"
    name = "hertz/material"
    Args = MaterialCoefficients
    compute = hertz_force
    material = True

    mix = classmethod(mix_material)
    elastic_time = material_time

    def values(self, law, contact):
        return (4.0 / 3.0 * modulus(law),)
