r"""LIGGGHTS's granular contact models, in LIGGGHTS's own formulas: the law of ``pair_style gran model
hertz|hooke tangential history|no_history [rolling_friction cdt|epsd|epsd2] [cohesion sjkr|sjkr2]``
and of LIGGGHTS's ``fix wall/gran model ...`` with the same words (Di Renzo & Di Maio, Chem. Eng.
Sci. 59, 525 (2004); Tsuji et al., Powder Technol. 71, 239 (1992); Ai et al., Powder Technol. 206,
269 (2011) for the rolling models; Johnson, Kendall & Roberts, Proc. R. Soc. A 324, 301 (1971),
simplified, for the cohesion).

One contact of body i with body j (a sphere, or a wall: ``wall=True``) whose centres are ``r``
apart, overlap :math:`\delta > 0`, unit normal :math:`\mathbf{n}` from j to i, normal relative speed
:math:`v_n = (\mathbf{v}_i - \mathbf{v}_j)\cdot\mathbf{n}`, sliding velocity of the contact points
:math:`\mathbf{v}_{tr}` (lever arms :math:`R_{i,j} - \delta/2`, computed by the caller), relative
spin :math:`\boldsymbol\omega_r = \boldsymbol\omega_i - \boldsymbol\omega_j` (:math:`\boldsymbol
\omega_i` against a wall), effective radius :math:`R^* = R_iR_j/(R_i+R_j)` (:math:`R_i` against a
wall) and effective mass :math:`m^*` (:math:`m_i` against a wall). Material, per type pair (the
wall's type for a wall; ``MATERIAL`` names the rows of the caller's table):

.. math::

    \frac{1}{Y^*} = \frac{1-\nu_i^2}{Y_i} + \frac{1-\nu_j^2}{Y_j}, \quad
    \frac{1}{G^*} = \frac{2(2-\nu_i)(1+\nu_i)}{Y_i} + \frac{2(2-\nu_j)(1+\nu_j)}{Y_j}, \quad
    \beta = \frac{\ln e}{\sqrt{\ln^2 e + \pi^2}}

The models, applied in LIGGGHTS's order (normal, cohesion, tangential, rolling); the tangential
Coulomb limit and the rolling cap read the normal model's :math:`F_n`, without the cohesion
(LIGGGHTS's default, ``tangential_reduce off``):

- normal ``hertz``: :math:`S_n = 2Y^*\sqrt{R^*\delta}`, :math:`S_t = 8G^*\sqrt{R^*\delta}`,
  :math:`k_n = \tfrac43 Y^*\sqrt{R^*\delta}`, :math:`k_t = S_t`,
  :math:`\gamma_n = -2\sqrt{5/6}\,\beta\sqrt{S_n m^*}`, :math:`\gamma_t = -2\sqrt{5/6}\,\beta
  \sqrt{S_t m^*}`; ``hooke``: :math:`k_n = k_t = \tfrac{16}{15}\sqrt{R^*}\,Y^*\big(\tfrac{15 m^*
  V^2}{16\sqrt{R^*}Y^*}\big)^{1/5}` with the characteristic velocity :math:`V`,
  :math:`\gamma_n = \gamma_t = \sqrt{4m^*k_n/(1 + \pi^2/\ln^2 e)}`. Both: :math:`k_n, k_t` divided by
  the unit system's ``nktv2p``, :math:`F_n = k_n\delta - \gamma_n v_n` (0 where negative with
  ``limitForce``), :math:`\gamma_t = 0` with ``tangential_damping off``. Note the differences from
  pdps's own ``dem/hertz`` (contact_models.hertz_contact): the tangential spring keeps no length when
  it turns, the Coulomb test uses the spring force alone, and the tangential damping acts only
  while the contact sticks.
- cohesion ``sjkr``: :math:`F_n \mathrel{-}= k A` with the area of the circle where the two spheres
  intersect, :math:`A = -\tfrac{\pi}{4}(r-R_i-R_j)(r+R_i-R_j)(r-R_i+R_j)(r+R_i+R_j)/r^2`
  (:math:`A = \pi(R_i^2 - r^2)` against a wall; :math:`\pi\min(R_i, R_j)^2` once the smaller sphere's
  centre is inside the other, where that circle shrinks and vanishes); ``sjkr2``: :math:`A = 2\pi\,\tfrac{2R_iR_j}{R_i+R_j}
  \,\delta` (:math:`2\pi R_i\delta` against a wall). :math:`k` is the cohesion energy density
  (energy/volume). Acts only while the bodies touch.
- tangential ``history``: the spring :math:`\boldsymbol\xi` grows by :math:`\mathbf{v}_{tr}\Delta t`
  and is projected onto the tangent plane (its length not restored); :math:`\mathbf{F}_t =
  -k_t\boldsymbol\xi`; if :math:`k_t|\boldsymbol\xi| > \mu|F_n|` the force is scaled to the Coulomb
  limit and :math:`\boldsymbol\xi = -\mathbf{F}_t/k_t` (no damping), else :math:`\mathbf{F}_t
  \mathrel{-}= \gamma_t\mathbf{v}_{tr}`. ``no_history``: :math:`\mathbf{F}_t = -\min(\mu|F_n|,
  \gamma_t|\mathbf{v}_{tr}|)\,\mathbf{v}_{tr}/|\mathbf{v}_{tr}|`.
- rolling ``cdt`` (constant directional torque): :math:`\mathbf{M}_r = \mu_r k_n\delta R^*\,
  \boldsymbol\omega_r/|\boldsymbol\omega_r|` less its part along :math:`\mathbf{n}` (against a wall
  the arm is :math:`R_i - \delta/2`); ``epsd`` (elastic-plastic spring-dashpot): a torque spring
  :math:`\mathbf{M}_r \mathrel{+}= k_r\,\boldsymbol\omega_{r,t}\Delta t`, :math:`k_r =
  2.25\,k_n\mu_r^2R^{*2}`, capped at :math:`\mu_r|F_n|R^*`; below the cap a dashpot
  :math:`\eta_r\,2\sqrt{I_r k_r}\,\boldsymbol\omega_{r,t}` is added (not stored), :math:`I_r =
  1.4\,(m_iR_i^2)(m_jR_j^2)/(m_iR_i^2 + m_jR_j^2)` (1.5 in 2-d; :math:`1.4 m_iR_i^2` against a wall)
  and :math:`\eta_r` the rolling viscous damping coefficient; ``epsd2``: the spring with
  :math:`k_r = k_tR^{*2}`, capped the same way, no dashpot. :math:`\boldsymbol\omega_{r,t}` is the
  relative spin less its part along :math:`\mathbf{n}`. i gets :math:`-\mathbf{M}_r`, j
  :math:`+\mathbf{M}_r`.

History per contact (``HISTORY_WIDTH`` values, kept by the caller on both bodies with j holding the
negatives): the tangential spring (3) and the epsd/epsd2 rolling torque (3). With ``update`` False
(the setup force computation of a run) neither spring is grown or stored, as LIGGGHTS's
``shearupdate`` for the tangential one (LIGGGHTS grows the rolling spring in setup too; here a
``run 0`` before a run changes nothing).

Units: :math:`Y, G` pressure, :math:`V` velocity, :math:`k` energy/volume, :math:`\mu, \mu_r, e,
\eta_r` dimensionless.
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import GlobalProperty, ScriptError

from .contact_models import restitution_beta, shear_effective, youngs_effective

HERTZ, HOOKE = 0, 1
NORMAL_MODELS = {"hertz": HERTZ, "hooke": HOOKE}
HISTORY, NO_HISTORY = 0, 1
TANGENTIAL_MODELS = {"history": HISTORY, "no_history": NO_HISTORY}
ROLL_OFF, CDT, EPSD, EPSD2 = 0, 1, 2, 3
ROLLING_MODELS = {"off": ROLL_OFF, "cdt": CDT, "epsd": EPSD, "epsd2": EPSD2}
COHESION_OFF, SJKR, SJKR2 = 0, 1, 2
COHESION_MODELS = {"off": COHESION_OFF, "sjkr": SJKR, "sjkr2": SJKR2}

# rows of the per-type-pair material table the law reads: table[row, itype, jtype]
MATERIAL = ("y_star", "g_star", "beta", "log_e", "mu", "mu_roll", "eta_roll", "cohesion")
Y_STAR, G_STAR, BETA, LOG_E, MU, MU_ROLL, ETA_ROLL, COHESION = range(len(MATERIAL))
HISTORY_WIDTH = 6
SQRT_FIVE_SIXTHS = math.sqrt(5.0 / 6.0)


def intersection_area(r, ri, rj):
    """pi a^2 of the circle where spheres at distances r intersect (arrays); the smaller one's
    cross-section once its centre is inside the other, as the cohesion laws (contact_area) and
    LIGGGHTS 3.8's heat transfer take it."""
    circle = -0.25 * math.pi * (r - ri - rj) * (r + ri - rj) * (r - ri + rj) * (r + ri + rj) / r ** 2
    return np.where(r < np.maximum(ri, rj), math.pi * np.minimum(ri, rj) ** 2, circle)


