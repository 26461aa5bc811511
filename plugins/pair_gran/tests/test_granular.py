"""pair_style granular (LAMMPS's composed contacts) against LAMMPS 22 Jul 2025's trajectories
(data/granular/NAME.ref, recorded by benchmarks/lammps_references/granular.py), formulas, analytic
limits and the errors of its pair_coeff lines."""

import math

from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import Record, assert_refused, register_styles

GRANULAR = Path(__file__).parent / "data" / "granular"
CASES = sorted(path.stem for path in GRANULAR.glob("*.ref"))


@pytest.mark.parametrize("name", CASES)
def test_trajectories_equal_lammps(granular_case, name):
    """x, v, omega of every particle at every dumped step equal LAMMPS's to 1e-10 of their scale
    over the whole contact, and a contact changed the motion."""
    record, table = granular_case(name, rtol=1e-10)
    assert not np.allclose(record.v[max(table) - 1], record.v[0])


UNIT_MASS = 1.9098593171027440      # density of a sphere of diameter 1 and mass 1


def two_spheres(tmp_path, coeff, speed, *, dt=1e-5, gap=0.0, steps=None, omega=((0, 0, 0), (0, 0, 0)),
                offset=0.0, extra=""):
    """Two unit spheres (mass 1) along x closing at ``speed`` each way (``offset``: the second one
    that far along y), ``gap`` apart, contact law ``coeff``; returns (sim, record) after ``steps``
    (or none: set up only)."""
    lines = ["pdps granular test", "", "2 atoms", "1 atom types", "", "0 10 xlo xhi", "0 10 ylo yhi",
             "0 10 zlo zhi", "", "Atoms # sphere", "",
             f"1 1 1.0 {UNIT_MASS!r} 4.5 5.0 5.0", f"2 1 1.0 {UNIT_MASS!r} {5.5 + gap!r} {5.0 + offset!r} 5.0", "",
             "Velocities", "", f"1 {speed!r} 0 0 0 0 0", f"2 {-speed!r} 0 0 0 0 0"]
    (tmp_path / "two.data").write_text("\n".join(lines) + "\n")
    register_styles(Record)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"units lj\natom_style sphere\nboundary p p p\nread_data {tmp_path / 'two.data'}\n"
                f"pair_style granular\npair_coeff * * {coeff}\ntimestep {dt!r}\nfix 1 all nve/sphere\n"
                f"fix record all test/record\n{extra}")
    for tag, w in zip((1, 2), omega):
        sim.particles.omega[sim.particles.index_of_tag(tag)] = w
    if steps:
        sim.command(f"run {steps}")
    return sim, sim.fixes["record"]


def collision(tmp_path, coeff, speed, steps=20000, **kwargs):
    """(restitution, contact time) of a head-on collision of two unit spheres at +-``speed``."""
    sim, record = two_spheres(tmp_path, coeff, speed, gap=1e-6, steps=steps, **kwargs)
    x = np.array([row[1, 0] - row[0, 0] for row in record.x])
    touching = np.flatnonzero(x < 1.0)
    assert len(touching) and touching[-1] < len(x) - 1, "the spheres should have met and parted"
    rebound = record.v[-1][1, 0] - record.v[-1][0, 0]
    return rebound / (2.0 * speed), len(touching) * float(sim.dt)


@pytest.mark.parametrize("speed", [0.2, 1.0, 3.0])
def test_coeff_restitution_with_hooke_rebounds_with_e_at_any_speed(tmp_path, speed):
    """Linear spring, dashpot alpha sqrt(m* k_n), alpha = -2 ln e / sqrt(pi^2 + ln^2 e): the damped
    oscillator's half period gives back exactly e of the closing speed."""
    e, _ = collision(tmp_path, "hooke 200000.0 0.6 damping coeff_restitution tangential linear_nohistory 0.0 0.0",
                     speed)
    assert e == pytest.approx(0.6, rel=1e-2)


@pytest.mark.parametrize("damping, e, rebound", [("coeff_restitution", 0.5, 0.5), ("tsuji", 0.5, 0.6161),
                                                 ("tsuji", 0.3, 0.4396)])
