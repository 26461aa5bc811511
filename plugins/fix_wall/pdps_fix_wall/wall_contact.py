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

LIGGGHTS's walls (fix wall/gran model ...) use LIGGGHTS's laws instead
(``pdps_granular_contact.liggghts`` with the wall as body j; ``liggghts_wall_contacts``): their
contacts keep the law's history (tangential spring, rolling spring) and the last normal, and can be
logged one row per contact (``LOG_COLUMNS``) for compute wall/gran/local.
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError
from pdps_granular_contact import contact_models, liggghts
from pdps_granular_contact.contact_slots import wall_slots

LSD, HERTZ = 0, 1
# a per-type law table's columns (ContactLaw.row): one row per particle type, for walls whose law
# depends on the particle's material
LAW_COLUMNS = ("kn", "cn", "kt", "ct", "mu", "per_mass", "e_star", "g_star", "beta")
HISTORY_WIDTH = 6           # tangential spring (3) and the contact's last normal (3)
TRANSFER_COS = 0.995        # a new contact whose normal is this close to one just ended continues it
# LIGGGHTS's laws (fix wall/gran model ...): a contact's values are the law's history, then its last
# normal (for handing it on between faces)
LIGGGHTS_WIDTH = liggghts.HISTORY_WIDTH + 3
LIGGGHTS_NORMAL_AT = liggghts.HISTORY_WIDTH
# the columns of a LIGGGHTS wall's contact log (compute wall/gran/local reads them): t is the torque
# of the tangential force alone (without rolling friction)
LOG_COLUMNS = (("row", "element", "px", "py", "pz", "vwx", "vwy", "vwz", "fx", "fy", "fz", "tx", "ty", "tz",
                "delta", "area") + tuple(f"history{h}" for h in range(liggghts.HISTORY_WIDTH)))


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


@njit(cache=True)
def liggghts_wall_contacts(i, count, distance, normal, key, touch, wall_velocity, v, omega, f,
                           torque, radius, rmass, ptype, wall_type, models, table, charvel, nktv2p,
                           dt, update, partner, values, used, slots, hist, force, tangential, roll,
                           n, vtr, wr, contact_force, log, logged, transfer_cos):
    """Force and torque on particle i from its wall contacts 0..count (module docstring), each
    contact's force into ``contact_force``; with a ``log`` of rows (LOG_COLUMNS), one row per
    touching contact after ``logged[0]`` (which counts them). Returns False when i has no free
    history slot."""
    r_i = radius[i]
    if not wall_slots(i, 0, count, distance, normal, key, r_i, partner, values, LIGGGHTS_NORMAL_AT, update,
                      used, slots, transfer_cos):
        return False
    width = values.shape[1] // partner.shape[1]
    for c in range(count):
        for d in range(3):
            contact_force[c, d] = 0.0
        if distance[c] >= r_i:
            continue
        overlap = r_i - distance[c]
        arm = r_i - 0.5 * overlap
        for d in range(3):
            n[d] = normal[c, d]
        vr0 = v[i, 0] - wall_velocity[c, 0]
        vr1 = v[i, 1] - wall_velocity[c, 1]
        vr2 = v[i, 2] - wall_velocity[c, 2]
        v_n = vr0 * n[0] + vr1 * n[1] + vr2 * n[2]
        w0, w1, w2 = arm * omega[i, 0], arm * omega[i, 1], arm * omega[i, 2]
        vtr[0] = vr0 - v_n * n[0] - (w1 * n[2] - w2 * n[1])
        vtr[1] = vr1 - v_n * n[1] - (w2 * n[0] - w0 * n[2])
        vtr[2] = vr2 - v_n * n[2] - (w0 * n[1] - w1 * n[0])
        for d in range(3):
            wr[d] = omega[i, d]
        s = slots[c]
        for h in range(liggghts.HISTORY_WIDTH):
            hist[h] = values[i, s * width + h] if s >= 0 else 0.0
        liggghts.liggghts_contact(models, True, table, ptype[i], wall_type, distance[c], r_i, 0.0,
                                  rmass[i], 0.0, rmass[i], n, v_n, vtr, wr, charvel, nktv2p, dt,
                                  update, hist, force, tangential, roll)
        if s >= 0:
            for h in range(liggghts.HISTORY_WIDTH):
                values[i, s * width + h] = hist[h]
            if update:
                for d in range(3):
                    values[i, s * width + LIGGGHTS_NORMAL_AT + d] = n[d]
        for d in range(3):
            f[i, d] += force[d]
            contact_force[c, d] = force[d]
        # the torque of the tangential force; the rolling torque comes on top
        tx = -arm * (n[1] * tangential[2] - n[2] * tangential[1])
        ty = -arm * (n[2] * tangential[0] - n[0] * tangential[2])
        tz = -arm * (n[0] * tangential[1] - n[1] * tangential[0])
        torque[i, 0] += tx - roll[0]
        torque[i, 1] += ty - roll[1]
        torque[i, 2] += tz - roll[2]
        row = logged[0]
        if row < log.shape[0]:
            log[row, 0] = i
            log[row, 1] = key[c]
            for d in range(3):
                log[row, 2 + d] = touch[c, d]
                log[row, 5 + d] = wall_velocity[c, d]
                log[row, 8 + d] = force[d]
            log[row, 11], log[row, 12], log[row, 13] = tx, ty, tz
            log[row, 14] = overlap
            log[row, 15] = math.pi * (r_i * r_i - distance[c] * distance[c])
            for h in range(liggghts.HISTORY_WIDTH):
                log[row, 16 + h] = hist[h]
            logged[0] = row + 1
    return True