@njit(cache=True)
def contact_area(cohesion, wall, r, radius_i, radius_j):
    """The area the cohesion model multiplies by k (module docstring); 0 without cohesion."""
    if cohesion == SJKR:
        if wall:
            return math.pi * (radius_i * radius_i - r * r)
        if r < max(radius_i, radius_j):
            # the smaller sphere's centre inside the other: its cross-section (LIGGGHTS 3.8's heat
            # transfer does the same), where the intersection circle shrinks and then vanishes
            return math.pi * min(radius_i, radius_j) ** 2
        return -0.25 * math.pi * ((r - radius_i - radius_j) * (r + radius_i - radius_j)
                                  * (r - radius_i + radius_j) * (r + radius_i + radius_j)) / (r * r)
    if cohesion == SJKR2:
        if wall:
            return 2.0 * math.pi * radius_i * (radius_i - r)
        return 2.0 * math.pi * (2.0 * radius_i * radius_j / (radius_i + radius_j)) * (radius_i + radius_j - r)
    return 0.0


@njit(cache=True)
def normal_constants(normal, table, ti, tj, r_eff, m_eff, overlap, charvel, nktv2p, tangential_damping):
    """(kn, kt, gamma_n, gamma_t) of the normal model for this contact."""
    if normal == HERTZ:
        root = math.sqrt(r_eff * overlap)
        sn = 2.0 * table[Y_STAR, ti, tj] * root
        st = 8.0 * table[G_STAR, ti, tj] * root
        kn = 4.0 / 3.0 * table[Y_STAR, ti, tj] * root
        kt = st
        gamma_n = -2.0 * SQRT_FIVE_SIXTHS * table[BETA, ti, tj] * math.sqrt(sn * m_eff)
        gamma_t = -2.0 * SQRT_FIVE_SIXTHS * table[BETA, ti, tj] * math.sqrt(st * m_eff)
    else:
        y_star = table[Y_STAR, ti, tj]
        root = math.sqrt(r_eff)
        kn = 16.0 / 15.0 * root * y_star * (15.0 * m_eff * charvel * charvel / (16.0 * root * y_star)) ** 0.2
        kt = kn
        log_e = table[LOG_E, ti, tj]
        # e = 1 (log e = 0): no damping, the limit of the formula
        gamma_n = math.sqrt(4.0 * m_eff * kn * log_e * log_e / (log_e * log_e + math.pi * math.pi))
        gamma_t = gamma_n
    if not tangential_damping:
        gamma_t = 0.0
    return kn / nktv2p, kt / nktv2p, gamma_n, gamma_t


