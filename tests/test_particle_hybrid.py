"""particle_style (atom_style) hybrid: the per-atom values of several styles at once, read and written
as LAMMPS reads and writes them (``hybrid sphere molecular``: spheres with molecule ids, as granular
clumps of fix rigid molecule and rigid/small need), and spheres' angular velocities in Velocities."""

import pathlib
import shutil

import numpy as np
import pytest

from pdps_core.api import Simulation

DATA = pathlib.Path(__file__).parent / "data"
# id mass radius mol vx vy vz omegax omegay omegaz x y z ix iy iz, as LAMMPS dumped them
LAMMPS = np.loadtxt(DATA / "hybrid_sphere_molecular.lammps.txt", comments=("#", "ITEM"))


def read(tmp_path, script, data="hybrid_sphere_molecular.data"):
    shutil.copy(DATA / data, tmp_path / data)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(script.replace("DATA", str(tmp_path / data)))
    return sim


def per_atom(sim):
    p = sim.particles
    n = p.nlocal
    order = np.argsort(p.tag[:n])
    columns = [p.tag[:n], p.rmass[:n], p.radius[:n], p.molecule[:n], *p.v[:n].T, *p.omega[:n].T, *p.x[:n].T,
               *p.image[:n].T]
    return np.column_stack(columns).astype(float)[order]


def test_hybrid_sphere_molecular_reads_a_data_file_as_lammps_does(tmp_path):
    sim = read(tmp_path, "atom_style hybrid sphere molecular\nread_data DATA")
    assert sim.particle_style == "hybrid sphere molecular"
    assert sim.particle_styles == ("sphere", "molecular")
    # mass from diameter and density, the molecule column after them, image flags, and the spheres'
    # angular velocities from the Velocities lines: every value LAMMPS has, to the last bit
    assert np.array_equal(per_atom(sim), LAMMPS)


def test_write_data_writes_what_lammps_writes(tmp_path):
    read(tmp_path, f"atom_style hybrid sphere molecular\nread_data DATA\nwrite_data {tmp_path}/out.data")
    text = (tmp_path / "out.data").read_text()
    # LAMMPS's own header and column order (checked: LAMMPS 22 Jul 2025 reads this file back to the
    # same dump as the original), with wx wy wz after each velocity
    assert "Atoms # hybrid\n\n1 1 1.0 2.0 3.0 1.0 2.0 7 0 0 0\n" in text
    assert "Velocities\n\n1 0.1 0.2 0.3 1.0 2.0 3.0\n" in text
    assert "Masses" not in text


def test_write_data_round_trip(tmp_path):
    sim = read(tmp_path, f"atom_style hybrid sphere molecular\nread_data DATA\nwrite_data {tmp_path}/out.data")
    again = Simulation(screen=False, log=None, dialect="lammps")
    again.command(f"atom_style hybrid sphere molecular\nread_data {tmp_path}/out.data")
    assert np.array_equal(per_atom(again), per_atom(sim))


def test_sphere_data_files_give_their_angular_velocities(tmp_path):
    (tmp_path / "s.data").write_text(
        "spheres\n\n2 atoms\n1 atom types\n\n0 4 xlo xhi\n0 4 ylo yhi\n0 4 zlo zhi\n\nAtoms # sphere\n\n"
        "1 1 1.0 1.0 1 1 1\n2 1 1.0 1.0 2 2 2\n\nVelocities\n\n1 1 0 0 0.5 -0.5 2\n2 0 1 0\n")
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"atom_style sphere\nread_data {tmp_path}/s.data")
    p = sim.particles
    first, second = (p.index_of_tag(t) for t in (1, 2))
    assert p.omega[first].tolist() == [0.5, -0.5, 2.0] and p.v[first].tolist() == [1.0, 0.0, 0.0]
    # a line with the velocity alone (older pdps write_data) leaves the sphere without spin
    assert p.omega[second].tolist() == [0.0, 0.0, 0.0] and p.v[second].tolist() == [0.0, 1.0, 0.0]


def test_a_type_mass_with_hybrid_spheres_is_kept_but_the_spheres_own_is_used(tmp_path):
    sim = read(tmp_path, "atom_style hybrid sphere molecular\nread_data DATA")
    before = len(sim.warnings)
    sim.command("mass * 3.0")
    messages = sim.warnings[before:]
    # LAMMPS takes the command (its hybrid needs per-type masses set) and uses per-particle ones
    assert np.array_equal(per_atom(sim)[:, 1], LAMMPS[:, 1])
    assert messages == ["mass * 3.0: atom_style hybrid sphere molecular uses each sphere's own mass "
                        "(diameter and density), not the type's, as LAMMPS does"]


@pytest.mark.parametrize("line, message", [
    ("atom_style hybrid", "hybrid needs one or more particle styles, e.g. hybrid sphere molecular"),
    ("atom_style hybrid sphere sphere", "a particle style appears twice in hybrid sphere sphere"),
    ("atom_style hybrid sphere ellipsoid",
     "unknown particle style ellipsoid in hybrid (known: atomic, sphere, charge, molecular, bond, angle, full)"),
])
def test_bad_hybrid_is_one_line(pdps_cli, line, message):
    result = pdps_cli(f"{line}\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n")
    assert result.returncode == 1
    usage = ("; usage: particle_style atomic|sphere|charge|molecular|bond|angle|full or particle_style hybrid "
             "STYLE1 STYLE2 ...")
    assert result.stderr.strip().splitlines()[-1] == f"ERROR: in.test:1: atom_style: {message}{usage}"