def test_hertz_dashpots_give_their_restitution_independent_of_speed(tmp_path, damping, e, rebound):
    """Hertz with a dashpot alpha sqrt(m* F_ne / delta): the restitution is the same at every
    impact speed (a dimensionless number of alpha alone), e within 1 % for coeff_restitution; for
    tsuji, LAMMPS 22 Jul 2025's (whose alpha lacks the sqrt(2) of Tsuji's mass convention that later
    LAMMPS multiplies in: with it the rebound is e to 0.2 %), the rebound that release gives."""
    coeff = f"hertz/material 1.0e5 {e} 0.3 damping {damping} tangential linear_nohistory 0.0 0.0"
    slow, _ = collision(tmp_path, coeff, 0.3, steps=40000)
    fast, _ = collision(tmp_path, coeff, 3.0)
    assert slow == pytest.approx(fast, rel=2e-3)
    assert fast == pytest.approx(rebound, rel=1e-2)


def test_undamped_hertz_lasts_hertz_contact_time(tmp_path):
    """t_c = 2.8683 (m*^2 / (R* E*^2 v))^(1/5) for F = 4/3 E* sqrt(R*) delta^(3/2), v the closing
    speed; an elastic contact returns the speed."""
    speed = 1.0
    e, duration = collision(tmp_path, "hertz/material 1.0e5 0.0 0.3 damping velocity tangential linear_nohistory "
                            "0.0 0.0", 0.5 * speed)
    youngs = 1.0e5 / (2.0 * (1.0 - 0.09))
    expected = 2.8683 * (0.5 ** 2 / (0.25 * youngs ** 2 * speed)) ** 0.2
    assert e == pytest.approx(1.0, abs=1e-6)
    assert duration == pytest.approx(expected, rel=1e-2)


def contact_state(r_eff, overlap, m_eff=0.5):
    from pdps_granular_contact.contact_state import DELTA, M_EFF, R_EFF, SIZE
    c = np.zeros(SIZE)
    c[R_EFF], c[DELTA], c[M_EFF] = r_eff, overlap, m_eff
    return c


def test_jkr_pulls_at_most_three_pi_gamma_r_and_its_radius_solves_jkr_relation():
    """The JKR force over the overlaps from the pull-off distance to compression: its least value is
    the pull-off force 3 pi gamma R* (JKR's 3/2 pi w R* of the work of adhesion w = 2 gamma), and the
    contact radius solves delta = a^2/R* - 2 sqrt(pi gamma a / E*)."""
    from pdps_granular_contact.contact_state import CONTACT_RADIUS, FN, FN_LIMIT
    from pdps_granular_contact.granular.normal_jkr import jkr_force, jkr_pulloff_distance
    modulus, gamma, r_eff = 5.0e4, 10.0, 0.25
    k = np.array([modulus, gamma])
    reach = jkr_pulloff_distance(k, 0.5, 0.5)
    least = math.inf
    for overlap in np.linspace(-reach, 0.01, 20001):
        c = contact_state(r_eff, overlap)
        jkr_force(c, k, np.zeros(1), 0)
        a = c[CONTACT_RADIUS]
        assert overlap == pytest.approx(a * a / r_eff - 2.0 * math.sqrt(math.pi * gamma * a / modulus), abs=1e-12)
        least = min(least, c[FN])
        assert c[FN_LIMIT] == pytest.approx(abs(c[FN] + 6.0 * math.pi * gamma * r_eff))
    assert -least == pytest.approx(3.0 * math.pi * gamma * r_eff, rel=1e-4)
    # at the pull-off distance the neck is still there: it breaks beyond (LAMMPS's contact test)
    assert reach == pytest.approx((3.0 * math.pi ** 2 / 16.0 * r_eff * gamma ** 2 / modulus ** 2) ** (1 / 3))


