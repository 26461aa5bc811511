"""Bad settings stop with one line; the time-step limits a timestep check reads; full contact slots;
the cutoff covers the largest contact; a run split in two follows the same trajectory."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, SimulationError
from pdps_core.testing import make_box, sphere_mass, unwrapped
from pdps_granular_contact import contact_models as cm

BOX = "units lj\nparticle_style sphere\nregion box block 0 10 0 10 0 10\ncreate_box 2 box\n"


def error_of(script):
    sim = Simulation(screen=False, log=None)
    with pytest.raises(ScriptError) as info:
        sim.command(script)
    message = str(info.value)
    assert "\n" not in message
    return message


@pytest.mark.parametrize("lines, message", [
    ("pair_style dem/lsd 1.2 1.0", "pair_style: e must be <= 1 (got 1.2)"),
    ("pair_style dem/lsd 0.3", "pair_style: missing argument cutoff; usage: pair_style dem/lsd e cutoff "
                               "[limit_damping yes|no] [max_contacts N]"),
    ("pair_style dem/lsd 0.3 1.0\npair_coeff * * -1000 16.6016 314.29 6.3008 0.5 1",
     "pair_coeff: kn must be > 0 (got -1000)"),
    ("pair_style dem/lsd 0.3 1.0\npair_coeff * * 1000 -16.6016 314.29 6.3008 0.5 1",
     "pair_coeff: cn must be >= 0 (got -16.6016)"),
    ("pair_style dem/lsd 0.3 1.0\npair_coeff * * 1000 16.6016 314.29 6.3008 -0.5",
     "pair_coeff: mu must be >= 0 (got -0.5)"),
    ("pair_style dem/lsd 0.3 1.0\npair_coeff * * kn 1000 e 0 mu 0.5", "pair_coeff: e must be > 0 (got 0)"),
    ("pair_style dem/lsd 0.3 1.0\npair_coeff * * kn 1000 e 0.5", "pair_coeff: missing keyword mu; usage: kn cn kt ct mu [cutoff]  or  "
     "kn KN [kt KT] [e E] mu MU [ct CT] [cutoff RC]"),
    ("pair_style dem/lsd 0.3 1.0\npair_coeff * * kn 1000 mu 0.5 gamma 3",
     "pair_coeff: unknown keyword gamma (known: kn, kt, e, mu, ct, cutoff)"),
    ("pair_style dem/hertz\npair_coeff * * 1e6 0.6 0.5 0.5", "pair_coeff: poisson must be <= 0.5 (got 0.6)"),
    ("pair_style dem/hertz\npair_coeff * * 0 0.3 0.5 0.5", "pair_coeff: youngs must be > 0 (got 0)"),
    ("pair_style dem/hertz\npair_coeff 1 1 NULL NULL 0.5 0.5",
     "pair_coeff: youngs and poisson of type 1 cannot be NULL: pair_coeff 1 1 gives the type's own material"),
    ("pair_style dem/hertz\npair_coeff 1 2 NULL 0.3 0.5 0.5",
     "pair_coeff: youngs and poisson are both numbers, or both NULL (each type's own material); usage: "
     "pair_coeff I J Y nu e mu  or  NULL NULL e mu (I != J: the two types' own materials)"),
    ("pair_style dem/hertz max_contacts 1", "pair_style: max_contacts must be >= 2 (got 1)"),
])
def test_bad_settings_give_one_line(lines, message):
    assert error_of(BOX + lines) == f"<command>:{len(BOX.splitlines()) + len(lines.splitlines())}: {message}"


def test_an_unset_type_pair_and_a_missing_material_are_named():
    run = "create_particle 1 single 5 5 5\ncreate_particle 2 single 7 5 5\n"
    assert error_of(BOX + run + "pair_style dem/hertz\npair_coeff 1 1 1e6 0.3 0.5 0.5\n"
                    "pair_coeff 2 2 1e6 0.3 0.5 0.5\nrun 0").endswith(
        "run: pair coefficients are not set for types 1 2 (give pair_coeff for every type pair, "
        "or a rule with pair_modify mix)")
    assert error_of(BOX + run + "pair_style dem/hertz\npair_coeff 1 1 1e6 0.3 0.5 0.5\n"
                    "pair_coeff 1 2 NULL NULL 0.5 0.5\nrun 0").endswith(
        "run: pair_coeff 1 2 NULL NULL needs the material of type 2 from a pair_coeff 2 2 line")


def test_point_particles_and_a_box_thinner_than_a_particle_are_refused():
    atomic = BOX.replace("particle_style sphere", "particle_style atomic")
    assert error_of(atomic + "mass * 1\ncreate_particle 1 single 5 5 5\npair_style dem/lsd 0.3 1.0\n"
                    "pair_coeff * * kn 1000 mu 0.5\nrun 0") == (
        "<command>:9: run: pair dem/lsd needs particle_style sphere (per-particle radius, mass and rotation)")
    thin = BOX.replace("0 10 0 10 0 10", "0 10 0 10 0 0.9")
    assert error_of(thin + "create_particle 1 single 5 5 0.45\npair_style dem/hertz\n"
                    "pair_coeff * * 1e6 0.3 0.5 0.5\nrun 0") == (
        "<command>:8: run: pair dem/hertz: the periodic box is thinner along z (0.9) than the largest "
        "particle (diameter 1): a particle would touch its own image")


def test_a_particle_with_more_contacts_than_slots_stops_the_run():
    sim = make_box("create_particle 1 single 5 5 5\n" + "".join(
        f"create_particle 1 single {5 + 0.99 * math.cos(a)} {5 + 0.99 * math.sin(a)} 5\n"
        for a in (0.0, 2.0, 4.0))
        + "pair_style dem/lsd 0.3 1.0 max_contacts 2\npair_coeff * * kn 1000 mu 0.5", ntypes=2,
                   particle_style="sphere")
    with pytest.raises(SimulationError) as info:
        sim.command("run 1")
    assert str(info.value) == ("<command>:1: run: particle 1 has more than 2 contacts at step 1; "
                               "raise max_contacts of pair_style dem/lsd")


def test_the_neighbor_cutoff_covers_the_largest_contact_whatever_the_given_cutoff():
    sim = make_box("create_particle 1 single 5 5 5 diameter 3\ncreate_particle 2 single 6.9 5 5\n"
                   "pair_style dem/lsd 0.3 0.5\npair_coeff * * kn 1000 mu 0.5\npair_coeff 2 2 kn 1000 mu 0.5 "
                   "cutoff 0.2\nrun 0", ntypes=2, particle_style="sphere")
    assert sim.pair_list.cutoff[1, 1] == 3.0 and sim.pair_list.cutoff[1, 2] == 2.0
    assert sim.pair_list.cutoff[2, 2] == 1.0
    assert np.abs(sim.f[0]).max() > 0          # r = 1.9 < 1.5 + 0.5: in contact
    assert np.array_equal(sim.f[0], -sim.f[1])


def two_types(pair, coeffs, v=(0.0, 0.0, 0.0)):
    sim = make_box("create_particle 1 single 2 5 5 diameter 1 density 2\n"
                   "create_particle 1 single 4 5 5 diameter 0.5 density 2\n"
                   "create_particle 2 single 6 5 5 diameter 2 density 3\n"
                   f"pair_style {pair}\n" + "".join(f"pair_coeff {c}\n" for c in coeffs),
                   ntypes=2, particle_style="sphere")
    sim.v[1] = v
    sim.command("run 0")
    return sim


def test_lsd_timestep_limit_is_the_contact_time_of_the_lightest_pair():
    sim = two_types("dem/lsd 0.3 1.0", ["1 1 kn 1000 e 0.5 mu 0.5", "1 2 kn 4000 e 0.5 mu 0.5",
                                        "2 2 1000 30 285 15 0.5"])
    limits = sim.pair.timestep_limits(sim)
    small, big = sphere_mass(0.5, 2), sphere_mass(2, 3)
    candidates = []
    for kn, m_star in ((1000, small / 2), (4000, small * big / (small + big))):
        candidates.append(cm.lsd_contact_time(kn, cm.lsd_damping(kn, m_star, 0.5), m_star))
    candidates.append(cm.lsd_contact_time(1000, 30, big / 2))
    assert limits == {"rayleigh": None, "hertz": None, "contact": pytest.approx(min(candidates), rel=1e-12)}


def test_lsd_timestep_limit_of_an_overdamped_contact_is_its_undamped_time():
    sim = two_types("dem/lsd 0.3 1.0", ["* * 1000 500 285 15 0.5"])
    m_star = sphere_mass(0.5, 2) / 2
    assert sim.pair.timestep_limits(sim)["contact"] == pytest.approx(math.pi * math.sqrt(m_star / 1000))


def test_hertz_timestep_limits_are_the_rayleigh_and_hertz_times_of_the_smallest_particle():
    coeffs = ["1 1 1e6 0.3 0.5 0.5", "2 2 1e5 0.25 0.5 0.5", "1 2 NULL NULL 0.5 0.5"]
    at_rest = two_types("dem/hertz", coeffs).pair
    limits = at_rest.timestep_limits(at_rest.sim)
    rayleigh = min(cm.rayleigh_time(0.25, 2.0, 1e6 / 2.6, 0.3), cm.rayleigh_time(1.0, 3.0, 1e5 / 2.5, 0.25))
    assert limits == {"rayleigh": pytest.approx(rayleigh, rel=1e-12), "hertz": None,
                      "contact": pytest.approx(rayleigh, rel=1e-12)}
    moving = two_types("dem/hertz", coeffs, v=(3.0, 4.0, 0.0)).pair
    limits = moving.timestep_limits(moving.sim)
    hertz = min(cm.hertz_contact_time(1e6 / (2 * (1 - 0.09)), r / 2, sphere_mass(2 * r, rho) / 2, 10.0)
                for r, rho in ((0.5, 2), (0.25, 2)))
    hertz = min(hertz, cm.hertz_contact_time(1e5 / (2 * (1 - 0.0625)), 0.5, sphere_mass(2, 3) / 2, 10.0))
    assert limits["hertz"] == pytest.approx(hertz, rel=1e-12)
    assert limits["contact"] == pytest.approx(min(hertz, rayleigh), rel=1e-12)


def test_a_run_split_in_two_follows_the_same_trajectory(dem):
    """The setup force computation of the second run uses the springs as stored, without advancing
    them: a sticking contact continues exactly. (Without damping: velocity Verlet evaluates forces at
    half-step velocities, the setup at full-step ones, so a damped contact would differ slightly.)"""
    def collide(runs):
        sim = dem.spheres("dem/lsd 0.3 1.0", ["* * kn 1000 e 1.0 mu 10 ct 0"],
                          [(1, 4.0, 5.0, 5.0, 1.0, 1.0), (1, 4.9, 5.45, 5.0, 1.0, 1.0)],
                          extra="timestep 0.0001\nfix move all test/nve_sphere")
        dem.set_motion(sim, 1, v=(1.0, 0.0, 0.0), omega=(0.0, 0.0, 8.0))
        for steps in runs:
            sim.command(f"run {steps}")
        return unwrapped(sim), sim.v[np.argsort(sim.tag)], sim.particles.omega[np.argsort(sim.tag)]
    whole, split = collide([600]), collide([350, 250])
    for a, b in zip(whole, split):
        assert np.array_equal(a, b)


def test_a_granular_box_with_no_particle_present_or_to_come_runs():
    """LIGGGHTS runs an empty granular box (an insertion that placed nothing, every particle gone):
    the pair's reach is then 0, and the skin alone sizes the bins."""
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command("atom_style granular\natom_modify map array\nboundary f f f\nunits si\n"
                "region box block 0 0.1 0 0.1 0 0.1 units box\ncreate_box 1 box\nneighbor 0.002 bin\n"
                "fix m1 all property/global youngsModulus peratomtype 5.e6\n"
                "fix m2 all property/global poissonsRatio peratomtype 0.45\n"
                "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9\n"
                "fix m4 all property/global coefficientFriction peratomtypepair 1 0.3\n"
                "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep 1e-5\n"
                "fix integr all nve/sphere\nrun 10\n"
                "create_atoms 1 single 0.05 0.05 0.05 units box\nset atom 1 diameter 0.01 density 2500\n"
                "velocity all set 0.0 0.0 -1.0 units box\nrun 10")
    assert sim.step == 20
    assert sim.particles.v[0, 2] == -1.0


def test_a_zero_cutoff_without_a_skin_is_refused():
    message = error_of(BOX + "neighbor 0.0 bin\npair_style dem/hertz\npair_coeff * * 1e6 0.3 0.5 0.5\nrun 1")
    assert message == ("<command>:8: run: neighbor list cutoff must be a finite number >= 0, and > 0 without a skin "
                       "(got 0, skin 0)")
