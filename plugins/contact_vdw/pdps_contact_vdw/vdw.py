r"""Cohesion model ``vdw``: the van der Waals attraction of two touching spheres (Hamaker, Physica 4,
1058 (1937); Rumpf's form for particles in contact, as in Seville, Willett & Knight, Powder
Technol. 113, 261 (2000)):

.. math::

    F_n \mathrel{-}= \frac{A\,R^*}{6\,z_0^2}

while the bodies touch, with A the Hamaker constant (energy), :math:`z_0` the separation of the
surfaces at contact (distance; about 0.4 nm for many solids) and :math:`R^* = R_iR_j/(R_i+R_j)`
(:math:`R_i` against a wall). Two spheres of :math:`R^*` pressed by nothing else stick with this
force: the pull-off force of a touching pair is :math:`AR^*/6z_0^2`.

Material, from ``fix property/global``: ``hamakerConstant peratomtypepair N ...`` (energy, > 0) and
``surfaceSeparation peratomtypepair N ...`` (distance, > 0). No history. The tangential Coulomb limit
and the rolling cap read the normal model's force without it, as LIGGGHTS's sjkr.

Syntax::

    pair_style gran model hertz tangential history cohesion vdw
    fix ID all wall/gran model hertz tangential history cohesion vdw primitive type 1 zplane 0.0

Example (glass beads, SI units)::

    fix m5 all property/global hamakerConstant peratomtypepair 1 6.5e-20
    fix m6 all property/global surfaceSeparation peratomtypepair 1 4e-10
    pair_style gran model hertz tangential history cohesion vdw
"""

from numba import njit

from pdps_granular_contact.composition import ContactSubModel
from pdps_granular_contact.contact_state import FN, R_EFF


@njit(cache=True)
def vdw_force(c, k, hist, h):
    """k: Hamaker constant A, separation z0."""
    c[FN] -= k[0] * c[R_EFF] / (6.0 * k[1] * k[1])


def _positive(value):
    return value > 0


class VanDerWaals(ContactSubModel):
    kind = "gran.cohesion"
    name = "vdw"
    compute = vdw_force
    properties = {"hamakerConstant": ("per_type_pair", "peratomtypepair", _positive, "> 0"),
                  "surfaceSeparation": ("per_type_pair", "peratomtypepair", _positive, "> 0")}

    def coefficients(self, material):
        return material.columns(material.property("hamakerConstant"), material.property("surfaceSeparation"))
