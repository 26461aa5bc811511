"""variable atomfile: per-particle values read from a file, set after set with next, read wherever
an atom-style variable is. LAMMPS 22 Jul 2025 printed ATOMFILE_LAMMPS on this machine for ATOMFILE
(thermo norm yes in lj units: the reduce sums over 4 particles are divided by 4)."""

import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import thermo_rows

VALUES = """# two sets of per-atom values
3
1 1.5
3 -2.0
4 0.25
# second set
2
2 10
4 20
"""
ATOMFILE = """units lj
atom_style atomic
atom_modify map array
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 single 0.5 0.5 0.5
create_atoms 1 single 1.5 0.5 0.5
create_atoms 1 single 2.5 0.5 0.5
create_atoms 1 single 3.5 0.5 0.5
mass 1 1.0
variable a atomfile values.txt
variable twice atom 2*v_a
compute total all reduce sum v_a v_twice
variable third equal v_a[3]
thermo_style custom step c_total[1] c_total[2] v_third
run 0
next a
run 0
"""
ATOMFILE_LAMMPS = [[0, -0.0625, -0.125, -2], [0, 7.5, 15, 0]]


def test_atomfile_values_set_after_set_as_lammps(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "values.txt").write_text(VALUES)
    sim = Simulation(screen=False, log="log.case", dialect="lammps")
    sim.command(ATOMFILE)
    sim.close()
    assert thermo_rows((tmp_path / "log.case").read_text()) == ATOMFILE_LAMMPS


@pytest.mark.parametrize("text, message", [
    ("2\n1 1.0\n", "variable a atomfile: values.txt: 2 lines 'ID value' expected after line 1 of its values"),
    ("one\n1 1.0\n", "variable a atomfile: values.txt: expected a count of lines, got one"),
    ("1\n1.5 2.0\n", "variable a atomfile: values.txt: IDs must be integers and values numbers"),
    ("# nothing\n", "variable a atomfile: values.txt holds no values"),
])
def test_broken_atomfiles_are_refused(tmp_path, monkeypatch, text, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "values.txt").write_text(text)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    with pytest.raises(ScriptError) as caught:
        sim.command("variable a atomfile values.txt")
    assert caught.value.message == message