@njit(cache=True)
def rolling_torque(rolling, wall, n, wr, r_eff, arm, kn, kt, fn, overlap, mu_roll, eta_roll, inertia, dt,
                   update, hist, torque):
    """The rolling torque M_r of the module docstring into ``torque`` (i gets -M_r, j +M_r);
    ``hist[3:6]`` is the epsd/epsd2 spring torque, grown and stored only when ``update``. ``wr``:
    relative spin, ``arm``: the lever arm cdt uses against a wall (R_i - delta/2)."""
    for d in range(3):
        torque[d] = 0.0
    if rolling == ROLL_OFF:
        return
    along = wr[0] * n[0] + wr[1] * n[1] + wr[2] * n[2]
    if rolling == CDT:
        size = math.sqrt(wr[0] * wr[0] + wr[1] * wr[1] + wr[2] * wr[2])
        if size > 0.0:
            scale = mu_roll * kn * overlap * (arm if wall else r_eff) / size
            for d in range(3):
                torque[d] = scale * (wr[d] - along * n[d])
        return
    kr = 2.25 * kn * mu_roll * mu_roll * r_eff * r_eff if rolling == EPSD else kt * r_eff * r_eff
    step = kr * dt if update else 0.0
    for d in range(3):
        torque[d] = hist[3 + d] + step * (wr[d] - along * n[d])
    size = math.sqrt(torque[0] * torque[0] + torque[1] * torque[1] + torque[2] * torque[2])
    cap = abs(fn) * r_eff * mu_roll
    capped = size > cap
    if capped:
        for d in range(3):
            torque[d] *= cap / size
    if update:
        for d in range(3):
            hist[3 + d] = torque[d]
    if rolling == EPSD and not capped:
        damping = eta_roll * 2.0 * math.sqrt(inertia * kr)
        for d in range(3):
            torque[d] += damping * (wr[d] - along * n[d])