def test_dmt_pulls_four_pi_gamma_r_at_touching_and_its_elastic_part_is_hertz():
    from pdps_granular_contact.contact_state import FN
    from pdps_granular_contact.granular.normal_dmt import dmt_force
    k = np.array([4.0 / 3.0 * 5.0e4, 10.0])
    c = contact_state(0.25, 1e-300)
    dmt_force(c, k, np.zeros(1), 0)
    assert c[FN] == pytest.approx(-4.0 * math.pi * 10.0 * 0.25, rel=1e-12)
    c = contact_state(0.25, 0.01)
    dmt_force(c, k, np.zeros(1), 0)
    assert c[FN] + 4.0 * math.pi * 10.0 * 0.25 == pytest.approx(4.0 / 3.0 * 5.0e4 * math.sqrt(0.25) * 0.01 ** 1.5)


def test_hertz_force_is_minus_the_derivative_of_its_energy():
    """F = -dU/dr with U = 2/5 k sqrt(R*) delta^(5/2) (k = 4/3 E*: 8/15 E* sqrt(R*) delta^(5/2)): centred
    differences of U."""
    from pdps_granular_contact.contact_state import FN
    from pdps_granular_contact.granular.normal_hertz import hertz_force
    k, r_eff, h = np.array([7.3e4]), 0.3, 1e-7
    energy = lambda d: 0.4 * k[0] * math.sqrt(r_eff) * d ** 2.5  # noqa: E731
    for overlap in (1e-4, 3e-3, 2e-2):
        c = contact_state(r_eff, overlap)
        hertz_force(c, k, np.zeros(1), 0)
        assert c[FN] == pytest.approx((energy(overlap + h) - energy(overlap - h)) / (2 * h), rel=1e-6)


def test_a_jkr_contact_holds_below_the_pull_off_force_and_breaks_above(tmp_path):
    """Spheres touching at rest, pulled apart by +-F (load control, overdamped so that nothing
    overshoots): the neck holds for F below JKR's 3 pi gamma R* = 23.56, stretched beyond touching,
    and breaks above it."""
    pulloff = 3.0 * math.pi * 10.0 * 0.25
    ends = {}
    for force in (0.97 * pulloff, 1.03 * pulloff):
        sim, record = two_spheres(tmp_path, "jkr 1.0e5 400.0 0.3 10.0 damping velocity tangential linear_history "
                                  "1000.0 0.5 0.5",
                                  0.0, gap=-1e-4, dt=1e-4, extra=f"group left id 1\ngroup right id 2\n"
                                  f"fix 2 left addforce {-force!r} 0 0\nfix 3 right addforce {force!r} 0 0\n")
        sim.command("run 30000")
        ends[force] = record.x[-1][1, 0] - record.x[-1][0, 0]
    held, broken = ends[0.97 * pulloff], ends[1.03 * pulloff]
    assert 1.0 < held < 1.0 + 1.2 * (3.0 * math.pi ** 2 / 16.0 * 0.25 * 100.0 / 5.4945e4 ** 2) ** (1 / 3)
    assert broken > 1.05


def test_a_contact_conserves_momentum_and_angular_momentum(tmp_path):
    """Force and its opposite, torques about the contact point (arms R - delta/2 adding up to r),
    rolling and twisting torques opposite: sum m v and sum x m v + I w stay as they were."""
    sim, record = two_spheres(
        tmp_path, "hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential mindlin NULL 1.0 0.5 "
        "rolling sds 500.0 2.0 0.1 twisting marshall", 1.0, gap=1e-3, offset=0.3, omega=((3, 1, 5), (1, -2, 4)),
        dt=1e-4, steps=2000)
    inertia = 0.4 * 1.0 * 0.25

    def momenta(k):
        x, v, w = record.x[k], record.v[k], record.omega[k]
        return v.sum(axis=0), np.cross(x, v).sum(axis=0) + inertia * w.sum(axis=0)
    (p0, l0), (p1, l1) = momenta(0), momenta(-1)
    assert not np.allclose(record.omega[-1], record.omega[0])
    np.testing.assert_allclose(p1, p0, atol=1e-13)
    np.testing.assert_allclose(l1, l0, atol=1e-12)


