"""Fix ehex: with ``hex`` the energy added per application is exactly F N dt and the momentum kept;
eHEX's position correction is Eq. 20 of Wirnsberger et al. (2015) computed here independently, keeps
the reservoir's centre of mass where it is; bad input is refused in one line; and a LAMMPS run of our
own (an eHEX source and a HEX sink) is reproduced to 10 digits."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, SimulationError
from pdps_core.testing import build, by_tag, lammps_thermo, run_ranks, thermo_rows

X = [[1.0, 1.0, 1.0], [2.1, 1.4, 1.3], [1.3, 2.2, 0.6], [2.0, 2.3, 1.9], [8.0, 8.0, 8.0]]
V = [[0.3, -0.2, 0.1], [-0.5, 0.4, 0.2], [0.1, 0.1, -0.6], [0.7, -0.3, 0.0], [-0.2, 0.5, 0.4]]
MASSES = {1: 1.0, 2: 3.0}
TYPES = [1, 2, 1, 2, 1]
M = np.array([MASSES[t] for t in TYPES])
DT = 0.01


def cluster(tmp_path, fixes):
    """Four Lennard-Jones particles in a cluster and one far away (in no region below), two masses;
    no integrator moves them, so each step's change is the fix's and the forces stay the setup's."""
    return build(tmp_path, X, v=V, types=TYPES, masses=MASSES,
                 setup=f"pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\ntimestep {DT}\n{fixes}")


def state(sim):
    p = sim.particles
    return (by_tag(sim, p.x[:p.nlocal]).copy(), by_tag(sim, p.v[:p.nlocal]).copy(),
            by_tag(sim, p.f[:p.nlocal]).copy())


def ehex_step(x, v, f, m, flux, dt):
    """One eHEX application to all the particles given, written from the paper's Eq. 20."""
    mr = m.sum()
    vr = m @ v / mr
    fr = f.sum(axis=0)
    kr = 0.5 * np.sum(m * np.sum(v * v, axis=1)) - 0.5 * mr * vr @ vr
    sfvr = np.sum(f * (v - vr))
    eta = m[:, None] * flux / (2 * kr) * (v - vr)
    eps = eta / (m[:, None] * kr) * (flux / 48 + sfvr / 6) - flux / (12 * kr) * (f / m[:, None] - fr / mr)
    s = np.sqrt(1 + flux * dt / kr)
    return x - dt ** 3 * eps, s * v - (s - 1) * vr, s


@pytest.mark.parametrize("flux", [3.0, -2.0])
def test_hex_adds_f_n_dt_exactly_and_keeps_the_momentum(tmp_path, flux):
    sim = cluster(tmp_path, f"fix e all ehex 2 {flux} hex")
    x0, v0, _ = state(sim)
    sim.command("run 4")
    x, v, _ = state(sim)
    ke = lambda u: 0.5 * np.sum(M * np.sum(u * u, axis=1))      # noqa: E731
    assert ke(v) == pytest.approx(ke(v0) + 2 * flux * 2 * DT, rel=1e-13)
    assert M @ v == pytest.approx(M @ v0, abs=1e-14)
    assert (x == x0).all()


def test_ehex_corrects_positions_as_eq_20_and_keeps_the_centre_of_mass(tmp_path):
    flux = 5.0
    sim = cluster(tmp_path, "region near block 0 3 0 3 0 3\n"
                            f"fix e all ehex 1 {flux} region near")
    sim.command("run 0")
    x0, v0, f0 = state(sim)
    assert np.abs(f0[:4]).max() > 1.0       # the correction's force term is tested, not 0
    sim.command("run 1")
    x, v, _ = state(sim)
    near = slice(0, 4)
    xe, ve, s = ehex_step(x0[near], v0[near], f0[near], M[near], flux, DT)
    assert x[near] == pytest.approx(xe, rel=1e-14, abs=1e-15)
    assert v[near] == pytest.approx(ve, rel=1e-13)
    assert sim.fix_value("e") == pytest.approx(s, rel=1e-14)
    assert np.abs(x[near] - x0[near]).max() > 1e-9          # the correction moved them
    assert (x[4] == x0[4]).all() and (v[4] == v0[4]).all()   # outside the region
    assert M[near] @ x[near] == pytest.approx(M[near] @ x0[near], rel=0, abs=1e-14)
    ke = lambda u, mm: 0.5 * np.sum(mm * np.sum(u * u, axis=1))      # noqa: E731
    assert ke(v[near], M[near]) == pytest.approx(ke(v0[near], M[near]) + flux * DT, rel=1e-13)


