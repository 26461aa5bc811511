"""Dialects (docs/lammps.md): which one a script is read in and why, and the points where PDPS and
LAMMPS differ: index bases, region units, the formula grammar (against LAMMPS's own answers,
recorded by benchmarks/lammps_references/expressions.py into tests/data/lammps/)."""

from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

DATA = Path(__file__).parent / "data" / "lammps"


def first_line(pdps_cli, script, *extra):
    done = pdps_cli(script, *extra, "-log", "none")
    return done, done.stdout.splitlines()[0] if done.stdout else ""


# ---- which dialect ----------------------------------------------------------------------------------
@pytest.mark.parametrize("script, line", [
    ("units lj\natom_style atomic\n", "read as LAMMPS: atom_style on line 2"),
    ("# water\nunits lj\nparticle_style atomic\n", "read as PDPS: particle_style on line 3"),
    ("units lj\nlattice fcc 0.8442\n", "read as LAMMPS: lattice fcc on line 2"),
    ("units lj\nlattice spacing x 1 y 1 z 1\n", "read as PDPS: lattice spacing on line 2"),
    ("units lj\nneigh_modify every 1\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n"
     "create_particle 1 single 0.5 0.5 0.5\n", "read as PDPS: create_particle on line 5"),
    ("# comment\n\ndialect lammps\nunits lj\n", "read as LAMMPS: dialect on line 3"),
    ("units lj\n", "read as PDPS: no command names a dialect (PDPS is the default)"),
])
def test_the_first_line_names_the_dialect_and_why(pdps_cli, script, line):
    done, first = first_line(pdps_cli, script)
    assert done.returncode == 0, done.stderr
    assert first == line


@pytest.mark.parametrize("settings, line", [
    ("units lj\natom_style atomic\n", "read as LAMMPS: atom_style on line 2 of in.settings (included on line 2)"),
    ("atom_style sphere\npair_style gran model hertz tangential history\n",
     "read as LIGGGHTS: pair_style gran on line 2 of in.settings (included on line 2)"),
    ("include in.inner\n", "read as LAMMPS: create_atoms on line 1 of in.inner (included on line 1 of "
                           "in.settings (included on line 2))"),
])
def test_the_files_a_script_includes_name_its_dialect(pdps_cli, tmp_path, settings, line):
    # issue 30: a script whose LAMMPS-only commands all sat in an included file was read as PDPS
    (tmp_path / "in.settings").write_text(settings)
    (tmp_path / "in.inner").write_text("create_atoms 1 single 0 0 0\n")
    done = pdps_cli("# the settings come from a file\ninclude in.settings\n", "-log", "none")
    assert done.stdout.splitlines()[0] == line


def test_the_command_line_decides_over_the_lines(pdps_cli):
    done, first = first_line(pdps_cli, "units lj\nparticle_style atomic\n", "--dialect", "lammps")
    assert (done.returncode, first) == (0, "read as LAMMPS: as asked")


