r"""What every granular wall of this package shares: the contact law's parameters read from script
words, and the composed contact law (``WallLaw``: pdps_granular_contact.composition's generated
``wall_forces``) that turns each particle's wall contacts (``WallContactTable``) into force and
torque, keeping each contact's history.

A wall is body j of infinite mass and radius, so the contact laws take :math:`m^* = m_i` and
:math:`R^* = R_i`. PDPS's walls (wall/dem, wall/mesh) compose PDPS's sub-models
(``pdps_granular_contact.dem``: lsd or hertz, tangential spring; ``ContactLaw.wall_law``). For a contact at
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

LIGGGHTS's walls (fix wall/gran model ...) compose LIGGGHTS's sub-models: their contacts keep the
law's history (tangential spring, rolling spring) and the last normal, and can be logged one row
per contact (``LOG_COLUMNS``, then the history) for compute wall/gran/local.
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError
from pdps_granular_contact import contact_models
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.dem.base import Tables

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


FLAT = np.zeros(0)          # no wall curvature: every contact's R* is the particle's radius


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


class WallLaw:
    """A composed contact law (pdps_granular_contact.composition.ContactModel) on a wall's contact
    table: the generated ``wall_forces`` and what it works in, kept between steps. ``bind`` at a
    run's start; ``forces`` each step."""

    def __init__(self, model):
        self.model = model
        self.coeff = self.kernels = None
        self._vectors = (np.zeros(3), np.zeros(3))
        self._used, self._slots = np.zeros(0, dtype=np.bool_), np.zeros(0, dtype=np.int64)
        self._not_logged = np.zeros(1, dtype=np.int64)
        self._still = (np.zeros((0, 3)), np.zeros((0, 3)))

    @property
    def log_columns(self):
        """A contact log's columns: LOG_COLUMNS, then the contact's history."""
        return len(LOG_COLUMNS) + self.model.history_width

    def bind(self, source):
        self.coeff = self.model.bind(source)
        self.kernels = self.model.kernels()

    def log_buffer(self, most):
        if most == 0:
            self._not_logged[0] = 0
            return np.zeros((0, self.log_columns)), self._not_logged
        return np.zeros((most, self.log_columns)), np.zeros(1, dtype=np.int64)

    def still(self, sim):
        """Zero spins and a torque sink, for particles that do not turn (no omega and torque)."""
        n = sim.particles.nall
        if len(self._still[0]) < n:
            self._still = (np.zeros((n + n // 4 + 16, 3)), np.zeros((n + n // 4 + 16, 3)))
        self._still[1][:] = 0.0
        return self._still

    def forces(self, sim, rows, nrows, starts, contacts, contact_force, history, wall_type, f, torque, update, *,
               radius, mass, omega, body_mass=contact_models.NO_BODY_MASS, log_rows=0, transfer_cos=TRANSFER_COS,
               curvature=FLAT):
        """The law on the contacts of the particles ``rows[:nrows]``, particle k's rows starts[k] ..
        starts[k + 1] of ``contacts`` (distance, normal, key, contact point, wall velocity: a
        WallContactTable's arrays), each one's force into ``contact_force``; returns (-1 or the row of
        a particle whose history overflowed, the contacts' log when ``log_rows``)."""
        p = sim.particles
        slots = history.partner.shape[1]
        most = most_contacts(starts, nrows)
        if len(self._used) < slots or len(self._slots) < most:
            self._used, self._slots = np.zeros(slots, dtype=np.bool_), np.zeros(most + most // 4 + 4, dtype=np.int64)
        buffer, logged = self.log_buffer(log_rows)
        bad = self.kernels.wall_forces(
            rows, starts, nrows, *contacts, curvature, p.v, omega, f, torque, radius, mass, body_mass, p.type, wall_type,
            self.coeff, sim.dt, update, sim.dimension, history.partner, history.values, self._used, self._slots,
            *self._vectors, contact_force, buffer, logged, transfer_cos)
        return bad, buffer[:logged[0]]


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

    def wall_law(self):
        """This law composed of PDPS's dem sub-models (lsd or hertz, tangential spring), for a wall."""
        normal = "lsd" if self.model == LSD else "hertz"
        return WallLaw(ContactModel("dem", {"normal": normal, "tangential": "spring"}, {"limit_damping": False}))

    def tables(self, ntypes, rows=None):
        """The dem sub-models' tables of this law for a wall (type 0: coeff[particle type, 0]), from
        one row per particle type (``rows``: LAW_COLUMNS; default this law for every type)."""
        rows = self.table(ntypes) if rows is None else rows
        n = ntypes + 1
        names = ("kn", "cn", "kt", "ct", "cn_per_root_mass", "ct_over_cn", "mu", "e_star", "g_star", "beta")
        tables = {name: np.zeros((n, n)) for name in names}
        for t in range(1, n):
            kn, cn, kt, ct, mu, per_mass, e_star, g_star, beta = rows[t]
            per_mass = per_mass != 0.0
            values = {"kn": kn, "cn": 0.0 if per_mass else cn, "kt": kt, "ct": 0.0 if per_mass else ct,
                      "cn_per_root_mass": cn if per_mass else 0.0,
                      "ct_over_cn": ct / cn if per_mass and cn > 0.0 else 0.0, "mu": mu,
                      "e_star": e_star, "g_star": g_star, "beta": beta}
            for name, value in values.items():
                tables[name][t, 0] = value
        return Tables(ntypes, tables)

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
def most_contacts(starts, nrows):
    """The most contacts of one particle in a contact table (its rows starts[k] .. starts[k + 1]),
    without a step's temporary array."""
    most = 0
    for k in range(nrows):
        most = max(most, starts[k + 1] - starts[k])
    return most


@njit(cache=True)
def forget_far(partner, chosen, near):
    """Close every wall contact of the chosen particles not near a wall (``near`` flags, one per
    chosen particle): none of them touches one before the next rebuild, and none is visited."""
    for k in range(len(chosen)):
        if not near[k]:
            i = chosen[k]
            for s in range(partner.shape[1]):
                partner[i, s] = -1
