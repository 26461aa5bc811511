"""fix pour mol: copies of a molecule template, and with rigid the bodies fix rigid/small mol makes of
them, against LAMMPS 22 Jul 2025 recorded on this machine for the scripts below (data/pour_molecule.json):
the first batch as LAMMPS's dump after one step, and the thermo rows through contacts with the floor."""

import json
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import run_ranks

RECORDED = json.loads((Path(__file__).parent / "data" / "pour_molecule.json").read_text())

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

ELL = """# an L of four spheres

4 atoms

Coords

1 0.0 0.0 0.0
2 1.0 0.0 0.0
3 2.0 0.0 0.0
4 2.0 1.1 0.4

Types

1 1
2 1
3 2
4 2

Diameters

1 1.0
2 1.0
3 0.9
4 1.1

Masses

1 0.6
2 0.5
3 0.4
4 0.7
"""

# 12 bent molecules (10 in the first batch, 2 at the second run's start), not rigid
TRI_SCRIPT = """atom_style sphere
atom_modify map array
boundary p p fm
comm_modify vel yes
fix prop all property/atom mol ghost yes
region box block 0 10 0 10 0 30 units box
create_box 3 box
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
neighbor 0.3 bin
neigh_modify delay 0
timestep 0.001
fix grav all gravity 1.0 vector 0 0 -1
fix nve all nve/sphere
fix zlo all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0 NULL
molecule tri {folder}/tri.mol
region slab block 1 9 1 9 20 28 units box
fix ins all pour 12 0 58271 vol 0.3 40 region slab mol tri
dump d all custom 1 {folder}/first.dump id type mol radius mass x y z vx vy vz ix iy iz
dump_modify d format float %.17g
thermo_style custom step atoms ke
thermo_modify format float %.15g
thermo 100
run 1
undump d
run 600
"""

# 9 rigid L's falling onto the floor, their weight on the centres of mass (gravity disable)
ELL_SCRIPT = """atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes cutoff 3.0
fix prop all property/atom mol ghost yes
region box block 0 12 0 12 0 30 units box
create_box 2 box
pair_style gran/hooke/history 4000.0 NULL 100.0 NULL 0.5 0
pair_coeff * *
neighbor 0.3 bin
neigh_modify delay 0 exclude molecule/intra all
timestep 0.001
fix grav all gravity 9.8 vector 0 0 -1 disable
molecule ell {folder}/ell.mol
fix rig all rigid/small molecule mol ell gravity grav
region slab block 2 10 2 10 8 14 units box
fix ins all pour 9 0 7310 vol 0.4 50 region slab mol ell rigid rig
fix zlo all wall/gran hooke/history 4000.0 NULL 100.0 NULL 0.5 0 zplane 0 NULL
compute k all ke
compute r all erotate/sphere
dump a all custom 1 {folder}/first.dump id type mol radius mass x y z vx vy vz
dump_modify a format float %.17g
thermo_style custom step atoms c_k c_r
thermo_modify format float %.15g
thermo 100
run 1
undump a
run 1500
"""


def run(folder, script):
    (folder / "tri.mol").write_text(TRI)
    (folder / "ell.mol").write_text(ELL)
    log = folder / "log.case"
    sim = Simulation(screen=False, log=str(log), dialect="lammps")
    sim.command(script.format(folder=folder))
    sim.close()
    return sim, log.read_text()


def thermo(text, ncol):
    rows = {}
    for line in text.splitlines():
        words = line.split()
        if len(words) == ncol and words[0].isdigit() and words[1].isdigit():
            rows[int(words[0])] = [float(w) for w in words]
    return [rows[step] for step in sorted(rows)]


def first_frame(path, columns):
    """The frame of step 1 (the dump's last: step 0 has no particles yet)."""
    text = path.read_text().split("ITEM: ATOMS")[-1]
    header, *lines = text.splitlines()
    assert header.split() == columns
    values = np.loadtxt(lines, ndmin=2)
    return values[np.argsort(values[:, 0])]


def test_the_first_batch_of_molecules_is_lammps_s_dump(tmp_path):
    """10 copies turned about random axes (LAMMPS's draws: height, x and y, the template's draw, the
    axis, the angle per try; then the velocity), each atom its template type plus TYPE, radius and
    mass, the copy a molecule id: LAMMPS's dump after one step to 1e-12, and its thermo to 600 steps."""
    sim, text = run(tmp_path, TRI_SCRIPT)
    assert "Particle insertion: 10 every 4000 steps, 12 by step 4001" in text
    got = first_frame(tmp_path / "first.dump", RECORDED["tri_columns"])
    want = np.array(RECORDED["tri_first_batch"])
    assert got.shape == want.shape == (30, 14)
    names = RECORDED["tri_columns"]
    exact = [names.index(c) for c in ("id", "type", "mol", "radius", "mass", "ix", "iy", "iz")]
    assert np.array_equal(got[:, exact], want[:, exact])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    rows = thermo(text, 3)
    assert len(rows) == len(RECORDED["tri_thermo"])
    for mine, lammps in zip(rows, RECORDED["tri_thermo"]):
        assert mine == pytest.approx(lammps, rel=1e-13, abs=1e-15)
    assert sorted(set(sim.particles.molecule[:sim.nlocal].tolist())) == list(range(1, 13))