@njit(cache=True)
def liggghts_contact(models, wall, table, ti, tj, r, radius_i, radius_j, mass_i, mass_j, m_eff, n, v_n,
                     vtr, wr, charvel, nktv2p, dt, update, hist, force, tangential, roll):
    """One contact: returns F_n (normal model plus cohesion, along n, on i). Into ``force`` the whole
    contact force on i (normal, cohesion and tangential; -force on j), into ``tangential`` its
    tangential part (whose torque the caller applies with the lever arms), into ``roll`` the rolling
    torque M_r (i gets -M_r). ``models``: int64 [normal, tangential, rolling, cohesion,
    tangential_damping, limit_force, dimension]. ``hist``: this contact's HISTORY_WIDTH values, as i
    sees them, updated in place. Against a wall (``wall``) radius_j and mass_j are not read."""
    overlap = radius_i + (0.0 if wall else radius_j) - r
    r_eff = radius_i if wall else radius_i * radius_j / (radius_i + radius_j)
    kn, kt, gamma_n, gamma_t = normal_constants(models[0], table, ti, tj, r_eff, m_eff, overlap, charvel,
                                                nktv2p, models[4] != 0)
    fn = kn * overlap - gamma_n * v_n
    if models[5] != 0 and fn < 0.0:
        fn = 0.0
    # the Coulomb limit and the rolling cap read the normal model's force: LIGGGHTS adds the
    # cohesion to it only with tangential_reduce on (off by default)
    fn_limit = fn
    fn -= table[COHESION, ti, tj] * contact_area(models[3], wall, r, radius_i, radius_j)
    mu = table[MU, ti, tj]
    if models[1] == HISTORY:
        if update:
            for d in range(3):
                hist[d] += vtr[d] * dt
            along = hist[0] * n[0] + hist[1] * n[1] + hist[2] * n[2]
            for d in range(3):
                hist[d] -= along * n[d]
        length = math.sqrt(hist[0] * hist[0] + hist[1] * hist[1] + hist[2] * hist[2])
        for d in range(3):
            tangential[d] = -kt * hist[d]
        limit = mu * abs(fn_limit)
        if kt * length > limit:
            if length != 0.0:
                ratio = limit / (kt * length)
                for d in range(3):
                    tangential[d] *= ratio
                    hist[d] = -tangential[d] / kt
            else:
                for d in range(3):
                    tangential[d] = 0.0
        else:
            for d in range(3):
                tangential[d] -= gamma_t * vtr[d]
    else:
        speed = math.sqrt(vtr[0] * vtr[0] + vtr[1] * vtr[1] + vtr[2] * vtr[2])
        scale = min(mu * abs(fn_limit), gamma_t * speed) / speed if speed != 0.0 else 0.0
        for d in range(3):
            tangential[d] = -scale * vtr[d]
    for d in range(3):
        force[d] = fn * n[d] + tangential[d]
    if models[2] != ROLL_OFF:
        shape = 1.5 if models[6] == 2 else 1.4
        if wall:
            inertia = shape * mass_i * radius_i * radius_i
        else:
            own_i = mass_i * radius_i * radius_i
            own_j = mass_j * radius_j * radius_j
            inertia = shape * own_i * own_j / (own_i + own_j)
        rolling_torque(models[2], wall, n, wr, r_eff, radius_i - 0.5 * overlap, kn, kt, fn_limit, overlap,
                       table[MU_ROLL, ti, tj], table[ETA_ROLL, ti, tj], inertia, dt, update, hist, roll)
    else:
        for d in range(3):
            roll[d] = 0.0
    return fn


