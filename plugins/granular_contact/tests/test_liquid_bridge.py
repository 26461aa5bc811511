"""LIGGGHTS's capillary cohesion models (pdps_granular_contact.gran.cohesion_easo_capillary_viscous,
cohesion_washino_capillary_viscous) in pair gran: their forces against the papers' formulas while
the spheres touch and in the bridge beyond contact, the rupture distances, the liquid a broken
bridge gives back (the liquid volume conserved), the reach of the neighbor list, and the one-line
refusals of bad input. The formulas here are written from the papers with LIGGGHTS's rounded
constants (4/3 x 1000 = 1333.333333, 8/15 = 0.5333333), independently of the modules."""

import math

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_refused, liggghts_material, pdps_cli  # noqa: F401
from pdps_granular_contact import contact_state as cs
from pdps_granular_contact.composition import ContactModel

R1, R2 = 0.005, 0.006
RHO1, RHO2 = 2500.0, 1500.0
THETA = (30.0, 40.0)                    # contact angles of the two types, degrees
SIGMA, ETA = 0.072, 0.05                # surface tension (N/m), viscosity (Pa s)
RHO_MIN, RHO_MAX = 1.01, 1.1
C0 = 0.01                               # initial content
MATERIAL = liggghts_material((5.e6, 1.e7), (0.45, 0.3), (0.9, 0.8, 0.8, 0.7), (0.3, 0.4, 0.4, 0.5))
FOUR_THIRDS, EIGHT_FIFTEENTHS = 1.333333333, 0.5333333


def liquid_lines(content=C0, theta=THETA, rho_max=RHO_MAX, more=""):
    return (f"fix l1 all property/global surfaceLiquidContentInitial scalar {content}\n"
            f"fix l2 all property/global surfaceTension scalar {SIGMA}\n"
            f"fix l3 all property/global fluidViscosity scalar {ETA}\n"
            f"fix l4 all property/global contactAngle peratomtype {' '.join(map(str, theta))}\n"
            f"fix l5 all property/global minSeparationDistanceRatio scalar {RHO_MIN}\n"
            f"fix l6 all property/global maxSeparationDistanceRatio scalar {rho_max}\n" + more)


def head(cohesion, liquid):
    return f"""atom_style granular
atom_modify map array
units si
boundary f f f
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 box
neighbor 0.002 bin
neigh_modify delay 0
{MATERIAL}{liquid}pair_style gran model hertz tangential history {cohesion}
pair_coeff * *
timestep 1e-6
"""


def wet_pair(cohesion, distance, *, v=(0.0, 0.0, 0.0), liquid=None, more=""):
    """Sphere 1 (type 1, radius R1) at the origin, sphere 2 (type 2, R2) on the x axis with its
    surface ``distance`` from 1's (negative: they overlap), 1 moving at ``v`` relative to 2."""
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(head(cohesion, liquid_lines() if liquid is None else liquid) + f"""create_atoms 1 single 0 0 0 units box
create_atoms 2 single {R1 + R2 + distance!r} 0 0 units box
set type 1 diameter {2 * R1} density {RHO1}
set type 2 diameter {2 * R2} density {RHO2}
set atom 1 vx {v[0]!r} vy {v[1]!r} vz {v[2]!r}
fix integr all nve/sphere
{more}""")
    return sim


def forces(sim):
    """Force and torque on each sphere (id order) of a run 0: the setup forces."""
    sim.command("run 0")
    order = np.argsort(sim.tag)
    return sim.f[order].copy(), sim.particles.torque[: sim.nlocal][order].copy()


def contents(sim):
    order = np.argsort(sim.tag)
    return sim.particles.arrays["surfaceLiquidContent"][: sim.nlocal][order].copy()


def theta_eff():
    """LIGGGHTS 3.8.0's effective contact angle of types 1 and 2: half the product, radians."""
    return 0.5 * math.radians(THETA[0]) * math.radians(THETA[1])


def solid(r):
    return 4.0 / 3.0 * math.pi * r ** 3


def easo_volume(c1=C0, c2=C0):
    """Easo's bridge: half of each film's cap under the other sphere (x 1000, as LIGGGHTS's)."""
    s = R1 + R2
    return (0.5 * FOUR_THIRDS * 1000 * math.pi * R1 ** 3 * c1 * (1 - math.sqrt(1 - R2 ** 2 / s ** 2))
            + 0.5 * FOUR_THIRDS * 1000 * math.pi * R2 ** 3 * c2 * (1 - math.sqrt(1 - R1 ** 2 / s ** 2)))


