"""Fix heat: the energy added per application is exactly EFLUX N dt and the momentum of the scaled
particles is unchanged (against the formula), only the region's particles are touched, bad input is
refused in one line, and a LAMMPS run of our own (a source and a variable sink) is reproduced to 10
digits."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, SimulationError
from pdps_core.testing import build, by_tag, lammps_thermo, run_ranks, thermo_rows

X = [[1.0, 1.0, 1.0], [3.0, 2.0, 1.5], [6.0, 5.0, 4.0], [8.0, 7.5, 6.0], [2.5, 8.0, 3.0]]
V = [[0.3, -0.2, 0.1], [-0.5, 0.4, 0.2], [0.1, 0.1, -0.6], [0.7, -0.3, 0.0], [-0.2, 0.5, 0.4]]
MASSES = {1: 1.0, 2: 3.0}
TYPES = [1, 2, 1, 2, 1]


def kinetic(sim, rows=slice(None)):
    m = np.array([MASSES[t] for t in TYPES])[rows]
    v = by_tag(sim, sim.particles.v[:sim.particles.nlocal])[rows]
    return 0.5 * float(np.sum(m * np.sum(v * v, axis=1))), m @ v


def free_particles(tmp_path, fixes):
    """Five particles of two masses and no forces; no integrator moves them, so each step's change is
    the fix's."""
    return build(tmp_path, X, v=V, types=TYPES, masses=MASSES, setup=f"timestep 0.01\n{fixes}")


@pytest.mark.parametrize("flux", [2.5, -1.5])
def test_each_application_adds_eflux_n_dt_and_keeps_the_momentum(tmp_path, flux):
    sim = free_particles(tmp_path, f"fix h all heat 2 {flux}")
    ke0, p0 = kinetic(sim)
    sim.command("run 1")
    assert kinetic(sim)[0] == ke0 and sim.fix_value("h") == 1.0     # step 1 is not a multiple of 2
    sim.command("run 5")
    ke, p = kinetic(sim)
    # steps 2, 4 and 6: three applications of EFLUX * 2 * dt
    assert ke == pytest.approx(ke0 + 3 * flux * 2 * 0.01, rel=1e-13)
    assert p == pytest.approx(p0, abs=1e-14)
    # the last factor: s^2 = (K + Q - K_cm) / (K - K_cm) with K of the step before
    m = np.array([MASSES[t] for t in TYPES])
    k_cm = 0.5 * float(p0 @ p0) / m.sum()
    expected = np.sqrt((ke - k_cm) / (ke - flux * 0.02 - k_cm))
    assert sim.fix_value("h") == pytest.approx(expected, rel=1e-13)


def test_a_region_limits_the_exchange_to_the_particles_inside_it(tmp_path):
    sim = free_particles(tmp_path, "region low block 0 5 INF INF INF INF\nfix h all heat 1 1.0 region low")
    inside, outside = [0, 1, 4], [2, 3]
    v0 = by_tag(sim, sim.particles.v[:5]).copy()
    ke0, p0 = kinetic(sim, inside)
    sim.command("run 3")
    v = by_tag(sim, sim.particles.v[:5])
    assert (v[outside] == v0[outside]).all()
    ke, p = kinetic(sim, inside)
    assert ke == pytest.approx(ke0 + 3 * 1.0 * 0.01, rel=1e-13)
    assert p == pytest.approx(p0, abs=1e-14)
    # each velocity relative to the centre of mass is scaled by one factor
    m = np.array([MASSES[t] for t in TYPES])[inside]
    vcm = p0 / m.sum()
    ratio = (v[inside] - vcm) / (v0[inside] - vcm)
    assert ratio == pytest.approx(np.full((3, 3), ratio[0, 0]), rel=1e-12)


def test_an_equal_style_variable_flux_is_read_at_each_application(tmp_path):
    sim = free_particles(tmp_path, "variable q equal 0.5*step\nfix h all heat 1 v_q")
    ke0, _ = kinetic(sim)
    sim.command("run 4")
    assert kinetic(sim)[0] == pytest.approx(ke0 + 0.5 * (1 + 2 + 3 + 4) * 0.01, rel=1e-13)


