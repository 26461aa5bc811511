"""fix_modify ID temp CID on fix langevin, as LAMMPS's: friction and noise act on the velocities
about the compute's bias (temp/region: only the particles inside the region; temp/partial: only the
chosen components); a compute without a bias changes nothing; bad names are refused in one line;
and LAMMPS's thermo of a region thermostat (and then a partial one) with tally yes at T = 0 is
reproduced to 10 digits."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import by_tag, lammps_thermo

SETUP = """
units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 6
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.5 4928459 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
timestep 0.005
region hot block INF INF INF INF 0 2
compute Thot all temp/region hot
compute tp all temp/partial 1 0 1
compute plain all temp
"""


def setup_forces(make_sim, fixes):
    sim = make_sim(dialect="lammps")
    sim.command(SETUP + fixes + "\nrun 0")
    p = sim.particles
    return sim, by_tag(sim, p.f[:p.nlocal]).copy(), by_tag(sim, p.x[:p.nlocal]).copy()


@pytest.mark.parametrize("temperature", [1.0, 0.0])
def test_a_region_temperature_thermostats_only_the_particles_inside_it(make_sim, temperature):
    _, pair, x = setup_forces(make_sim, "")
    sim, thermostatted, _ = setup_forces(make_sim, f"fix l all langevin {temperature} {temperature} 0.5 1234\n"
                                                   "fix_modify l temp Thot")
    inside = np.asarray(sim.region("hot").match(x), dtype=bool)
    assert 0 < inside.sum() < len(inside)
    assert (thermostatted[~inside] == pair[~inside]).all()
    assert (thermostatted[inside] != pair[inside]).all()


def test_a_partial_temperature_thermostats_only_its_components(make_sim):
    _, pair, _ = setup_forces(make_sim, "")
    _, thermostatted, _ = setup_forces(make_sim, "fix l all langevin 1.0 1.0 0.5 1234\nfix_modify l temp tp")
    assert (thermostatted[:, 1] == pair[:, 1]).all()
    assert (thermostatted[:, [0, 2]] != pair[:, [0, 2]]).all()


def test_a_temperature_without_a_bias_changes_nothing(make_sim):
    _, named, _ = setup_forces(make_sim, "fix l all langevin 1.0 1.0 0.5 1234\nfix_modify l temp plain")
    _, unnamed, _ = setup_forces(make_sim, "fix l all langevin 1.0 1.0 0.5 1234")
    assert (named == unnamed).all()


@pytest.mark.parametrize("line, message", [
    ("fix_modify l temp nothere", "fix_modify: compute nothere is not defined (temperature of fix l)"),
])
def test_a_missing_compute_is_refused_with_one_line(make_sim, line, message):
    sim = make_sim(dialect="lammps")
    sim.command(SETUP + "fix l all langevin 1.0 1.0 0.5 1234")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value) == f"<command>:1: {message}"


def test_a_compute_that_is_no_temperature_and_gjf_with_a_bias_are_refused(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command(SETUP + "compute pe all pe\nfix l all langevin 1.0 1.0 0.5 1234 gjf vhalf\nfix 1 all nve")
    with pytest.raises(ScriptError, match=r"^<command>:1: fix_modify: compute pe \(pe\) is not a temp compute, so it "
                                          r"gives no temperature$"):
        sim.command("fix_modify l temp pe")
    with pytest.raises(ScriptError, match=r"^<command>:1: fix_modify: fix l langevin gjf with a temperature that has "
                                          r"a bias \(Thot, temp/region\) is not supported; use gjf no$"):
        sim.command("fix_modify l temp Thot")


def test_a_temperature_of_another_group_is_warned_of(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(SETUP + "group low region hot\nfix l low langevin 1.0 1.0 0.5 1234\nfix_modify l temp Thot")
    sim.close()
    assert ("WARNING: fix l langevin: temperature compute Thot is of group all, not the fix's low "
            "(LAMMPS's fix_modify warns so too)") in (tmp_path / "log.case").read_text()


def test_an_uncomputed_temperature_is_refused_when_the_run_starts(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command(SETUP + "fix l all langevin 1.0 1.0 0.5 1234\nfix_modify l temp Thot\nfix 1 all nve\nuncompute Thot")
    with pytest.raises(ScriptError, match=r"^<command>:1: run: fix l: its temperature compute Thot is not defined$"):
        sim.command("run 1")


# LAMMPS 22 Jul 2025 on this machine, this script (ours), thermo_modify format float %22.16g: at
# T = 0 the thermostat is friction alone, so the run is deterministic.
#   step temp c_Thot pe etotal f_hot
LAMMPS_LANGEVIN_TEMP = [
    (0, 1.5, 1.54763353591389, -6.773368053253967, -4.529227428253966, 0.0),
    (50, 0.6750951837364766, 0.4929059735798248, -5.880419592834056, -4.870413907790812, 0.3331861268589388),
    (100, 0.5855350203702813, 0.3863662834787513, -5.971850532054667, -5.095835247672566, 0.5597428169162556),
    (150, 0.5187777517772842, 0.3074817561808447, -6.074837932001941, -5.298697779928895, 0.7623891640356493),
    (200, 0.4507145303893809, 0.2424304385324023, -6.157025043733459, -5.48271385178372, 0.9430502075956565),
    (200, 0.450714530389381, 0.2424304385324023, -6.157025043733456, -5.482713851783718, 0.0),
    (250, 0.3062822213334802, 0.2495535809483689, -6.294628579548713, -5.836401662475577, 0.3536717263053911),
    (300, 0.2346149844299333, 0.1887398795964693, -6.420893241815705, -6.069887229953734, 0.5864418339522887),
]

SCRIPT = SETUP + """
neighbor 0.3 bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve
fix hot all langevin 0.0 0.0 0.5 59804 tally yes
fix_modify hot temp Thot
thermo_style custom step temp c_Thot pe etotal f_hot
thermo 50
run 200
fix_modify hot temp tp
run 100
"""


def test_lammps_region_then_partial_thermostat_with_its_tally_is_reproduced_to_10_digits(tmp_path, monkeypatch):
    _, rows = lammps_thermo(tmp_path, monkeypatch, SCRIPT)
    assert [int(row[0]) for row in rows] == [row[0] for row in LAMMPS_LANGEVIN_TEMP]
    for row, reference in zip(rows, LAMMPS_LANGEVIN_TEMP):
        assert [float(v) for v in row[1:]] == pytest.approx(reference[1:], rel=1e-10, abs=1e-14), row[0]
    assert np.isfinite([float(v) for row in rows for v in row]).all()