SETUP = """\
units lj
atom_style sphere
region box block 0 10 0 10 0 10
create_box 2 box
pair_style granular
"""
MINDLIN = "tangential mindlin NULL 1.0 0.5"


@pytest.mark.parametrize("coeff, message", [
    (f"* * hertz/materal 1e5 0.5 0.3 {MINDLIN}",
     "normal model must be one of dmt, hertz, hertz/material, hooke, jkr (got hertz/materal)"),
    (f"* * hertz/material 1e5 0.5 {MINDLIN}",
     "normal hertz/material needs 3 coefficient(s) (E eta_n0 nu) (got 2: 1e5 0.5)"),
    (f"* * hertz/material -1e5 0.5 0.3 {MINDLIN}", "normal hertz/material: E must be > 0 (got -1e5)"),
    ("* * hertz/material 1e5 0.5 0.3 tangential mindlin NULL 1.0",
     "tangential mindlin needs 3 coefficient(s) (k_t x_gamma_t mu_s) (got 2: NULL 1.0)"),
    ("* * hooke 1e5 x damping velocity tangential linear_history 1e3 1.0 0.5",
     "normal hooke: eta_n0 must be a finite number (got x)"),
    ("* * hertz/material 1e5 0.5 0.3", "pair granular needs a tangential model: ... tangential TANGENTIAL "
     "coefficients (got none)"),
    (f"* * hooke 1e5 0.5 {MINDLIN}", "tangential mindlin: k_t NULL takes the stiffness from the normal model's "
     "material, which hooke has not (use hertz/material, dmt or jkr, or give k_t)"),
    ("* * hooke 1e5 0.5 tangential linear_history 1e3 1.0 0.5 rolling epsd 1 1 1",
     "rolling model must be one of sds (got epsd)"),
    ("* * hooke 1e5 0.5 tangential linear_history 1e3 1.0 0.5 wiggle",
     "keyword must be one of damping, tangential, rolling, twisting, heat, limit_damping, cutoff (got wiggle)"),
    ("* * hooke 1e5 1.5 damping coeff_restitution tangential linear_history 1e3 1.0 0.5",
     "damping coeff_restitution reads the normal model's eta_n0 as a restitution coefficient: it must be > 0 and "
     "<= 1 (got 1.5)"),
    (f"* * jkr 1e5 0.5 0.3 1.0 {MINDLIN} limit_damping",
     "limit_damping cannot be used with a cohesive normal model (got jkr)"),
    (f"* * dmt 1e5 0.5 0.3 1.0 damping tsuji {MINDLIN}",
     "damping tsuji cannot be used with a cohesive normal model (got dmt)"),
    (f"* * hertz/material 1e5 0.5 0.3 {MINDLIN} heat area 1.0",
     "heat models of pair granular are not built in pdps: they need LAMMPS's fix heat/flow and atom style "
     "sphere/temp, which pdps has not (got heat area)"),
    ("* * classic hooke 1e5 NULL 50 NULL 0.5 1", "pair granular's classic model is not built in pdps: use "
     "pair_style gran/hooke, gran/hooke/history or gran/hertz/history (got classic)"),
])
def test_bad_pair_coeff_lines_are_refused_at_their_line(pdps_cli, coeff, message):
    assert_refused(pdps_cli(SETUP + f"pair_coeff {coeff}\n"), 6, f"pair_coeff: {message}")


def test_none_leaves_a_part_out():
    from pdps_granular_contact.granular.words import read_law
    law = read_law("hooke 1e5 0.5 tangential linear_history 1e3 1.0 0.5 rolling none twisting none heat none".split())
    assert sorted(law.parts) == ["damping", "normal", "tangential"]
    assert law.name("damping") == "viscoelastic"


def test_other_models_for_another_type_pair_are_refused(pdps_cli):
    done = pdps_cli(SETUP + "pair_coeff 1 1 hooke 1e5 0.5 tangential linear_history 1e3 1.0 0.5\n"
                    "pair_coeff 2 2 hooke 1e5 0.5 tangential mindlin 1e3 1.0 0.5\n")
    assert_refused(done, 7, "pair_coeff: pdps composes one law for every type pair: tangential mindlin differs "
                   "from the linear_history of an earlier pair_coeff line (got mindlin)")


