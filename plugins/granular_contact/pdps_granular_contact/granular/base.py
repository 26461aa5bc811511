r"""What the sub-models of LAMMPS's ``pair_style granular`` share: the base class, the coefficients
of each type pair, and the mixing of two types' coefficients.

A sub-model declares its coefficients as ``Args`` (the numbers after its word on a ``pair_coeff``
line, in LAMMPS's order) and gives its compute function the numbers ``values(law)`` makes of them
for one type pair; ``law`` is that pair's ``Law``, so a sub-model may read another part's
coefficients as LAMMPS's do (damping reads the normal model's damping coefficient, mindlin with
``NULL`` stiffness the normal model's modulus, marshall twisting the tangential friction).

Mixing (``pair_coeff I J`` not given, LAMMPS's ``GranSubMod::mix_coeffs``): the geometric mean
:math:`\sqrt{c_ic_j}` of each coefficient, except where a model mixes otherwise (an effective
modulus :math:`1/E^* = (1-\nu_i^2)/E_i + (1-\nu_j^2)/E_j` for the material models); two types whose
models differ in a part cannot be mixed.
"""

import math
from dataclasses import dataclass, field

import numpy as np

from pdps_core.api import ScriptError, StyleArgs

from pdps_granular_contact.composition import PARTS, ContactSubModel

PAIR, WALL = "pair", "wall"


def mix_geom(a, b):
    return math.sqrt(a * b)


def effective_modulus(youngs_i, youngs_j, poisson_i, poisson_j):
    """LAMMPS's mix_stiffnessE: :math:`1/((1-\nu_i^2)/E_i + (1-\nu_j^2)/E_j)`."""
    return 1.0 / ((1.0 - poisson_i * poisson_i) / youngs_i + (1.0 - poisson_j * poisson_j) / youngs_j)


def effective_shear_modulus(youngs_i, youngs_j, poisson_i, poisson_j):
    """LAMMPS's mix_stiffnessG: :math:`1/(2(2-\nu_i)(1+\nu_i)/E_i + 2(2-\nu_j)(1+\nu_j)/E_j)`."""
    return 1.0 / (2.0 * (2.0 - poisson_i) * (1.0 + poisson_i) / youngs_i
                  + 2.0 * (2.0 - poisson_j) * (1.0 + poisson_j) / youngs_j)


@dataclass(frozen=True)
class Law:
    """The contact law of one type pair: part -> (sub-model class, its coefficients ``Args``);
    ``mixed``: made by mixing two types' laws (LAMMPS's mixed_coefficients); ``limit_damping``
    and ``cutoff`` (None: the radii's) of the pair_coeff line."""
    parts: dict
    limit_damping: bool = False
    cutoff: float | None = None
    mixed: bool = False
    words: tuple = field(default=(), compare=False)

    def args(self, part):
        return self.parts[part][1]

    def name(self, part):
        return self.parts[part][0].name if part in self.parts else None

    def mix(self, other, i, j):
        """The law of types i, j from this one (i i) and ``other`` (j j), as LAMMPS mixes."""
        for part in (part for part in PARTS if part in self.parts or part in other.parts):
            if self.name(part) != other.name(part):
                raise ScriptError(f"types {i} and {j} have different {part} models ({self.name(part) or 'none'} and "
                                  f"{other.name(part) or 'none'}): their coefficients cannot be mixed; give pair_coeff "
                                  f"{i} {j}")
        parts = {part: (cls, cls.mix(self.args(part), other.args(part))) for part, (cls, _) in self.parts.items()}
        cutoff = None if self.cutoff is None or other.cutoff is None else max(self.cutoff, other.cutoff)
        return Law(parts, self.limit_damping or other.limit_damping, cutoff, mixed=True)


class Laws:
    """The laws of every type pair a sub-model's ``coefficients`` reads: ``laws[(i, j)]``, i <= j;
    ``contact``: PAIR (between particles) or WALL (LAMMPS's contact_type), for the laws of a wall
    the wall's law is that of every particle type."""

    def __init__(self, ntypes, laws, contact=PAIR):
        self.ntypes, self.laws, self.contact = ntypes, laws, contact

    def columns(self, values):
        """The table (ntypes + 1, ntypes + 1, n) of ``values(law)`` (n numbers) of every type pair."""
        n = self.ntypes + 1
        rows = {pair: tuple(float(v) for v in values(law)) for pair, law in self.laws.items()}
        width = len(next(iter(rows.values()))) if rows else 0
        table = np.zeros((n, n, width))
        for (i, j), row in rows.items():
            table[i, j, :] = row
            table[j, i, :] = row
        return table


class GranularSubModel(ContactSubModel):
    """A sub-model of LAMMPS's pair granular: ``Args`` its coefficients (the words after its name),
    ``values(law)`` the numbers its compute function gets for one type pair (by default its
    coefficients in order)."""
    Args = StyleArgs
    # a normal model that attracts (DMT, JKR: LAMMPS's cohesive_flag), which some damping models refuse
    cohesive = False
    # a damping model that cannot be used with a cohesive normal model (LAMMPS's allow_cohesion 0)
    allows_cohesion = True

    @classmethod
    def coefficient_names(cls):
        return [info.alias or name for name, info in cls.Args.model_fields.items()]

    @classmethod
    def mix(cls, ci, cj):
        """LAMMPS's default mixing: the geometric mean of each coefficient."""
        return cls.Args(**{name: mix_geom(getattr(ci, name), getattr(cj, name)) for name in cls.Args.model_fields})

    def values(self, law, contact):
        if self.part not in law.parts:
            return ()
        args = law.args(self.part)
        return tuple(getattr(args, name) for name in self.Args.model_fields)

    def coefficients(self, laws):
        return laws.columns(lambda law: self.values(law, laws.contact))

    def contact_time(self, laws, t, m_eff, r_eff, speed):
        """A normal model's duration of a contact of two type-t bodies at ``speed`` (``laws``: the
        Laws of the run), from ``elastic_time``; None where it gives none."""
        law = laws.laws.get((t, t))
        return None if law is None else self.elastic_time(law, m_eff, r_eff, speed)

    def elastic_time(self, law, m_eff, r_eff, speed):
        """The undamped contact's duration under ``law`` (None: no estimate)."""
        return None

    @classmethod
    def check(cls, law):
        """A one-line ScriptError where this model cannot run with the rest of ``law``."""
