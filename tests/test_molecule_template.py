"""The molecule command: LAMMPS's molecule file read into a template (pdps_core/state/molecule.py),
its lines as LAMMPS 22 Jul 2025 prints them for the same file (recorded on this machine 2026-12-08),
what the template derives, and one line for each bad file or refused keyword."""

import io
import re

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

TRI = """# three spheres in a bent row

3 atoms

Coords

1 0.0 0.0 0.0
2 1.0 0.0 0.0
3 1.5 0.9 0.3

Types

1 1
2 2
3 1

Diameters

1 1.0
2 0.8
3 1.2

Masses

1 0.5
2 0.3
3 0.9
"""

# LAMMPS's lines after "molecule tri tri.mol"
LAMMPS_LINES = """Read molecule template tri:
# three spheres in a bent row
  1 molecules
  0 fragments
  0 bodies
  3 atoms with max type 2
  0 bonds with max type 0
  0 angles with max type 0
  0 dihedrals with max type 0
  0 impropers with max type 0"""

HEADER = """LAMMPS data file created for rigid body molecule template

2 atoms

2.5 mass

0.4 0 0 com

0.1 1.2 1.3 0.01 0.02 0.03 inertia

Coords

1 0 0 0
2 1 0 0

Types

1 1
2 1
"""


def define(tmp_path, text, line="molecule m {path}", name="m.mol"):
    path = tmp_path / name
    path.write_text(text)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command("units lj\natom_style sphere\n" + line.format(path=path))
    return sim, screen.getvalue()


def test_the_file_reads_as_lammps_prints_it(tmp_path):
    sim, printed = define(tmp_path, TRI, "molecule tri {path}")
    assert LAMMPS_LINES in printed
    template = sim.molecule_template("tri")
    assert (template.natoms, template.ntypes) == (3, 2)
    assert template.types.tolist() == [1, 2, 1]
    np.testing.assert_array_equal(template.radius, [0.5, 0.4, 0.6])
    centre = np.array([2.5, 0.9, 0.3]) / 3
    np.testing.assert_allclose(template.center, centre, rtol=1e-15)
    # the surface farthest from the centre: the third sphere's
    reach = max(np.linalg.norm(x - centre) + r for x, r in zip(template.coords, template.radius))
    assert template.molradius == pytest.approx(reach, rel=1e-15)
    total, com, tensor = template.mass_properties(np.full(3, np.nan))
    m = np.array([0.5, 0.3, 0.9])
    assert total == pytest.approx(1.7, rel=1e-15)
    np.testing.assert_allclose(com, (m[:, None] * template.coords).sum(axis=0) / 1.7, rtol=1e-15)
    d = template.coords - com
    ixx = (m * (d[:, 1] ** 2 + d[:, 2] ** 2)).sum() + (0.4 * m * template.radius ** 2).sum()
    ixy = -(m * d[:, 0] * d[:, 1]).sum()
    assert tensor[0] == pytest.approx(ixx, rel=1e-14) and tensor[5] == pytest.approx(ixy, rel=1e-14)


def test_the_header_s_mass_com_and_inertia_stand(tmp_path):
    sim, _ = define(tmp_path, HEADER)
    total, com, tensor = sim.molecule_template("m").mass_properties(np.array([np.nan, 1.0]))
    assert total == 2.5
    assert com.tolist() == [0.4, 0.0, 0.0]
    # xx yy zz, then yz xz xy: the order LAMMPS 22 Jul 2025 uses them in
    assert tensor.tolist() == [0.1, 1.2, 1.3, 0.01, 0.02, 0.03]
    assert sim.molecule_template("m").radius is None


def test_masses_of_types_when_the_file_has_none(tmp_path):
    sim, _ = define(tmp_path, HEADER.replace("2.5 mass\n", ""))
    total, _, _ = sim.molecule_template("m").mass_properties(np.array([np.nan, 1.5]))
    assert total == 3.0
    with pytest.raises(ScriptError, match="molecule m: a type of its atoms has no mass"):
        sim.molecule_template("m").masses(np.array([np.nan, np.nan]))