def test_a_particle_past_a_periodic_face_counts_by_its_image_in_the_box(tmp_path):
    """Particle 2 crosses x = 10 in the step (no rebuild wraps it before end_of_step): at 10.04 it is
    in region 0..5 by its image at 0.04, as LAMMPS's remap, so it is scaled with the others."""
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [9.99, 1.0, 1.0], [3.0, 1.0, 1.0]],
                v=[[0.3, 0.1, 0.0], [5.0, 0.0, 0.0], [-0.2, 0.0, 0.1]],
                setup="timestep 0.01\nfix 1 all nve\nregion low block 0 5 INF INF INF INF\n"
                      "fix e all ehex 1 1.0 region low hex")
    sim.command("run 1")
    x, v = by_tag(sim, sim.particles.x[:3]), by_tag(sim, sim.particles.v[:3])
    assert x[1, 0] == pytest.approx(10.04, rel=1e-14)
    assert v[1, 0] != 5.0
    assert 0.5 * np.sum(v * v) == pytest.approx(0.5 * (0.3 ** 2 + 0.1 ** 2 + 5.0 ** 2 + 0.2 ** 2 + 0.1 ** 2) + 0.01,
                                                rel=1e-13)


def test_a_sink_larger_than_the_thermal_energy_stops_the_run(tmp_path):
    sim = cluster(tmp_path, "fix e all ehex 1 -1000.0")
    with pytest.raises(SimulationError, match=r"^<command>:1: run: fix e ehex at step 1: the kinetic energy went "
                                              r"negative \(removing 10 from a thermal kinetic energy of "):
        sim.command("run 1")


@pytest.mark.parametrize("line, message", [
    ("fix e all ehex 0 1.0", "fix: every must be >= 1 (got 0)"),
    ("fix e all ehex 1", "fix: missing argument flux; usage: fix ID GROUP ehex N F [region RID] [hex]"),
    ("fix e all ehex 1 1.0 region nowhere", "fix: fix e ehex: region nowhere is not defined"),
    ("fix e all ehex 1 1.0 constrain", "fix: keyword constrain of fix ehex: it applies fix shake's or rattle's "
                                       "constraints after the scaling, and pdps has neither (LAMMPS refuses it "
                                       "without one)"),
    ("fix e all ehex 1 1.0 com", "fix: keyword com of fix ehex: it applies fix shake's or rattle's "
                                 "constraints after the scaling, and pdps has neither (LAMMPS refuses it "
                                 "without one)"),
    ("fix e all ehex 1 v_q", "fix: flux must be a finite number (got v_q)"),
    ("fix e all ehex 1 inf", "fix: flux must be a finite number (got inf)"),
])
def test_bad_arguments_are_refused_with_one_line(tmp_path, line, message):
    sim = cluster(tmp_path, "")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value) == f"<command>:1: {message}"


# LAMMPS 22 Jul 2025 on this machine, this script (ours), thermo_modify format float %22.16g:
#   step temp etotal c_Thot c_Tcold f_hot f_cold
LAMMPS_EHEX = {
    0: (1.200000000000001, -4.976883678254707, 1.230016263924002, 1.34684259883633, 1, 1),
    50: (0.6181326852601886, -4.986025216038873, 0.6742098575585915, 0.6142441079597764, 1.000020474540267,
         0.9999565809560986),
    100: (0.654626578988828, -4.985688351256769, 0.6533319156276982, 0.642242486916788, 1.000022056121049,
          0.9999539939589217),
    150: (0.6216672220122953, -4.986043523798871, 0.6054195287980721, 0.548267046842614, 1.000020753942153,
          0.9999412847723443),
    200: (0.6354118315182686, -4.984823718689177, 0.5986254400131191, 0.6870501531612008, 1.000020774168001,
          0.9999610447135665),
}

EHEX_SCRIPT = """
units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 8
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.2 4928459 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
neighbor 0.3 bin
neigh_modify delay 0 every 1 check yes
timestep 0.005
region hot block INF INF INF INF 0 1
region cold block INF INF INF INF 4 5
compute Thot all temp/region hot
compute Tcold all temp/region cold
fix 1 all nve
fix hot all ehex 1 0.5 region hot
fix cold all ehex 2 -0.5 region cold hex
thermo_style custom step temp etotal c_Thot c_Tcold f_hot f_cold
thermo 50
run 200
"""


def test_a_lammps_ehex_source_and_hex_sink_are_reproduced_to_10_digits(tmp_path, monkeypatch):
    _, rows = lammps_thermo(tmp_path, monkeypatch, EHEX_SCRIPT)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_EHEX)
    for row in rows:
        assert [float(v) for v in row[1:]] == pytest.approx(LAMMPS_EHEX[int(row[0])], rel=1e-10), row[0]


def test_two_ranks_give_lammps_figures_too(tmp_path):
    """The reservoir's sums run over both ranks' particles."""
    script = EHEX_SCRIPT.replace("thermo 50", "thermo 50\nthermo_modify format float %22.16g")
    rows = thermo_rows(run_ranks(script, 2, tmp_path, dialect="lammps").stdout)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_EHEX)
    for row in rows:
        assert row[1:] == pytest.approx(LAMMPS_EHEX[int(row[0])], rel=1e-10), row[0]
