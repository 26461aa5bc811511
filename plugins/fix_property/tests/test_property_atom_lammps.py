"""LAMMPS's fix property/atom (i_NAME, d_NAME), defined before the box and filled by read_data's
fix ID NULL SECTION, read by fix rigid custom i_NAME: three rigid bodies whose ids come from a data
file section. LAMMPS 22 Jul 2025 printed CLUMPS_LAMMPS on this machine for CLUMPS."""

import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.script.dialect import detect
from pdps_core.testing import thermo_rows

DATA = """LAMMPS data file for three rigid bodies

9 atoms
1 atom types

-6 6 xlo xhi
-6 6 ylo yhi
-6 6 zlo zhi

Masses

1 1.0

Atoms # atomic

1 1 -3 0 0
2 1 -2.0 0 0
3 1 -3 1.0 0
4 1 0 2.2 0.5
5 1 1.0 2.2 0.5
6 1 0 3.2 0.5
7 1 3 -0.4 -0.6
8 1 4.0 -0.4 -0.6
9 1 3 0.6 -0.6

Clumps

1 1
2 1
3 1
4 2
5 2
6 2
7 3
8 3
9 3
"""
CLUMPS = """units lj
atom_style atomic
atom_modify map array
pair_style lj/cut 2.5
fix 0 all property/atom i_clump
read_data data.clumps fix 0 NULL Clumps
pair_coeff * * 1.0 1.0
velocity all create 2.0 4928459 loop geom
fix 1 all rigid custom i_clump
variable xb equal xcm(all,x)
thermo_style custom step temp pe etotal press f_1
thermo 100
run 500
"""
# step temp pe etotal press f_1
CLUMPS_LAMMPS = [
    [0, 1.4678289, -0.14583333, 1.0773574, -0.50702678, 1.2231907],
    [100, 1.4678293, -0.14583333, 1.0773577, 0.0016549804, 1.223191],
    [200, 1.4678294, -0.14583333, 1.0773578, 0.0016549929, 1.2231911],
    [300, 1.4678297, -0.14583333, 1.077358, 0.0016549419, 1.2231914],
    [400, 1.4683938, -0.14812928, 1.0755322, 0.0016350246, 1.2236615],
    [500, 1.4732485, -0.15398008, 1.073727, 0.0015820298, 1.2277071],
]


@pytest.fixture
def folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "data.clumps").write_text(DATA)
    return tmp_path


def test_bodies_from_a_data_section_move_as_lammps(folder):
    assert detect(CLUMPS, "in.clumps")[0].name == "lammps"
    sim = Simulation(screen=False, log="log.case", dialect="lammps")
    sim.command(CLUMPS)
    sim.close()
    rows = thermo_rows((folder / "log.case").read_text())
    assert len(rows) == len(CLUMPS_LAMMPS)
    for got, want in zip(rows, CLUMPS_LAMMPS):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-12), want[0]


def test_the_section_fills_the_property(folder):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(CLUMPS.split("pair_coeff")[0])
    clump = sim.particles.arrays["clump"][:sim.nlocal]
    assert dict(zip(sim.tag.tolist(), clump.tolist())) == {k: (k - 1) // 3 + 1 for k in range(1, 10)}


def test_mol_gives_the_particles_molecule_ids():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style sphere\nfix 0 all property/atom mol ghost yes\nregion b block 0 4 0 4 0 4\n"
                "create_box 1 b\ncreate_atoms 1 single 1 1 1\ncreate_atoms 1 single 2 2 2\nset atom 2 mol 7\n"
                "group seven molecule 7")
    assert sim.particles.molecule[:2].tolist() == [0, 7]
    assert sim.groups.select(sim, "seven").tolist() == [False, True]
    with pytest.raises(ScriptError) as caught:
        sim.command("fix 1 all property/atom mol")
    assert str(caught.value) == ("<command>:1: fix: mol: the particles already have molecule ids (LAMMPS: Fix "
                                 "property/atom mol when atom_style already has molecule attribute)")


@pytest.mark.parametrize("lines, message", [
    ("fix 0 all property/atom q", "<command>:3: fix: q: pdps's fix property/atom makes i_NAME and d_NAME values; for q "
                                  "choose an atom_style that has it"),
    ("fix 0 all property/atom mol mol", "<command>:3: fix: mol: named twice"),
    ("fix 0 all property/atom clump", "<command>:3: fix: clump: expected i_NAME or d_NAME"),
    ("fix 0 all property/atom i_a d_a", "<command>:3: fix: d_a: named twice"),
    ("fix 0 all property/atom i_clump\nread_data data.clumps fix 0 NULL Bodies",
     "<command>:4: read_data: fix 0: section Bodies is one of read_data's own sections (LAMMPS refuses it too): name the "
     "fix's section otherwise"),
    ("fix 0 all property/atom i_clump\nread_data data.clumps fix 0 NULL Other",
     "<command>:4: read_data: {folder}/data.clumps:26: unsupported section Clumps (sections read: Masses, Atoms, "
     "Velocities)"),
    ("fix 0 all property/atom d_a d_b\nread_data data.clumps fix 0 NULL Clumps",
     "<command>:4: read_data: data.clumps: line 28 of section Clumps: expected ID and 2 value(s) (got 1 1)"),
    ("read_data data.clumps add merge", "<command>:3: read_data: read_data keyword add is not supported; usage: read_data FILE "
                                        "[fix ID NULL SECTION ...]"),
])
def test_bad_properties_are_refused(folder, lines, message):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    with pytest.raises(ScriptError) as caught:
        sim.command("units lj\natom_style atomic\n" + lines)
    assert str(caught.value) == message.format(folder=folder)