def test_mixing_follows_lammps():
    """pair_coeff 1 1 and 2 2 only: 1 2 gets E* of the two materials (k = 4/3 E*), the geometric
    means of eta_n0, nu and of the tangential coefficients, mindlin NULL of the mixed E*, nu."""
    from pdps_granular_contact.granular.base import effective_modulus, effective_shear_modulus
    from pdps_granular_contact.granular.words import read_law
    one = read_law("hertz/material 1e5 0.5 0.3 damping coeff_restitution tangential mindlin NULL 1.0 0.5".split())
    two = read_law("hertz/material 3e5 0.8 0.2 damping coeff_restitution tangential mindlin NULL 0.5 0.3".split())
    mixed = one.mix(two, 1, 2)
    normal, tangential = mixed.args("normal"), mixed.args("tangential")
    assert normal.E == pytest.approx(effective_modulus(1e5, 3e5, 0.3, 0.2))
    assert (normal.eta_n0, normal.nu) == pytest.approx((math.sqrt(0.4), math.sqrt(0.06)))
    assert (tangential.k_t, tangential.x_gamma_t, tangential.mu_s) == (None, math.sqrt(0.5), math.sqrt(0.15))
    hertz, mindlin = (cls({}) for cls, _ in (mixed.parts["normal"], mixed.parts["tangential"]))
    assert hertz.values(mixed, "pair") == pytest.approx((4.0 / 3.0 * normal.E,))
    assert mindlin.values(mixed, "pair")[0] == pytest.approx(8.0 * effective_shear_modulus(normal.E, normal.E,
                                                                                            normal.nu, normal.nu))
    assert hertz.values(one, "pair") == pytest.approx((4.0 / 3.0 * 1e5 / (2.0 * (1.0 - 0.09)),))
    other = read_law("hertz/material 3e5 0.8 0.2 damping coeff_restitution tangential linear_history 1e3 0.5 0.3"
                     .split())
    with pytest.raises(ScriptError, match="types 1 and 2 have different tangential models"):
        one.mix(other, 1, 2)


def test_jkr_reaches_its_pull_off_distance_in_the_neighbor_cutoff(tmp_path):
    sim, _ = two_spheres(tmp_path, "jkr 1.0e5 200.0 0.3 10.0 tangential linear_history 1000.0 0.5 0.5", 0.0,
                         gap=0.5)
    sim.command("run 0")
    reach = (3.0 * math.pi ** 2 / 16.0 * 0.25 * 100.0 / (1e5 / 1.82) ** 2) ** (1 / 3)
    assert sim.pair.init(1)[1, 1] == pytest.approx(1.0 + reach)