def washino_volume(c1=C0, c2=C0, fraction=0.05):
    return fraction * FOUR_THIRDS * 1000 * math.pi * (R1 ** 3 * c1 + R2 ** 3 * c2)


def soulie(distance, volume_1000=None):
    """Soulie et al.'s capillary force (along the normal; < 0 pulls)."""
    v = (volume_1000 or easo_volume()) / 1000 / max(R1, R2) ** 3
    theta = theta_eff()
    a = -1.1 * v ** -0.53
    b = (-0.148 * math.log(v) - 0.96) * theta ** 2 - 0.0082 * math.log(v) + 0.48
    c = 0.0018 * math.log(v) + 0.078
    return -math.pi * SIGMA * math.sqrt(R1 * R2) * (math.exp(a * distance / max(R1, R2) + b) + c)


def rabinovich(distance, volume_1000=None):
    """Rabinovich et al.'s capillary force: eq. A11 touching (distance < 0), eqs. 19, 20 apart (at
    distance 0 their limit: 2d = sqrt(2V / pi R*), s / 2d = 0)."""
    volume = (volume_1000 or washino_volume()) / 1000
    r = R1 * R2 / (R1 + R2)
    theta = theta_eff()
    if distance < 0:
        return -2 * math.pi * r * SIGMA * math.cos(theta) * (1 - distance * math.sqrt(math.pi * r / (2 * volume)))
    if distance == 0:
        gap, neck = 0.5 * math.sqrt(2 * volume / (math.pi * r)), math.cos(theta)
    else:
        gap = 0.5 * distance * (math.sqrt(1 + 2 * volume / (math.pi * r * distance ** 2)) - 1)
        neck = math.cos(theta) / (1 + distance / (2 * gap))
    alpha = math.sqrt(2 * gap / r)
    return -2 * math.pi * r * SIGMA * (neck + math.sin(alpha) * math.sin(alpha + theta))


def nase(v_n, v_t, distance):
    """Nase et al.'s viscous force (normal, tangential vector) at surface distance ``distance``."""
    r = R1 * R2 / (R1 + R2)
    ratio = max(RHO_MIN, distance / r)
    stokes = -6 * math.pi * ETA * r
    return stokes * v_n / ratio, stokes * (EIGHT_FIFTEENTHS * math.log(1 / ratio) + 0.9588) * np.asarray(v_t)


def rupture(volume_1000):
    """Lian et al.'s rupture distance, capped at (R1 + R2)(rho_max - 1)."""
    return min((1 + 0.5 * theta_eff()) * (volume_1000 / 1000) ** (1 / 3), (R1 + R2) * (RHO_MAX - 1))


CAPILLARY = {"easo/capillary/viscous": (soulie, easo_volume), "washino/capillary/viscous": (rabinovich, washino_volume)}