def test_a_sink_larger_than_the_thermal_energy_stops_the_run(tmp_path):
    sim = free_particles(tmp_path, "fix h all heat 1 -1000.0")
    with pytest.raises(SimulationError, match=r"fix h heat at step 1: the kinetic energy went negative \(removing 10 "
                                              r"from a thermal kinetic energy of 1\.95333; LAMMPS's 'Fix heat kinetic "
                                              r"energy went negative'\)$"):
        sim.command("run 1")


def test_a_region_with_no_particles_stops_the_run(tmp_path):
    sim = free_particles(tmp_path, "region far block 9 10 9 10 9 10\nfix h all heat 1 1.0 region far")
    with pytest.raises(SimulationError, match=r"fix h heat at step 1: no particles of group all inside region far "
                                              r"to exchange heat with$"):
        sim.command("run 1")


@pytest.mark.parametrize("line, message", [
    ("fix h all heat 0 1.0", "fix: every must be >= 1 (got 0)"),
    ("fix h all heat 1", "fix: missing argument eflux; usage: fix ID GROUP heat N EFLUX [region RID]"),
    ("fix h all heat 1 1.0 region nowhere", "fix: fix h heat: region nowhere is not defined"),
    ("fix h all heat 1 1.0 units box", "fix: unknown keyword units (known: region)"),
    ("fix h all heat 1 nan", "fix: eflux must be a finite number or v_NAME (got nan)"),
])
def test_bad_arguments_are_refused_with_one_line(tmp_path, line, message):
    sim = free_particles(tmp_path, "")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value) == f"<command>:1: {message}"


def test_a_string_flux_and_an_undefined_variable_are_refused_when_the_run_starts(tmp_path):
    sim = free_particles(tmp_path, "variable a string hot\nfix h all heat 1 v_a")
    with pytest.raises(ScriptError, match=r"^<command>:1: run: fix h heat: EFLUX v_a is a string-style variable; give "
                                          r"an equal-style or atom-style one \(LAMMPS's 'Variable for fix heat is "
                                          r"invalid style'\)$"):
        sim.command("run 1")
    sim = free_particles(tmp_path, "fix h all heat 1 v_missing")
    with pytest.raises(ScriptError, match=r"^<command>:1: run: fix h heat: variable missing is not defined$"):
        sim.command("run 1")


def test_an_atom_style_flux_scales_each_particle_by_its_own_factor_and_keeps_the_momentum(tmp_path):
    sim = free_particles(tmp_path, "variable q atom 2.0*x\nfix h all heat 1 v_q")
    x, v0 = np.array(X), np.array(V)
    m = np.array([MASSES[t] for t in TYPES])
    ke = 0.5 * float(np.sum(m * np.sum(v0 * v0, axis=1)))
    drift = 0.5 * float((m @ v0) @ (m @ v0)) / m.sum()
    s = np.sqrt((ke + 2.0 * x[:, 0] * 0.01 - drift) / (ke - drift))
    expected = s[:, None] * v0 - ((s - 1.0)[:, None] * v0 * m[:, None]).sum(axis=0) / m.sum()
    sim.command("run 1")
    v = by_tag(sim, sim.particles.v[:5])
    assert v == pytest.approx(expected, rel=1e-13)
    assert m @ v == pytest.approx(m @ v0, abs=1e-14)
    assert sim.fix_value("h") == pytest.approx(s.mean(), rel=1e-14)


def test_a_uniform_atom_style_flux_is_the_equal_style_one(tmp_path):
    equal = free_particles(tmp_path, "fix h all heat 1 2.5")
    atom = free_particles(tmp_path, "variable q atom 2.5\nfix h all heat 1 v_q")
    equal.command("run 3")
    atom.command("run 3")
    assert by_tag(atom, atom.particles.v[:5]) == pytest.approx(by_tag(equal, equal.particles.v[:5]), rel=1e-14)


def test_an_atom_style_sink_larger_than_the_thermal_energy_stops_the_run(tmp_path):
    sim = free_particles(tmp_path, "variable q atom -1000*(x>5)\nfix h all heat 1 v_q")
    with pytest.raises(SimulationError, match=r"fix h heat at step 1: the kinetic energy of a particle went negative"):
        sim.command("run 1")