def test_the_partner_gets_the_spring_negated_and_the_rolling_and_twist_unchanged():
    """What j keeps of a contact i computed: the tangential spring seen from j is -xi, but
    mindlin_rescale's contact radius (LAMMPS's transfer factor +1), the rolling displacement (from R*
    (w_i - w_j) x n) and the twist angle (from (w_i - w_j).n) are the same seen from either sphere, so
    they go to j as they are and do not flip when the other sphere comes to hold the contact (LAMMPS
    22 Jul 2025 negates the last two: its trajectories then depend on its atom sort;
    tests/lammps_scripts/test_granular_settle.py)."""
    from pdps_granular_contact import contact_block
    from pdps_granular_contact.composition import ContactModel
    from pdps_granular_contact.granular.base import Laws
    from pdps_granular_contact.granular.words import read_law
    law = read_law("hertz/material 1e5 0.5 0.3 tangential mindlin_rescale NULL 1.0 0.5 rolling sds 500 2 0.1 "
                   "twisting sds 50 0.5 0.05".split())
    model = ContactModel("granular", {part: cls.name for part, (cls, _) in law.parts.items()})
    assert model.history_width == 4 + 3 + 1
    model.bind(Laws(1, {(1, 1): law}))
    kernels = model.kernels()
    history, owner = np.zeros((2, 8)), np.full(2, -1, dtype=np.int64)
    hist = np.arange(1.0, 9.0)
    # one contact of rows 0 and 1, slot 0 on both, as the pair loop's block holds it (contact_block)
    block_in, block_out, block_index = model.block()
    for h in range(8):
        block_out[(contact_block.HIST_OUT + h) * contact_block.BLOCK] = hist[h]
    for column, value in ((contact_block.ROW_I, 0), (contact_block.ROW_J, 1), (contact_block.SLOT_I, 0),
                          (contact_block.SLOT_J, 0)):
        block_index[column * contact_block.BLOCK] = value
    kernels.scatter_contacts(1, block_in, block_out, block_index, np.zeros((2, 3)), np.zeros((2, 3)), history, owner,
                             True, np.zeros(0), np.zeros((0, 3)), np.zeros(0), np.zeros(0),
                             np.zeros((0, 2), dtype=np.int64), np.zeros((0, 3)), np.zeros(1, dtype=np.int64))
    np.testing.assert_array_equal(history[0], hist)
    np.testing.assert_array_equal(history[1], [-1, -2, -3, 4, 5, 6, 7, 8])


def test_same_settling_on_1_and_2_ranks(tmp_path):
    """A bed of polydisperse spheres settling on a fix wall/gran granular floor, pair granular with
    every history kind (mindlin_rescale's 4 values, a rolling displacement and a twist angle handed
    on unchanged), newton off: the same kinetic energies on 1 and 2 ranks."""
    from pdps_core.testing import run_ranks, sphere_bed, thermo_rows
    sphere_bed(tmp_path / "bed.data", (12, 6, 4), (0.7, 0.7, 0.7), (0, 0, 0), (15.6, 7.8, 12), ntypes=1, seed=11)
    law = ("hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential mindlin_rescale NULL 1.0 0.5 "
           "rolling sds 500.0 2.0 0.1 twisting sds 50.0 0.5 0.05")
    script = f"""\
        units lj
        atom_style sphere
        boundary p p f
        newton off
        read_data bed.data
        pair_style granular
        pair_coeff * * {law}
        timestep 0.0001
        fix 1 all nve/sphere
        fix 2 all gravity 10.0 vector 0 0 -1
        fix 3 all wall/gran granular {law} zplane 0.0 NULL
        compute rke all erotate/sphere
        thermo_style custom step ke c_rke
        thermo_modify format float %.15g
        thermo 500
        run 3000
        """
    one = np.array(thermo_rows(run_ranks(script, 1, tmp_path).stdout))
    two = np.array(thermo_rows(run_ranks(script, 2, tmp_path).stdout))
    assert one[:, 0].tolist() == list(range(0, 3001, 500))
    assert one[-1, 2] > 0.0
    assert two == pytest.approx(one, rel=1e-9)


def test_a_restart_file_carries_the_models_mixing_and_every_history_on(tmp_path):
    """Two types mixed, mindlin_rescale, rolling and twisting, spheres 1 and 2 in contact at the
    restart (step 600 of the LAMMPS case material_two_types_mixed, overlap 8e-4): a run split
    by write_restart / read_restart (which gives back pair granular, its pair_coeff lines and the
    contacts' history) follows the run split in one process bit for bit (a second run's setup forces
    see full-step velocities, as LAMMPS's, so a split run is not the straight one)."""
    from pdps_core.testing import restart_round_trip
    data = (Path(__file__).parent / "data" / "granular" / "material_two_types_mixed.data").read_text()
    (tmp_path / "three.data").write_text(data)
    law = ("damping coeff_restitution tangential mindlin_rescale NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 "
           "twisting marshall")
    straight, resumed = restart_round_trip(tmp_path, f"""\
        units lj
        atom_style sphere
        boundary p p p
        read_data {tmp_path / 'three.data'}
        pair_style granular
        pair_coeff 1 1 hertz/material 1.0e5 0.5 0.3 {law}
        pair_coeff 2 2 hertz/material 3.0e5 0.8 0.2 {law}
        timestep 0.0001
        fix 1 all nve/sphere
        """, 600, 300, split=True, again="fix 1 all nve/sphere")
    assert resumed.pair.coeffs == straight.pair.coeffs and (1, 2) not in resumed.pair.coeffs
    for key in ("x", "v", "omega"):
        got, want = ([getattr(sim.particles, key)[sim.particles.index_of_tag(t)] for t in (1, 2, 3)]
                     for sim in (resumed, straight))
        np.testing.assert_array_equal(got, want)