@pytest.mark.parametrize("script, extra, message", [
    ("units lj\ndialect lammps\n", (),
     "ERROR: in.test:2: dialect: dialect must come before any other command (line 1 has units)"),
    ("dialect fortran\n", (), "ERROR: in.test:1: dialect: dialect must be lammps, liggghts or pdps (got fortran)"),
    ("dialect pdps\nunits lj\n", ("--dialect", "lammps"),
     "ERROR: in.test: dialect pdps (dialect on line 1) contradicts the dialect given (lammps)"),
])
def test_dialect_errors(pdps_cli, script, extra, message):
    done = pdps_cli(script, *extra, "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [message]


def test_python_commands_are_pdps_until_told(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None)
    assert sim.dialect.name == "pdps"
    sim.command("dialect lammps")
    assert sim.dialect.name == "lammps"
    sim.command("region box block 0 1 0 1 0 1\ncreate_box 1 box")
    with pytest.raises(ScriptError, match="the dialect cannot change midway"):
        sim.command("dialect pdps")
    assert Simulation(screen=False, log=None, dialect="lammps").dialect.index_base == 1


# ---- index bases --------------------------------------------------------------------------------------
CENTROID = """region box block 0 4 0 4 0 4 units box
create_box 1 box
mass 1 1
create_atoms 1 single 1 2 3 units box
compute cen all centroid
"""


@pytest.mark.parametrize("dialect, index, value", [("lammps", 1, 1.0), ("lammps", 3, 3.0),
                                                    ("pdps", 0, 1.0), ("pdps", 2, 3.0)])
def test_vector_indices_count_from_the_dialects_base(make_sim, dialect, index, value):
    sim = Simulation(screen=False, log=None, dialect=dialect)
    sim.command(CENTROID + f"variable c equal c_cen[{index}]\nrun 0")
    assert sim.variables.value("c") == value


def test_index_0_is_an_error_in_lammps(make_sim):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(CENTROID + "run 0")
    with pytest.raises(ScriptError) as caught:
        sim.compute_value("cen", (0,))
    assert caught.value.message == "c_cen[0]: indices count from 1 in the LAMMPS dialect (got 0)"


# ---- region units ------------------------------------------------------------------------------------
LATTICES = [line.split("\t") for line in (DATA / "lattices.txt").read_text().splitlines()]


@pytest.mark.parametrize("scene, atoms, lx, ly, lz", LATTICES, ids=[row[0] for row in LATTICES])
def test_lattices_through_regions_as_lammps_fills_them(scene, atoms, lx, ly, lz):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\n" + scene.replace("|", "\n") + "\ncreate_box 1 box\ncreate_atoms 1 box\nmass 1 1")
    count = sim.variables.evaluate("atoms")
    if "region inner" in scene:
        sim.command("group inner region inner")
        count = sim.variables.evaluate("count(inner)")
    assert count == int(atoms)
    np.testing.assert_allclose(sim.box.length, [float(lx), float(ly), float(lz)], rtol=1e-15)


def test_pdps_regions_default_to_box_units(make_sim):
    sim = Simulation(screen=False, log=None, dialect="pdps")
    sim.command("lattice spacing x 0.5 y 0.5 z 1\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                "create_particle 1 region box")
    assert sim.nlocal == 4000 and np.allclose(sim.box.length, 10.0)


# ---- formulas ------------------------------------------------------------------------------------------
FORMULAS = [line.split("\t") for line in (DATA / "expressions.txt").read_text().splitlines()]


@pytest.mark.parametrize("formula, value", FORMULAS, ids=[row[0] for row in FORMULAS])
@pytest.mark.parametrize("dialect", ["lammps", "pdps"])
def test_formulas_give_what_lammps_prints(formula, value, dialect):
    sim = Simulation(screen=False, log=None, dialect=dialect)
    assert sim.variables.evaluate(formula) == float(value)


# ---- what pdps does not run -------------------------------------------------------------------------
@pytest.mark.parametrize("line, message", [
    ("kspace_style pppm 1e-4", "kspace_style is a LAMMPS command pdps does not support; instead: pdps has no "
                               "long-range electrostatics (docs/lammps.md)"),
    ("labelmap atom 1 C", "labelmap is a LAMMPS command pdps does not support; instead: numeric types "
                          "(docs/lammps.md)"),
])
def test_lammps_commands_pdps_does_not_run_name_an_alternative(pdps_cli, line, message):
    done = pdps_cli(f"units lj\natom_style atomic\n{line}\n", "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [f"ERROR: in.test:3: {line.split()[0]}: {message}"]


def test_lammps_styles_pdps_has_not_name_an_alternative(pdps_cli):
    done = pdps_cli("units lj\natom_style atomic\npair_style lj/cut/coul/long 2.5\n", "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        "ERROR: in.test:3: pair_style: pair style lj/cut/coul/long is a LAMMPS style pdps does not have; "
        "instead: pdps has no charges: lj/cut for the Lennard-Jones part (docs/lammps.md)"]


LIGGGHTS_MATERIAL = """
    atom_style granular
    region box block -1 1 -1 1 0 2 units box
    create_box 1 box
    fix m1 all property/global youngsModulus peratomtype 5.e6
    fix m2 all property/global poissonsRatio peratomtype 0.45
    fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
    fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
"""


def test_liggghts_2_spellings_of_its_granular_models(make_sim):
    """LIGGGHTS's conveyor tutorial: pair_style gran/hertz/history with no coefficients and fix
    wall/gran/hertz/history mesh|primitive ... mean today's gran model hertz tangential history; in the
    LAMMPS dialect those names stay LAMMPS's styles, which need their coefficients."""
    sim = make_sim(dialect="liggghts")
    sim.command(LIGGGHTS_MATERIAL + """
        pair_style gran/hertz/history
        pair_coeff * *
        fix floor all wall/gran/hertz/history primitive type 1 zplane 0.0
    """)
    assert sim.pair.name == "gran" and sim.pair.args.model == "hertz"
    floor = sim.fixes["floor"].args
    assert sim.fixes["floor"].name == "wall/gran" and (floor.model, floor.tangential) == ("hertz", "history")
    sim.command("pair_style gran/hooke")
    assert sim.pair.name == "gran" and sim.pair.args.model == "hooke" and sim.pair.args.tangential == "no_history"
    # 2.x lines with model settings (LIGGGHTS's note on the 3.x syntax change)
    sim.command("fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.1")
    sim.command("pair_style gran/hertz/history rolling_friction cdt")
    assert sim.pair.name == "gran" and sim.pair.args.rolling_friction == "cdt"
    sim.command("fix side all wall/gran/hertz/history primitive type 1 xplane -0.5 rolling_friction cdt")
    side = sim.fixes["side"].args
    assert (side.model, side.tangential, side.rolling_friction) == ("hertz", "history", "cdt")
    assert side.primitive == ("type", 1, ("xplane", -0.5))
    sim.command("fix top all wall/gran/hooke/history type 1 zplane 2.0")
    top = sim.fixes["top"].args
    assert (top.model, top.tangential, top.primitive) == ("hooke", "history", ("type", 1, ("zplane", 2.0)))
    lammps = make_sim(dialect="lammps")
    lammps.command("atom_style sphere\nregion box block -1 1 -1 1 0 2 units box\ncreate_box 1 box")
    with pytest.raises(ScriptError, match="missing argument"):
        lammps.command("pair_style gran/hertz/history")


def test_a_liggghts_2_wall_name_in_a_lammps_script_is_refused_before_the_run(pdps_cli):
    """LIGGGHTS 2.x's wall names are the granular plugin's spellings (Style.respell), not LAMMPS
    fixes: in a LAMMPS script the line is refused when the script is read, before any step runs."""
    result = pdps_cli("atom_style sphere\nregion box block -1 1 -1 1 0 2 units box\ncreate_box 1 box\n"
                      "run 10\nfix floor all wall/gran/hooke/history primitive type 1 zplane 0.0\n",
                      "--dialect", "lammps")
    assert result.returncode == 1
    assert result.stderr.strip() == (
        "ERROR: in.test:5: fix: fix style wall/gran/hooke/history is LIGGGHTS 2.x's spelling of wall/gran "
        "model hooke tangential history; read the script as LIGGGHTS (--dialect liggghts)")
    assert "Loop time" not in result.stdout


# LIGGGHTS 3.8.0's default thermo line is Step Atoms KinEng CPU, and its ke is its compute
# thermo_kin_eng, the sum of 1/2 m v^2 (not LAMMPS's 1/2 dof k_B T, which is 0 for one particle).
# One sphere falling onto a wall, as LIGGGHTS 3.8.0 printed it here.
FALLING_SPHERE = """atom_style granular
atom_modify map array
boundary p p f
newton off
communicate single vel yes
units si
region reg block 0 0.1 0 0.1 0 0.1 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
create_atoms 1 single 0.05 0.05 0.05
set atom 1 diameter 0.01 density 2500
fix integr all nve/sphere
fix wz all wall/gran model hertz tangential history primitive type 1 zplane 0.0
thermo 1000
run 3000
"""
FALLING_SPHERE_LIGGGHTS = {0: (1, 0.0), 1000: (1, 6.298638e-06), 2000: (1, 2.5194552e-05)}


def test_liggghts_default_thermo_line_and_its_kinetic_energy(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.liggghts"), dialect="liggghts")
    sim.command(FALLING_SPHERE)
    sim.close()
    lines = (tmp_path / "log.liggghts").read_text().splitlines()
    at = next(i for i, line in enumerate(lines) if line.split()[:1] == ["Step"])
    assert lines[at].split() == ["Step", "Atoms", "KinEng", "CPU"]
    rows = {int(words[0]): words for words in map(str.split, lines[at + 1:at + 4])}
    for step, (atoms, ke) in FALLING_SPHERE_LIGGGHTS.items():
        assert int(rows[step][1]) == atoms
        assert float(rows[step][2]) == pytest.approx(ke, rel=1e-6, abs=1e-30)