@pytest.mark.parametrize("model", CAPILLARY)
def test_touching_spheres_feel_the_capillary_and_viscous_forces(model):
    """Sphere 1 approaching and sliding past 2 while they overlap by 10 um: the cohesion adds, on
    top of the dry contact, the capillary pull and Nase's viscous forces at rho_min along the normal
    n = x1 - x2 and the sliding velocity, and the torque -(R1 - delta/2) n x F_t,visc."""
    capillary, _ = CAPILLARY[model]
    delta, v = 1e-5, (0.02, 0.03, -0.01)
    # Soulie's force of touching spheres is the one at distance 0, Rabinovich's grows with the overlap
    distance = 0.0 if model.startswith("easo") else -delta
    wet_f, wet_t = forces(wet_pair(f"cohesion {model}", -delta, v=v))
    dry_f, dry_t = forces(wet_pair("", -delta, v=v))
    n = np.array([-1.0, 0.0, 0.0])
    v_n = np.dot(v, n)
    v_t = np.asarray(v) - v_n * n
    normal, tangential = nase(v_n, v_t, -delta)
    expected = (capillary(distance) + normal) * n + tangential
    np.testing.assert_allclose(wet_f[0] - dry_f[0], expected, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(wet_f[1] - dry_f[1], -expected, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(wet_t[0] - dry_t[0], -(R1 - delta / 2) * np.cross(n, tangential), rtol=1e-8,
                               atol=1e-18)
    assert capillary(distance) < 0.0


def stretched(model, distance, v=(0.0, 0.0, 0.0)):
    """The bridge of two spheres that touched (one step in contact), now ``distance`` apart with 1
    moving at ``v``: the setup forces of a run 0."""
    sim = wet_pair(f"cohesion {model}", -1e-6)
    sim.command(f"run 1\nset atom 1 x 0.0 y 0.0 z 0.0\nset atom 2 x {R1 + R2 + distance!r} y 0.0 z 0.0\n"
                "velocity all set 0 0 0 units box\n"
                f"set atom 1 vx {v[0]!r} vy {v[1]!r} vz {v[2]!r}\nset atom 1 omega 0 0 0\nset atom 2 omega 0 0 0")
    return forces(sim)


@pytest.mark.parametrize("model", CAPILLARY)
def test_a_stretched_bridge_pulls_as_the_formula_says_until_it_ruptures(model):
    """Apart by s below the rupture distance min((1 + theta/2) V^1/3, (R1 + R2)(rho_max - 1)) the
    bridge pulls with the capillary force at s and Nase's viscous force at max(rho_min, s/R*);
    just beyond it, nothing pulls."""
    capillary, volume = CAPILLARY[model]
    cut = rupture(volume())
    v = (0.01, 0.004, 0.0)
    for s in (0.0, 0.1 * cut, 0.5 * cut, 0.999 * cut):
        f, _ = stretched(model, s, v)
        n = np.array([-1.0, 0.0, 0.0])
        v_n = np.dot(v, n)
        normal, tangential = nase(v_n, np.asarray(v) - v_n * n, s)
        np.testing.assert_allclose(f[0], (capillary(s) + normal) * n + tangential, rtol=1e-9, atol=1e-15)
    f, _ = stretched(model, 1.001 * cut, v)
    np.testing.assert_array_equal(f, 0.0)


def test_both_rupture_criteria_hold():
    """The bridge of these spheres is shorter than the cap for easo and longer than it for washino's
    contents x 5: each criterion decides once."""
    assert (1 + 0.5 * theta_eff()) * (easo_volume() / 1000) ** (1 / 3) < (R1 + R2) * (RHO_MAX - 1)
    assert (1 + 0.5 * theta_eff()) * (washino_volume() / 1000) ** (1 / 3) < (R1 + R2) * (RHO_MAX - 1)
    assert (1 + 0.5 * theta_eff()) * (washino_volume(5 * C0, 5 * C0) / 1000) ** (1 / 3) > (R1 + R2) * (RHO_MAX - 1)


def test_a_bridge_capped_by_rho_max_ruptures_there():
    """With five times the liquid washino's bridge outlasts the cap (R1 + R2)(rho_max - 1): it
    pulls just inside the cap and not beyond it."""
    liquid = liquid_lines(content=5 * C0)
    cap = (R1 + R2) * (RHO_MAX - 1)
    f, _ = forces(wet_pair("cohesion washino/capillary/viscous", 0.999 * cap, liquid=liquid))
    np.testing.assert_allclose(f[0, 0], -rabinovich(0.999 * cap, washino_volume(5 * C0, 5 * C0)), rtol=1e-9)
    f, _ = forces(wet_pair("cohesion washino/capillary/viscous", 1.001 * cap, liquid=liquid))
    np.testing.assert_array_equal(f, 0.0)


def test_washino_bridges_form_before_contact_easo_ones_at_contact():
    """Two spheres approaching, apart by half the rupture distance: washino's bridge is already
    there (Lian's distance forms it), easo's not yet (it forms at contact)."""
    s = 0.5 * rupture(washino_volume())
    f, _ = forces(wet_pair("cohesion washino/capillary/viscous", s))
    np.testing.assert_allclose(f[0, 0], -rabinovich(s), rtol=1e-9)
    f, _ = forces(wet_pair("cohesion easo/capillary/viscous", s))
    np.testing.assert_array_equal(f, 0.0)


@pytest.mark.parametrize("model", CAPILLARY)
def test_a_broken_bridge_shares_its_liquid_by_solid_volume(model):
    """Two wet spheres (sphere 2 twice as wet) pulled apart from contact: when the bridge breaks,
    its volume V goes back as V R^3 / (R1^3 + R2^3) to each and the volume the bridge took from each
    leaves it; the liquid volume sum c V_s is what it was."""
    _, volume = CAPILLARY[model]
    c1, c2 = C0, 2 * C0
    sim = wet_pair(f"cohesion {model}", -1e-6, v=(-0.2, 0.0, 0.0))
    sim.command(f"run 0\nset atom 2 property/atom surfaceLiquidContent {c2}")
    before = contents(sim)
    sim.command("run 10000")
    after = contents(sim)
    x = sim.x[np.argsort(sim.tag)]
    assert x[1, 0] - x[0, 0] > (R1 + R2) * RHO_MAX
    split = R1 ** 3 / (R1 ** 3 + R2 ** 3)
    bridge = volume(c1, c2) / 1000
    if model.startswith("easo"):
        s = R1 + R2
        taken = (0.5 * solid(R1) * c1 * (1 - math.sqrt(1 - R2 ** 2 / s ** 2)),
                 0.5 * solid(R2) * c2 * (1 - math.sqrt(1 - R1 ** 2 / s ** 2)))
    else:
        taken = (0.05 * solid(R1) * c1, 0.05 * solid(R2) * c2)
    expected = [c1 + (split * bridge - taken[0]) / solid(R1), c2 + ((1 - split) * bridge - taken[1]) / solid(R2)]
    np.testing.assert_allclose(after, expected, rtol=1e-10)
    assert abs(after[0] - c1) > 1e-5 * c1
    volumes = np.array([solid(R1), solid(R2)])
    assert after @ volumes == pytest.approx(before @ volumes, rel=1e-13)


def test_the_neighbor_cutoff_covers_the_reach():
    """Spheres up to 1.1 rho_max (R_i + R_j) apart are looked at (LIGGGHTS's contact distance
    factor): the cutoff of types 1 and 2."""
    sim = wet_pair("cohesion easo/capillary/viscous", 0.01)
    sim.command("run 0")
    assert math.sqrt(sim.pair.cutsq[1, 2]) == pytest.approx(1.1 * RHO_MAX * (R1 + R2), rel=1e-14)
    dry = wet_pair("", 0.01)
    dry.command("run 0")
    assert math.sqrt(dry.pair.cutsq[1, 2]) == pytest.approx(R1 + R2, rel=1e-14)


def test_limit_liquid_content_caps_the_particles_of_a_pair_and_resizes_rho_max():
    """limitLiquidContent: a particle evaluated in a pair holds at most maxLiquidContent of its type
    (sphere 3, far from all, keeps its liquid until it meets one), and rho_max becomes 1 +
    max_t (1 + theta_t^2/4)(2 f c_max,t 4/3 pi R_max^3)^(1/3) / 2 R_min."""
    liquid = liquid_lines(more="fix l7 all property/global maxLiquidContent peratomtype 0.004 0.02\n")
    sim = wet_pair("cohesion washino/capillary/viscous limitLiquidContent on", 0.0005, liquid=liquid,
                   more="create_atoms 1 single -0.03 0 0 units box\nset atom 3 diameter 0.01 density 2500")
    sim.command("run 0")
    np.testing.assert_array_equal(contents(sim), [0.004, C0, C0])
    ratio = max((1 + 0.5 * (0.5 * math.radians(t) ** 2)) * (2666.666666 * math.pi * R2 ** 3 * cap * 0.05) ** (1 / 3)
                * 0.1 / (2 * R1) for t, cap in zip(THETA, (0.004, 0.02)))
    warning = next(m for m in sim.warnings if "maxLiquidContent" in m)
    assert warning == (f"maxLiquidContent was specified, resulting in maxSeparationDistanceRatio being overwritten by "
                       f"{1 + ratio:e} (was {RHO_MAX:e})")


def test_tangential_reduce_lets_the_coulomb_limit_see_the_bridge():
    """tangential_reduce on: the normal force the tangential model's Coulomb limit reads gains the
    capillary and viscous normal forces (off, the default: it does not)."""
    limits = {}
    for reduce in ("off", "on"):
        model = ContactModel("gran", {"normal": "hertz", "tangential": "history", "cohesion": "easo/capillary/viscous"},
                             {"tangential_reduce": reduce})
        sim = wet_pair("", -1e-5)
        sim.command("run 0")
        coeff = model.bind(sim.pair.material)
        c = np.zeros(cs.SIZE)
        c[cs.RADIUS_I], c[cs.RADIUS_J], c[cs.R] = R1, R2, R1 + R2 - 1e-5
        c[cs.DELTA], c[cs.R_EFF] = 1e-5, R1 * R2 / (R1 + R2)
        c[cs.MASS_I], c[cs.MASS_J] = RHO1 * solid(R1), RHO2 * solid(R2)
        c[cs.M_EFF] = c[cs.MASS_I] * c[cs.MASS_J] / (c[cs.MASS_I] + c[cs.MASS_J])
        c[cs.NX], c[cs.VX], c[cs.DT], c[cs.UPDATE], c[cs.DIMENSION] = 1.0, -0.01, 1e-6, 1.0, 3
        c[cs.LIQUID_I] = c[cs.LIQUID_J] = C0
        model.kernels().contact_one(c, coeff, 1, 2, np.zeros(model.history_width))
        limits[reduce] = (c[cs.FN], c[cs.FN_LIMIT])
    normal, _ = nase(-0.01, np.zeros(3), -1e-5)
    assert limits["on"][1] - limits["off"][1] == pytest.approx(soulie(0.0) + normal, rel=1e-9)
    assert limits["on"][0] == limits["off"][0]


def bad_liquid(**change):
    values = {"content": C0, "theta": THETA, "rho_max": RHO_MAX}
    values.update(change)
    return liquid_lines(**values)


@pytest.mark.parametrize("cohesion, liquid, at, message", [
    ("easo/capillary/viscous", liquid_lines().replace("fix l2 all property/global surfaceTension scalar 0.072\n", ""),
     "run", "pair gran needs surfaceTension: fix ID all property/global surfaceTension scalar VALUE"),
    ("easo/capillary/viscous", bad_liquid(theta=(30, 200)), "run",
     "contactAngle (fix l4) must be in [0, 180] (degrees) (got 200)"),
    ("washino/capillary/viscous", bad_liquid(theta=(30,)), "run",
     "contactAngle (fix l4) has 1 value(s) for 2 particle type(s)"),
    ("easo/capillary/viscous", bad_liquid(rho_max=0.9), "run",
     "maxSeparationDistanceRatio (fix l6) must be >= 1 (got 0.9)"),
    ("easo/capillary/viscous", bad_liquid(content=-0.1), "run",
     "surfaceLiquidContentInitial (fix l1) must be >= 0 (got -0.1)"),
    ("washino/capillary/viscous limitLiquidContent on", liquid_lines(), "run",
     "pair gran needs maxLiquidContent: fix ID all property/global maxLiquidContent peratomtype V1 ... V2"),
    ("washino/capillary/viscous modifyLbVolume on", liquid_lines(), "run",
     "pair gran needs lbVolumeFraction: fix ID all property/global lbVolumeFraction scalar VALUE"),
    ("easo/capillary/viscous limitLiquidContent on", liquid_lines(), "pair_style",
     "limitLiquidContent is not a setting of the chosen models (normal hertz cohesion easo/capillary/viscous "
     "tangential history)"),
])
def test_bad_liquid_input_is_refused_in_one_line(pdps_cli, cohesion, liquid, at, message):  # noqa: F811
    script = head(f"cohesion {cohesion}", liquid) + ("create_atoms 1 single 0 0 0 units box\n"
                                                     "set type 1 diameter 0.01 density 2500\nrun 0\n")
    line = next(k for k, text in enumerate(script.splitlines(), start=1) if text.startswith(at))
    assert_refused(pdps_cli(script), line, f"{at}: {message}")


def test_fix_wall_gran_refuses_a_liquid_bridge(pdps_cli):  # noqa: F811
    script = head("", liquid_lines()) + ("fix floor all wall/gran model hertz tangential history cohesion "
                                         "easo/capillary/viscous primitive type 1 zplane -0.04\n")
    assert_refused(pdps_cli(script), len(script.splitlines()),
                   "fix: cohesion easo/capillary/viscous is a liquid bridge between particles: pair gran only "
                   "(LIGGGHTS's manual: not part of fix wall/gran)")


def test_a_liggghts_script_reads_the_liquid_as_f_surfaceLiquidContent():
    """The per-atom liquid is LIGGGHTS's f_surfaceLiquidContent in computes and atom-style
    variables, made at the first run (a run 0) with surfaceLiquidContentInitial as LIGGGHTS prints
    it (%e: seven significant digits)."""
    sim = wet_pair("cohesion easo/capillary/viscous", 0.01, liquid=liquid_lines(content=0.0123456789))
    sim.command("run 0\nset atom 2 property/atom surfaceLiquidContent 0.02\n"
                "compute lc all reduce sum f_surfaceLiquidContent\nvariable vl atom f_surfaceLiquidContent*radius^3\n"
                "compute lv all reduce sum v_vl\nvariable lc equal c_lc\nvariable lv equal c_lv")
    assert sim.variables.value("lc") == pytest.approx(0.01234568 + 0.02, rel=1e-15)
    assert sim.variables.value("lv") == pytest.approx(0.01234568 * R1 ** 3 + 0.02 * R2 ** 3, rel=1e-14)