def test_the_cutoff_keywords_set_the_neighbor_cutoff(tmp_path):
    """pair_coeff's cutoff for its type pair, else pair_style's, else the radii's sum."""
    coeff = "hooke 1e5 0.5 tangential linear_history 1e3 1.0 0.5"
    sim, _ = two_spheres(tmp_path, coeff, 0.0, gap=0.5)
    sim.command("run 0")
    assert sim.pair.init(1)[1, 1] == pytest.approx(1.0)
    sim.command(f"pair_style granular 1.7\npair_coeff * * {coeff}\nrun 0")
    assert sim.pair.init(1)[1, 1] == pytest.approx(1.7)
    sim.command(f"pair_coeff * * {coeff} cutoff 2.5\nrun 0")
    assert sim.pair.init(1)[1, 1] == pytest.approx(2.5)


@pytest.mark.parametrize("normal", ["hertz/material 1.0e5 0.5 0.3 damping coeff_restitution",
                                    "jkr 1.0e5 500.0 0.3 2.0"])
def test_spheres_created_overlapping_separate_under_nve_limit(normal):
    """Two spheres at one point (no normal: no force), two others half inside them: finite forces,
    every pair with a direction pushed out to touching (JKR: held near it by its neck)."""
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"""
        units lj
        atom_style sphere
        boundary p p p
        region box block 0 8 0 8 0 8
        create_box 1 box
        create_atoms 1 single 4.0 4.0 4.0
        create_atoms 1 single 4.0 4.0 4.0
        create_atoms 1 single 4.05 4.0 4.0
        create_atoms 1 single 4.0 4.1 4.02
        set type 1 diameter 1.0
        pair_style granular
        pair_coeff * * {normal} tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting marshall
        timestep 0.0001
        fix 1 all nve/limit 0.001
        run 4000
        """)
    x = sim.particles.x[:4]
    assert np.isfinite(x).all() and np.isfinite(sim.particles.v[:4]).all()
    assert np.isfinite(sim.particles.omega[:4]).all()
    separated = [d for d in (np.linalg.norm(x[i] - x[j]) for i in range(4) for j in range(i + 1, 4)) if d > 1e-9]
    assert len(separated) >= 5 and min(separated) > 0.95


@pytest.mark.parametrize("coeff, expected", [
    ("hooke 2e5 50 damping mass_velocity tangential linear_history 5e4 0.5 0.5", math.pi * math.sqrt(0.5 / 2e5)),
    ("hertz/material 1e5 0.5 0.3 tangential mindlin NULL 1.0 0.5",
     2.868 * (0.5 ** 2 / (0.25 * (1e5 / 1.82) ** 2 * 2.0)) ** 0.2),
])
def test_a_timestep_above_a_tenth_of_the_contact_time_is_warned(tmp_path, coeff, expected):
    """The shortest contact of the lightest spheres meeting at twice the largest speed (pi sqrt(m*/k_n)
    for hooke, Hertz's time of E* for the others; pair gran's advice): a time step above a tenth of it
    is warned, one below is not."""
    for dt, warned in ((expected / 20.0, False), (expected / 5.0, True)):
        sim, _ = two_spheres(tmp_path, coeff, 1.0, dt=dt)
        sim.command("run 0")
        assert sim.pair.timestep_limits(sim)["contact"] == pytest.approx(expected, rel=1e-12)
        assert any("is more than the shortest contact" in w for w in sim.warnings) == warned