@pytest.mark.parametrize("text, message", [
    (TRI.replace("3 atoms", "0 atoms"), "m.mol: the header must give 'N atoms' with N >= 1"),
    (TRI.replace("3 atoms", "3 atoms\n1 bonds"), "m.mol:4: 1 bonds: pdps's molecule templates carry no bonds"),
    (TRI.replace("3 atoms", "three atoms"), "m.mol:3: the number of atoms must be a whole number (got three)"),
    (TRI.replace("Coords", "Coordinates"), "m.mol:5: unknown section or header line 'Coordinates' (sections: Coords, "
     "Types, Diameters, Masses, Molecules)"),
    (TRI.replace("Masses", "Charges"), "m.mol:23: section Charges: pdps's molecule templates carry no charges"),
    (TRI + "\nBonds\n\n1 1 1 2\n", "m.mol:29: section Bonds: pdps's molecule templates carry no bonds"),
    (TRI.replace("2 1.0 0.0 0.0", "1 1.0 0.0 0.0"), "m.mol:8: atom 1 given twice in section Coords"),
    (TRI.replace("3 1.5 0.9 0.3", "4 1.5 0.9 0.3"), "m.mol:9: atom index 4 in section Coords is beyond the 3 atoms"),
    (TRI.replace("3 1.5 0.9 0.3", "3 1.5 0.9"), "m.mol:9: section Coords takes ID and 3 value(s) per line (got 3 1.5 0.9)"),
    (TRI.replace("3 1.5 0.9 0.3", "3 1.5 nan 0.3"), "m.mol:9: Coords must be finite (got nan)"),
    (TRI.replace("3 1.5 0.9 0.3", "3 1.5 1e300 0.3"), "m.mol:9: Coords must lie within +-1e+100 (got 1e300)"),
    (TRI.replace("3 atoms", "99999999999 atoms"), "m.mol: the header gives 99999999999 atoms, more than the file's 27 "
     "lines can list"),
    (TRI.replace("2 0.8", "2 -0.8"), "m.mol:20: Diameters: each diameter must be >= 0"),
    (TRI.replace("3 0.9\n", "3 0\n"), "m.mol:27: Masses: each mass must be > 0"),
    (TRI.replace("3 1\n\nDiam", "3 0\n\nDiam"), "m.mol:15: Types: each type must be a whole number >= 1"),
    (TRI.split("Types")[0], "m.mol: no Types section (a template needs its atoms' types)"),
    (TRI.replace("3 1.5 0.9 0.3\n", ""), "m.mol:10: section Coords takes ID and 3 value(s) per line (got Types)"),
    (TRI.split("Diameters")[0].replace("3 1\n", ""), "m.mol: section Types ends after 2 of 3 atoms"),
    (HEADER.replace("2.5 mass", "-1 mass"), "m.mol: mass must be > 0 (got -1)"),
    (TRI.replace("3 1\n\nDiam", "3 1\n\nMolecules\n\n1 1\n2 1\n3 2\n\nDiam"), "m.mol:21: Molecules: the template holds 2 "
     "molecules; pdps's templates are one molecule each"),
])
def test_a_bad_file_gets_one_line(tmp_path, text, message):
    with pytest.raises(ScriptError) as caught:
        define(tmp_path, text, "molecule m m.mol".replace("m.mol", "{path}"))
    text = re.sub(r"^<command>:\d+: molecule: ", "", str(caught.value))
    assert text.replace(str(tmp_path / "m.mol"), "m.mol") == message


@pytest.mark.parametrize("line, message", [
    ("molecule m {path} offset 1 0 0 0 0", "molecule keyword offset is not supported in pdps (templates are read as "
     "their file gives them)"),
    ("molecule m {path} {path}", "molecule m: one file per template in pdps (got a second word: {path})"),
    ("molecule m nowhere.mol", "molecule m: cannot read nowhere.mol (No such file or directory)"),
    ("molecule m-1 {path}", "molecule ID must be letters, digits and underscores (got m-1)"),
    ("molecule m {path}\nmolecule m {path}", "molecule m is already defined"),
    ("molecule m", "expected: molecule ID FILE"),
])
def test_refused_lines(tmp_path, line, message):
    path = tmp_path / "m.mol"
    with pytest.raises(ScriptError) as caught:
        define(tmp_path, TRI, line)
    assert re.sub(r"^<command>:\d+: molecule: ", "", str(caught.value)) == message.format(path=path)


def test_clear_forgets_the_templates(tmp_path):
    sim, _ = define(tmp_path, TRI)
    sim.command("clear")
    with pytest.raises(ScriptError, match=r"molecule template m is not defined \(defined: none\)"):
        sim.molecule_template("m")