def test_rigid_molecules_fall_as_lammps_s(tmp_path):
    """fix rigid/small mol makes a body of each copy as fix pour places it; fix gravity disable leaves
    the particles alone and rigid/small's gravity keyword pulls each centre of mass: the first batch
    as LAMMPS's dump, the bodies' mass and principal moments as LAMMPS's compute rigid/local gives
    them, and the kinetic and rotational energies to 1e-11 through the bodies' impacts (1500 steps;
    LAMMPS on 2 ranks prints the same digits)."""
    sim, text = run(tmp_path, ELL_SCRIPT)
    assert "Particle insertion: 6 every 1107 steps, 9 by step 1108" in text
    got = first_frame(tmp_path / "first.dump", RECORDED["ell_columns"])
    want = np.array(RECORDED["ell_first_batch"])
    assert got.shape == want.shape == (24, 11)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    body = sim.fixes["rig"].template_body
    lammps = np.array(RECORDED["ell_bodies"])
    assert body.mass == lammps[0, 2]
    np.testing.assert_allclose(body.inertia, lammps[0, 6:9], rtol=1e-15)
    assert body.extent == pytest.approx(1.5394804, abs=1e-7)
    rows = thermo(text, 4)
    assert len(rows) == len(RECORDED["ell_thermo"])
    for mine, lammps in zip(rows, RECORDED["ell_thermo"]):
        assert mine == pytest.approx(lammps, rel=1e-11, abs=1e-20)


@pytest.mark.parametrize("change, message", [
    ("fix ins all pour 9 0 7310 vol 0.4 50 region slab mol ell rigid zlo",
     "fix ins (pour): fix zlo (wall/gran) makes no rigid bodies of molecule templates (fix rigid/small ... mol "
     "TEMPLATE does)"),
    ("fix ins all pour 9 0 7310 vol 0.4 50 region slab mol ell rigid nowhere",
     "fix ins (pour): rigid fix nowhere does not exist"),
    ("fix ins all pour 9 0 7310 vol 0.4 50 region slab mol tri rigid rig",
     "fix ins (pour) and fix rig use different molecule templates (tri and ell)"),
])
def test_a_pour_s_rigid_fix_must_make_bodies_of_its_template(tmp_path, change, message):
    (tmp_path / "tri.mol").write_text(TRI)
    (tmp_path / "ell.mol").write_text(ELL)
    script = ELL_SCRIPT.format(folder=tmp_path).replace(
        "fix ins all pour 9 0 7310 vol 0.4 50 region slab mol ell rigid rig", f"molecule tri {tmp_path}/tri.mol\n{change}")
    script = script.split("run 1")[0] + "run 1\n"
    sim = Simulation(screen=False, log=None, dialect="lammps")
    with pytest.raises(ScriptError) as caught:
        sim.command(script)
    assert str(caught.value).endswith(message)


@pytest.mark.parametrize("line, message", [
    ("fix ins all pour 9 2 7310 region slab mol ell", "fix: TYPE 2 plus molecule ell's types (up to 2) must be at most 2 "
     "(LAMMPS: Invalid atom type in fix pour mol command)"),
    ("fix ins all pour 9 0 7310 region slab mol nothing", "fix: molecule template nothing is not defined (defined: ell)"),
    ("fix ins all pour 9 0 7310 region slab mol ell molfrac 1", "fix: keyword molfrac of fix pour: pdps's molecule "
     "templates are one molecule each (LAMMPS's molfrac chooses among a set's)"),
])
def test_bad_molecule_pours_get_one_line(tmp_path, line, message):
    (tmp_path / "ell.mol").write_text(ELL)
    head = ELL_SCRIPT.format(folder=tmp_path).split("fix rig all")[0]
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(head)
    with pytest.raises(ScriptError) as caught:
        sim.command("region slab block 2 10 2 10 8 14 units box\n" + line)
    assert str(caught.value).split(": ", 1)[1] == message


def test_rigid_molecules_on_2_ranks_as_on_1(tmp_path):
    """Rank 0 adds every copy and the bodies' records travel with their owner particles: the rigid
    L's print on 2 ranks what LAMMPS printed (to 1e-11)."""
    (tmp_path / "ell.mol").write_text(ELL)
    script = ELL_SCRIPT.format(folder=tmp_path)
    script = "\n".join(line for line in script.splitlines() if not line.startswith(("dump", "undump")))
    rows = thermo(run_ranks(script, 2, tmp_path).stdout, 4)
    assert len(rows) == len(RECORDED["ell_thermo"])
    for mine, lammps in zip(rows, RECORDED["ell_thermo"]):
        assert mine == pytest.approx(lammps, rel=1e-11, abs=1e-20)