# LAMMPS 22 Jul 2025 on this machine, this script (ours), thermo_modify format float %22.16g: EFLUX
# atom-style in a region (every step) and in the whole box (every 2 steps).
#   step temp etotal c_Thot c_Tcold f_hot f_cold
LAMMPS_HEAT_ATOM = {
    0: (1.200000000000001, -4.976883678254707, 1.230016263924002, 1.34684259883633, 1, 1),
    50: (0.618131737977394, -4.986016736246104, 0.6736444503316347, 0.6148063343082361, 1.00000124659654,
         0.9999998421169499),
    100: (0.6546280776029199, -4.985671177778688, 0.6526286064042993, 0.6430530701015925, 1.000001315457056,
          0.9999998503352586),
    150: (0.6216841398981289, -4.986013091811913, 0.6043027198473875, 0.5493979654811295, 1.000001201650911,
          0.9999998424043092),
    200: (0.6355302960583292, -4.984849382566659, 0.5978724756834856, 0.6886447567004227, 1.000001263098704,
          0.9999998454368698),
}


# LAMMPS 22 Jul 2025 on this machine, this script (ours), thermo_modify format float %22.16g:
#   step temp etotal c_Thot c_Tcold f_hot f_cold
LAMMPS_HEAT = {
    0: (1.200000000000001, -4.976883678254707, 1.230016263924002, 1.34684259883633, 1, 1),
    50: (0.6181273195113631, -4.986037688234173, 0.6742103123668711, 0.6142081392409812, 1.000020847926289,
         0.999952236538373),
    100: (0.6546066720459051, -4.985737543127758, 0.6533307145550845, 0.6421240689772163, 1.000022056177974,
          0.9999447832799729),
    150: (0.621630108054876, -4.986154087659286, 0.605416192711287, 0.5480538261550423, 1.000020754043544,
          0.9999236405244891),
    200: (0.6353294840012649, -4.985022165237385, 0.5986123506200297, 0.6866808385573899, 1.000021301232737,
          0.9999454342108657),
}

HEAT_SCRIPT = """
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
variable flux equal -0.5-0.001*step
fix 1 all nve
fix hot all heat 1 0.5 region hot
fix cold all heat 2 v_flux region cold
thermo_style custom step temp etotal c_Thot c_Tcold f_hot f_cold
thermo 50
run 200
"""


def test_a_lammps_source_and_variable_sink_are_reproduced_to_10_digits(tmp_path, monkeypatch):
    _, rows = lammps_thermo(tmp_path, monkeypatch, HEAT_SCRIPT)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_HEAT)
    for row in rows:
        assert [float(v) for v in row[1:]] == pytest.approx(LAMMPS_HEAT[int(row[0])], rel=1e-10), row[0]


def test_two_ranks_give_lammps_figures_too(tmp_path):
    """The reservoir's sums run over both ranks' particles."""
    script = HEAT_SCRIPT.replace("thermo 50", "thermo 50\nthermo_modify format float %22.16g")
    rows = thermo_rows(run_ranks(script, 2, tmp_path, dialect="lammps").stdout)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_HEAT)
    for row in rows:
        assert row[1:] == pytest.approx(LAMMPS_HEAT[int(row[0])], rel=1e-10), row[0]


def test_a_lammps_run_with_atom_style_fluxes_is_reproduced_to_10_digits(tmp_path, monkeypatch):
    script = HEAT_SCRIPT.replace("variable flux equal -0.5-0.001*step\n",
                                 "variable q atom 0.02*(1+x/lx)\nvariable s atom -0.01*(1+y/ly)\n")
    script = script.replace("fix hot all heat 1 0.5 region hot\nfix cold all heat 2 v_flux region cold",
                            "fix hot all heat 1 v_q region hot\nfix cold all heat 2 v_s")
    _, rows = lammps_thermo(tmp_path, monkeypatch, script)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_HEAT_ATOM)
    for row in rows:
        assert [float(v) for v in row[1:]] == pytest.approx(LAMMPS_HEAT_ATOM[int(row[0])], rel=1e-10), row[0]
