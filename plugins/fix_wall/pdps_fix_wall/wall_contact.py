r"""What every granular wall of this package shares: the contact law's parameters read from script
words, and the numba kernel that turns one particle's wall contacts into force and torque, keeping
each contact's tangential history.

A wall is body j of infinite mass and radius, so the shared laws of
``pdps_granular_contact.contact_models`` take :math:`m^* = m_i` and :math:`R^* = R_i`. For a contact at
distance :math:`d` from the surface, with unit normal :math:`\mathbf{n}` from the surface to the centre
of particle i and overlap :math:`\delta = R_i - d > 0`, the relative velocity of the contact points is

.. math::

    \mathbf{v} = \mathbf{v}_i + \boldsymbol{\omega}_i \times (-R_i\mathbf{n}) - \mathbf{v}_w(\mathbf{p})

with :math:`\mathbf{v}_w(\mathbf{p})` the wall's velocity at the contact point :math:`\mathbf{p}`. The
force :math:`\mathbf{F}` of the law acts on i, and the torque is :math:`(-R_i\mathbf{n})\times\mathbf{F}`
(lever arm :math:`R_i`, as LAMMPS's fix wall/gran).

History: each contact keeps its tangential spring (3 values) and its last normal (3 values) in a
``ContactHistory`` keyed by the wall element's id. A contact that opens in the same step as another
of the same wall closes, with a normal within about 6 degrees of it (``TRANSFER_COS``; a mesh's
``curvature``), takes over its spring: a sphere rolling from one triangle of a tessellated surface
onto the next keeps its static friction (``wall_slots``).

LIGGGHTS's walls (fix wall/gran model ...) compose their law of sub-models instead
(``pdps_granular_contact.composition``, whose generated ``wall_forces`` takes a ``WallContactTable``):
their contacts keep the law's history (tangential spring, rolling spring) and the last normal, and
can be logged one row per contact (``LOG_COLUMNS``, then the history) for compute wall/gran/local.
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError
from pdps_granular_contact import contact_models
from pdps_granular_contact.contact_slots import wall_slots

LSD, HERTZ = 0, 1
# a per-type law table's columns (ContactLaw.row): one row per particle type, for walls whose law
# depends on the particle's material
LAW_COLUMNS = ("kn", "cn", "kt", "ct", "mu", "per_mass", "e_star", "g_star", "beta")
HISTORY_WIDTH = 6           # tangential spring (3) and the contact's last normal (3)
TRANSFER_COS = 0.995        # a new contact whose normal is this close to one just ended continues it
# the columns of a LIGGGHTS wall's contact log (compute wall/gran/local reads them), then the
# contact's history values (as many as its composed law keeps): t is the torque of the tangential
# force alone (without rolling friction)
LOG_COLUMNS = ("row", "element", "px", "py", "pz", "vwx", "vwy", "vwz", "fx", "fy", "fz", "tx", "ty", "tz",
               "delta", "area")


class WallContactTable:
    """Particles' contacts with a wall, one after the other (particle k's are rows starts[k] ..
    starts[k + 1]): distance of the centre from the element, normal from the surface to the centre,
    the element's key, the contact point, the wall's velocity there, and (written by the force loop)
    the contact's force. Grows by a quarter when short and is kept between steps."""

    def __init__(self):
        self.rows = -1
        self.starts = np.zeros(1, dtype=np.int64)
        self.room(0, 0)

    def room(self, particles, rows):
        """Arrays for ``particles`` particles and ``rows`` contacts at most."""
        if len(self.starts) < particles + 1:
            self.starts = np.zeros(particles + particles // 4 + 2, dtype=np.int64)
        if rows > self.rows:
            size = rows + rows // 4 + 4
            self.rows = size
            self.distance, self.key = np.empty(size), np.empty(size, dtype=np.int64)
            self.normal, self.touch, self.wall_velocity, self.contact_force = (np.empty((size, 3)) for _ in range(4))
        return self

    def arrays(self):
        """(distance, normal, key, touch, wall_velocity)."""
        return self.distance, self.normal, self.key, self.touch, self.wall_velocity


class ContactLaw:
    """The wall's contact law as plain numbers for the kernel.

    lsd: ``kn``, ``cn``, ``kt``, ``ct``, ``mu``; when the damping comes from a restitution coefficient
    ``e``, ``cn`` and ``ct`` are per unit square-root mass and ``per_mass`` is set (C_n = 2 zeta
    sqrt(kn m), so C_n(m) = C_n(1) sqrt(m)). hertz: ``e_star``, ``g_star``, ``beta``, ``mu``.
    """

    def __init__(self, model, *, kn=0.0, cn=0.0, kt=0.0, ct=0.0, mu=0.0, per_mass=False,
                 e_star=0.0, g_star=0.0, beta=0.0, restitution=None):
        self.model = model
        self.kn, self.cn, self.kt, self.ct, self.mu = kn, cn, kt, ct, mu
        self.per_mass = per_mass
        self.e_star, self.g_star, self.beta = e_star, g_star, beta
        self.restitution = restitution

    @classmethod
    def lsd(cls, kn, mu, *, e=None, cn=None, kt=None, ct=None):
        """Linear spring-dashpot. With ``cn``, ``kt``, ``ct``: as written (PDPS). With only ``e``:
        C_n from e for m* = m_i, and LAMMPS's defaults k_t = 2/7 k_n, C_t = C_n / 2."""
        if cn is not None:
            return cls(LSD, kn=kn, cn=cn, kt=kt, ct=ct, mu=mu, restitution=e)
        unit = contact_models.lsd_damping(kn, 1.0, e)
        return cls(LSD, kn=kn, cn=unit, kt=2.0 / 7.0 * kn, ct=0.5 * unit, mu=mu, per_mass=True,
                   restitution=e)

    @classmethod
    def hertz(cls, youngs, poisson, e, mu):
        """Hertz-Mindlin with wall and particles of one material (LIGGGHTS's effective moduli for
        two bodies of Young's modulus Y and Poisson ratio nu): E* = Y / (2 (1 - nu^2)),
        G* = Y / (4 (2 - nu)(1 + nu))."""
        e_star = youngs / (2.0 * (1.0 - poisson * poisson))
        g_star = youngs / (4.0 * (2.0 - poisson) * (1.0 + poisson))
        return cls(HERTZ, e_star=e_star, g_star=g_star, beta=contact_models.restitution_beta(e),
                   mu=mu, restitution=e)

    def kernel_args(self):
        return (self.model, self.kn, self.cn, self.kt, self.ct, self.mu, self.per_mass,
                self.e_star, self.g_star, self.beta)

    def row(self):
        """The law's numbers as one row of a per-type table (``LAW_COLUMNS``)."""
        return [self.kn, self.cn, self.kt, self.ct, self.mu, float(self.per_mass), self.e_star,
                self.g_star, self.beta]

    def table(self, ntypes):
        """The same law for every particle type: a (ntypes + 1, 9) table, row 0 unused."""
        return np.tile(np.array(self.row(), dtype=np.float64), (ntypes + 1, 1))

    def check_timestep(self, sim, fix, masses):
        """Warn when the time step resolves a linear contact with fewer than 10 steps."""
        if self.model != LSD:
            return
        m = sim.comm.min(float(np.min(masses)) if len(masses) else math.inf)
        if not math.isfinite(m):
            return
        cn = self.cn * math.sqrt(m) if self.per_mass else self.cn
        if self.kn / m <= (cn / (2.0 * m)) ** 2:
            return          # overdamped: no rebound to resolve
        duration = contact_models.lsd_contact_time(self.kn, cn, m)
        if sim.dt > duration / 10.0:
            sim.warn(f"fix {fix.id} ({fix.name}): timestep {sim.dt:g} resolves a wall contact of the "
                     f"lightest particle (mass {m:.4g}, duration {duration:.4g}) with fewer than 10 "
                     f"steps; use timestep <= {duration / 50.0:.3g} for accurate rebounds")


def check_law_numbers(e=None, kn=None, cn=None, kt=None, ct=None, mu=None):
    """Ranges a user gets told about by name."""
    if e is not None and not 0.0 < e <= 1.0:
        raise ScriptError(f"e must be in (0, 1] (got {e:g})")
    if kn is not None and not kn > 0.0:
        raise ScriptError(f"kn must be > 0 (got {kn:g})")
    for name, value in (("Cn", cn), ("kt", kt), ("Ct", ct), ("mu", mu)):
        if value is not None and value < 0.0:
            raise ScriptError(f"{name} must be >= 0 (got {value:g})")


@njit(cache=True)
def particle_wall_contacts(i, start, end, distance, normal, key, wall_velocity, reach, mass,
                           v, omega, f, torque, rotation, partner, values,
                           model, kn, cn, kt, ct, mu, per_mass, e_star, g_star, beta, dt, update,
                           used, slots, n, rel, force, spring, contact_force, transfer_cos):
    """Force and torque on particle i from its wall contacts ``start..end`` (distance to the
    surface, normal from surface to centre, element key, wall velocity at the contact point);
    each contact's force on i into ``contact_force[c]`` (zero for contacts that do not touch).
    Contacts with distance >= reach do not touch. With ``update`` the history is kept (opened,
    taken over, closed: ``wall_slots``); without it (setup) forces use the stored springs and
    change nothing. ``n``, ``rel``, ``force``, ``spring``: scratch vectors (3 each) of the caller.
    Returns False when particle i has no free history slot."""
    width = HISTORY_WIDTH
    if not wall_slots(i, start, end, distance, normal, key, reach, partner, values, 3, update, used,
                      slots, transfer_cos):
        return False
    for c in range(start, end):
        overlap = reach - distance[c]
        for d in range(3):
            contact_force[c, d] = 0.0
        if overlap <= 0.0:
            continue
        for d in range(3):
            n[d] = normal[c, d]
            rel[d] = v[i, d] - wall_velocity[c, d]
            force[d] = 0.0
        if rotation:
            # omega x (-R n) is R (n x omega)
            rel[0] += reach * (n[1] * omega[i, 2] - n[2] * omega[i, 1])
            rel[1] += reach * (n[2] * omega[i, 0] - n[0] * omega[i, 2])
            rel[2] += reach * (n[0] * omega[i, 1] - n[1] * omega[i, 0])
        s = slots[c - start]
        if update:
            shear = values[i, s * width:s * width + 3]
            for d in range(3):
                values[i, s * width + 3 + d] = n[d]
        else:
            for d in range(3):
                spring[d] = values[i, s * width + d] if s >= 0 else 0.0
            shear = spring
        if model == LSD:
            root_mass = math.sqrt(mass) if per_mass else 1.0
            contact_models.lsd_contact(overlap, n, rel, shear, kn, cn * root_mass, kt,
                                       ct * root_mass, mu, dt, False, force)
        else:
            contact_models.hertz_contact(overlap, n, rel, shear, e_star, g_star, reach, mass, beta,
                                         mu, dt, False, force)
        for d in range(3):
            f[i, d] += force[d]
            contact_force[c, d] = force[d]
        if rotation:
            torque[i, 0] -= reach * (n[1] * force[2] - n[2] * force[1])
            torque[i, 1] -= reach * (n[2] * force[0] - n[0] * force[2])
            torque[i, 2] -= reach * (n[0] * force[1] - n[1] * force[0])
    return True


@njit(cache=True)
def forget_far(partner, chosen, near):
    """Close every wall contact of the chosen particles not near a wall (``near`` flags, one per
    chosen particle): none of them touches one before the next rebuild, and none is visited."""
    for k in range(len(chosen)):
        if not near[k]:
            i = chosen[k]
            for s in range(partner.shape[1]):
                partner[i, s] = -1