# LIGGGHTS's property names, the form each is given in, and its range
PROPERTIES = {
    "youngsModulus": ("per_type", "peratomtype", lambda y: y > 0, "> 0"),
    "poissonsRatio": ("per_type", "peratomtype", lambda nu: -1 < nu <= 0.5, "in (-1, 0.5]"),
    "coefficientRestitution": ("per_type_pair", "peratomtypepair", lambda e: 0 < e <= 1, "in (0, 1]"),
    "coefficientFriction": ("per_type_pair", "peratomtypepair", lambda mu: mu >= 0, ">= 0"),
    "coefficientRollingFriction": ("per_type_pair", "peratomtypepair", lambda mu: mu >= 0, ">= 0"),
    "coefficientRollingViscousDamping": ("per_type_pair", "peratomtypepair", lambda eta: eta >= 0, ">= 0"),
    "cohesionEnergyDensity": ("per_type_pair", "peratomtypepair", lambda k: k >= 0, ">= 0"),
    "characteristicVelocity": ("scalar", "scalar", lambda v: v > 0, "> 0"),
    "thermalConductivity": ("per_type", "peratomtype", lambda k: k >= 0, ">= 0"),
    "thermalCapacity": ("per_type", "peratomtype", lambda c: c > 0, "> 0"),
}


def find_property(sim, name):
    """The fix holding global property ``name`` (the last one defined: fix property/global), or None."""
    found = None
    for fix in sim.fixes.values():
        if isinstance(fix, GlobalProperty) and fix.variable == name:
            found = fix
    return found


def read_property(sim, name, ntypes, who, spec=None):
    """The values of property ``name`` checked as PROPERTIES (or ``spec``, a tuple of that form, for
    a property a sub-model declares) says: a float (scalar), an array of ntypes + 1 (per type, index
    0 unused) or of (ntypes + 1, ntypes + 1) (per type pair). Missing, wrongly shaped or out-of-range
    values raise a one-line ScriptError naming the fix."""
    form, spelling, valid, bounds = spec or PROPERTIES[name]
    fix = find_property(sim, name)
    if fix is None:
        example = {"scalar": "VALUE", "per_type": "V1 ... V" + str(ntypes),
                   "per_type_pair": f"{ntypes} V11 ... V{ntypes}{ntypes}"}[form]
        raise ScriptError(f"{who} needs {name}: fix ID all property/global {name} {spelling} {example}")
    label = f"{name} (fix {fix.id})"
    if fix.style != form:
        raise ScriptError(f"{label} must be given as {spelling} (got {fix.args.style})")
    values = fix.values
    if form == "per_type" and len(values) != ntypes:
        raise ScriptError(f"{label} has {len(values)} value(s) for {ntypes} particle type(s)")
    if form == "per_type_pair" and fix.columns != ntypes:
        raise ScriptError(f"{label} is a {fix.columns} x {fix.columns} table for {ntypes} particle type(s)")
    bad = [float(x) for x in values if not valid(float(x))]
    if bad:
        raise ScriptError(f"{label} must be {bounds} (got {bad[0]:g})")
    if form == "scalar":
        return float(values[0])
    if form == "per_type":
        return np.concatenate([[0.0], values])
    table = np.zeros((ntypes + 1, ntypes + 1))
    table[1:, 1:] = values.reshape(ntypes, ntypes)
    return table


def material_table(sim, models, ntypes, who):
    """(table, characteristic velocity) for the models (an int sequence as ``liggghts_contact``
    takes): the MATERIAL rows for type pairs 1..ntypes from the fix property/global commands,
    each property read only where a model needs it (rows it does not need stay 0; the velocity is 0
    unless the normal model is hooke). A wall calls this with ntypes covering its own type."""
    youngs = read_property(sim, "youngsModulus", ntypes, who)
    poisson = read_property(sim, "poissonsRatio", ntypes, who)
    restitution = read_property(sim, "coefficientRestitution", ntypes, who)
    table = np.zeros((len(MATERIAL), ntypes + 1, ntypes + 1))
    for i in range(1, ntypes + 1):
        for j in range(1, ntypes + 1):
            table[Y_STAR, i, j] = youngs_effective(youngs[i], poisson[i], youngs[j], poisson[j])
            table[G_STAR, i, j] = shear_effective(youngs[i], poisson[i], youngs[j], poisson[j])
            table[BETA, i, j] = restitution_beta(restitution[i, j])
            table[LOG_E, i, j] = math.log(restitution[i, j])
    table[MU] = read_property(sim, "coefficientFriction", ntypes, who)
    if models[2] != ROLL_OFF:
        table[MU_ROLL] = read_property(sim, "coefficientRollingFriction", ntypes, who)
    if models[2] == EPSD:
        table[ETA_ROLL] = read_property(sim, "coefficientRollingViscousDamping", ntypes, who)
    if models[3] != COHESION_OFF:
        table[COHESION] = read_property(sim, "cohesionEnergyDensity", ntypes, who)
    charvel = read_property(sim, "characteristicVelocity", ntypes, who) if models[0] == HOOKE else 0.0
    return table, charvel
