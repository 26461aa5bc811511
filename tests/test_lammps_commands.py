"""LAMMPS commands in pdps (docs/lammps.md): neighbor exclusions, the ghost cutoff, newton, control flow,
thermo keywords and thermo_modify, units, lattices, create_atoms."""

import math
import re

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import forces_by_tag, lj_fcc, make_box

LJ_PAIR = """mass * 1
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
"""


def lj(r):
    return 4.0 * (r ** -12 - r ** -6)


def three_particles(extra=""):
    sim = make_box(LJ_PAIR, ntypes=2)
    sim.command("create_particle 1 single 2 2 2\ncreate_particle 2 single 3.1 2 2\ncreate_particle 1 single 2 3.2 2\n"
                f"{extra}\nthermo_style custom step pe evdwl\nthermo_modify norm no\nrun 0")
    return sim


# ---- neigh_modify exclude -------------------------------------------------------------------------
def test_excluded_type_pairs_feel_nothing():
    sim = three_particles("neigh_modify exclude type 1 2")
    f = forces_by_tag(sim)
    np.testing.assert_allclose(f[1], [0, 0, 0], atol=0)                      # type 2: only 1-2 pairs
    assert sim.variables.evaluate("pe") == pytest.approx(lj(1.2), rel=1e-12)    # 1-3 only


def test_excluded_groups_and_none():
    sim = three_particles("group a id 1\ngroup b id 3\nneigh_modify exclude group a b")
    expected = lj(1.1) + lj(math.hypot(1.1, 1.2))
    assert sim.variables.evaluate("pe") == pytest.approx(expected, rel=1e-12)
    sim.command("neigh_modify exclude none\nrun 0")
    assert sim.variables.evaluate("pe") == pytest.approx(expected + lj(1.2), rel=1e-12)


def test_exclude_errors():
    sim = make_box(ntypes=2)
    with pytest.raises(ScriptError, match=r"exclude takes type I J, group G1 G2, molecule/intra G, molecule/inter G or none \(got bond\)"):
        sim.command("neigh_modify exclude bond 1 2")
    with pytest.raises(ScriptError, match="exclude molecule/intra needs molecule ids"):
        sim.command("neigh_modify exclude molecule/intra all")


# ---- comm_modify cutoff, newton --------------------------------------------------------------------
def test_a_larger_ghost_cutoff_changes_ghosts_not_forces():
    plain = three_particles()
    wide = three_particles("comm_modify cutoff 4.5 vel yes\nnewton off")
    assert wide.particles.nghost > plain.particles.nghost
    np.testing.assert_allclose(forces_by_tag(wide), forces_by_tag(plain), rtol=1e-14, atol=1e-14)


# ---- thermo -----------------------------------------------------------------------------------------
def test_thermo_keywords_as_lammps_defines_them():
    sim = three_particles("velocity all set 0.5 0 0")
    values = {k: sim.variables.evaluate(k) for k in ("pe", "evdwl", "ke", "etotal", "enthalpy", "density", "xlo",
                                                     "zhi", "fmax", "fnorm", "ecoul", "nbuild", "atoms")}
    assert values["pe"] == values["evdwl"]
    assert values["etotal"] == pytest.approx(values["pe"] + values["ke"])
    press = sim.variables.evaluate("press")
    assert values["enthalpy"] == pytest.approx(values["etotal"] + press * 1000.0)
    assert values["density"] == pytest.approx(3.0 / 1000.0)
    assert (values["xlo"], values["zhi"], values["ecoul"], values["atoms"]) == (0.0, 10.0, 0.0, 3)
    f = sim.f
    assert values["fmax"] == pytest.approx(np.abs(f).max())
    assert values["fnorm"] == pytest.approx(np.sqrt((f * f).sum()))


def test_thermo_modify_format_and_norm():
    import io
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None)
    sim.command("region box block 0 10 0 10 0 10\ncreate_box 1 box\n" + LJ_PAIR +
                "create_particle 1 single 2 2 2\ncreate_particle 1 single 3.1 2 2\n"
                "thermo_style custom step pe\nthermo_modify norm yes format float %.3f format 1 %5d\nrun 0")
    line = [row for row in screen.getvalue().splitlines() if row.strip().startswith("0 ")][0]
    assert line == f"    0 {lj(1.1) / 2:.3f}"


# ---- units --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("style, boltz, dt, skin", [("real", 0.0019872067, 1.0, 2.0), ("metal", 8.617343e-5, 0.001, 2.0),
                                                    ("cgs", 1.3806504e-16, 1e-8, 0.1), ("nano", 0.013806504, 0.00045, 0.1),
                                                    ("micro", 1.3806504e-8, 2.0, 0.1)])
def test_units_set_lammps_constants_and_defaults(style, boltz, dt, skin):
    sim = Simulation(screen=False, log=None)
    sim.command(f"units {style}")
    assert (sim.units.boltz, sim.dt, sim.neighbor.skin) == (boltz, dt, skin)


def test_metal_units_kick_with_ftm2v():
    # F = 1 eV/A on m = 2 g/mol for 10 steps of 1 fs: v = n dt F / m * ftm2v, in A/ps
    sim = Simulation(screen=False, log=None)
    sim.command("units metal\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 2.0\n"
                "create_particle 1 single 5 5 5\nfix 1 all nve\nfix push all addforce 1.0 0 0\nrun 10")
    assert sim.v[0, 0] == pytest.approx(10 * 0.001 * 1.0 / 2.0 / 1.0364269e-4, rel=1e-13)


# ---- lattices ---------------------------------------------------------------------------------------
def lammps_sim(lines):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(lines)
    return sim


def nearest(sim):
    x = sim.x
    d = x[:, None, :] - x[None, :, :]
    d -= sim.box.length * np.round(d / sim.box.length)
    r = np.sqrt((d * d).sum(-1))
    np.fill_diagonal(r, np.inf)
    return r.min()


@pytest.mark.parametrize("style, cells, per_cell, neighbour", [
    ("hcp", "0 3 0 2 0 2", 4, 1.0), ("diamond", "0 2 0 2 0 2", 8, math.sqrt(3) / 4), ("bcc", "0 3 0 3 0 3", 2,
                                                                                        math.sqrt(3) / 2)])
def test_3d_lattices_fill_cells_with_their_basis(style, cells, per_cell, neighbour):
    sim = lammps_sim(f"units metal\nlattice {style} 1.0\nregion box block {cells}\ncreate_box 1 box\n"
                     "create_atoms 1 box\nmass 1 1")
    ncell = np.prod([int(w) for w in cells.split()[1::2]])
    assert sim.nlocal == ncell * per_cell
    assert nearest(sim) == pytest.approx(neighbour, rel=1e-12)


def test_lj_scaling_gives_the_reduced_density():
    sim = lammps_sim("lattice hcp 0.9\nregion box block 0 4 0 2 0 2\ncreate_box 1 box\ncreate_atoms 1 box\nmass 1 1")
    assert sim.nlocal / sim.box.volume == pytest.approx(0.9, rel=1e-12)


def test_2d_lattices():
    sim = lammps_sim("dimension 2\nlattice hex 0.8\nregion box block 0 3 0 2 -0.5 0.5\ncreate_box 1 box\n"
                     "create_atoms 1 box\nmass 1 1")
    assert sim.nlocal == 3 * 2 * 2
    assert sim.nlocal / (sim.box.length[0] * sim.box.length[1]) == pytest.approx(0.8, rel=1e-12)


def test_orient_rotates_the_lattice_and_spacing_follows():
    sim = lammps_sim("units metal\nlattice fcc 4.0 orient x 1 1 0 orient y -1 1 0 orient z 0 0 1\n"
                     "region box block 0 2 0 2 0 2\ncreate_box 1 box\ncreate_atoms 1 box\nmass 1 1")
    np.testing.assert_allclose(sim.lattice.spacing, [4.0 * math.sqrt(2), 4.0 * math.sqrt(2), 4.0], rtol=1e-12)
    assert sim.nlocal / sim.box.volume == pytest.approx(4 / 64.0, rel=1e-12)
    assert nearest(sim) == pytest.approx(4.0 / math.sqrt(2), rel=1e-12)


def test_custom_lattice_and_origin_and_basis_types():
    sim = lammps_sim("units metal\nlattice custom 2.0 a1 1 0 0 a2 0 1 0 a3 0 0 1 basis 0 0 0 basis 0.5 0.5 0.5 "
                     "origin 0.25 0.25 0.25\nregion box block 0 2 0 2 0 2\ncreate_box 2 box\n"
                     "create_atoms 1 box basis 2 2\nmass * 1")
    assert sim.nlocal == 16
    assert np.isclose(sim.x.min(), 0.5)
    assert sorted(np.bincount(sim.type)[1:].tolist()) == [8, 8]


def test_create_atoms_single_in_lattice_units_and_remap():
    sim = lammps_sim("units metal\nlattice sc 2.0\nregion box block 0 3 0 3 0 3\ncreate_box 1 box\n"
                     "create_atoms 1 single 1 1 1\ncreate_atoms 1 single 7 1 1 units box remap yes\nmass 1 1")
    np.testing.assert_allclose(sorted(sim.x[:, 0].tolist()), [1.0, 2.0])


# ---- control flow ---------------------------------------------------------------------------------
def test_loops_and_conditions(pdps_cli):
    done = pdps_cli("""
        variable i loop 3
        variable total equal 0
        label top
        variable total equal ${total}+${i}
        if "${i} == 2" then "print two" elif "${i} > 2" "print three" else "print one"
        next i
        jump SELF top
        print "total ${total}"
    """, "-log", "none")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[1:] == ["one", "two", "three", "total 6"]


@pytest.mark.parametrize("script, line", [
    ("label a\nprint x\njump SELF a\n", 3),
    ("variable z equal 1\nlabel a\nvariable z equal 1\njump SELF a\n", 4),      # redefined, unchanged
])
def test_an_endless_loop_is_an_error(pdps_cli, script, line):
    done = pdps_cli(script, "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        f"ERROR: in.test:{line}: jump: jump SELF a: an endless loop (variables, step and particles are as "
        "they were at the last jump back)"]


@pytest.mark.parametrize("target", ["in.test", "./in.test"])
def test_a_jump_to_the_scripts_own_file_is_checked_as_jump_self(pdps_cli, target):
    # issue 30: the loop check knew only SELF, and this ran forever
    done = pdps_cli(f"label a\nprint x\njump {target} a\n", "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        f"ERROR: in.test:3: jump: jump {target} a: an endless loop (variables, step and particles are as "
        "they were at the last jump back)"]


def test_a_loop_through_the_scripts_own_file_ends_with_its_variable(pdps_cli):
    # LAMMPS's idiom: next exhausts the loop variable, and the jump after it is skipped
    done = pdps_cli("variable i loop 3\nlabel top\nprint i=${i}\nnext i\njump in.test top\nprint done\n",
                    "-log", "none")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[1:] == ["i=1", "i=2", "i=3", "done"]


def test_a_loop_whose_variable_changes_runs_to_its_end(pdps_cli):
    done = pdps_cli('variable n equal 0\nlabel top\nvariable n equal ${n}+1\n'
                    'if "${n} < 5" then "jump SELF top"\nprint "n=${n}"\n', "-log", "none")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "n=5"


def test_run_upto_and_ramp_over_start_stop():
    import io
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None)
    sim.command("region box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1\ncreate_particle 1 single 1 1 1\n"
                "fix 1 all nve\nvariable r equal ramp(0,100)\nthermo 0")
    sim.command("run 10 upto")
    assert sim.step == 10
    sim.command('fix p all print 10 "ramp $(v_r)"\nrun 10 start 0 stop 40')
    # steps 10 and 20 of a ramp from step 0 to 40: a quarter and half way (fix print prints at the run's
    # first step too: LAMMPS 22 Jul 2025 prints "ramp 25" and "ramp 50" for this script); between
    # runs ramp() reads its start, as LAMMPS's
    assert [line for line in screen.getvalue().splitlines() if line.startswith("ramp")] == ["ramp 25", "ramp 50"]
    assert sim.variables.value("r") == 0.0
    with pytest.raises(ScriptError, match="run 5 upto: the step is already 20"):
        sim.command("run 5 upto")


# ---- dump_modify ----------------------------------------------------------------------------------
def test_dump_modify_sort_format_every_first_append(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "d.custom").write_text("earlier\n")
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 3 0 3 0 3\ncreate_box 1 box\nmass 1 1\nlattice sc 1\n"
                "create_particle 1 box\nfix 1 all nve\n"
                "dump d all atom 4 d.atom\ndump_modify d sort -4 format float %.2f every 5 first yes\n"
                "dump c all custom 10 d.custom id x\ndump_modify c format line \"%3d %.1f\" append yes\n"
                "run 3")
    frames = (tmp_path / "d.atom").read_text().split("ITEM: TIMESTEP\n")[1:]
    assert [int(f.split()[0]) for f in frames] == [0]             # first yes: a frame at the start
    rows = [line.split() for line in frames[0].splitlines()[8:]]
    ys = [float(r[3]) for r in rows]
    assert ys == sorted(ys, reverse=True) and rows[0][3] == "0.67"  # sorted by column 4 (ys), descending
    custom = (tmp_path / "d.custom").read_text().splitlines()
    assert custom[0] == "earlier" and custom[10] == "  1 0.0"
    with pytest.raises(ScriptError, match="dump_modify thresh is not supported"):
        sim.command("dump_modify d thresh x > 1")
    with pytest.raises(ScriptError, match="append must be set before the dump writes its first frame"):
        sim.command("dump_modify c append yes")


def test_run_every_runs_commands_between_chunks(pdps_cli):
    done = pdps_cli("""
        region box block 0 5 0 5 0 5
        create_box 1 box
        mass 1 1
        create_particle 1 single 1 1 1
        fix 1 all nve
        thermo 0
        run 30 every 10 "print 'at $(step)'"
        print "done"
    """, "-log", "none")
    assert done.returncode == 0, done.stderr
    assert [line for line in done.stdout.splitlines() if line.startswith(("at ", "done"))] == [
        "at 10", "at 20", "at 30", "done"]


def test_clear_keeps_variables_and_starts_afresh():
    sim = make_box("mass 1 1\ncreate_particle 1 single 1 1 1\nvariable keep equal 7")
    sim.command("clear")
    assert sim.box is None and sim.nlocal == 0 and sim.variables.value("keep") == 7.0
    sim.command("region box block 0 2 0 2 0 2\ncreate_box 1 box")
    assert sim.box is not None


@pytest.mark.parametrize("mode", ["warn", "ignore"])
def test_thermo_modify_lost_deletes_particles_leaving_fixed_faces(mode):
    import io
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None)
    sim.command("boundary f p p\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1\n"
                "create_particle 1 single 4.9 1 1\ncreate_particle 1 single 2 2 2\nvelocity all set 1 0 0\n"
                f"fix 1 all nve\nthermo 50\nthermo_modify lost {mode}\nrun 100")
    assert sim.nlocal == 1 and sim.variables.evaluate("atoms") == 1
    warnings = [line for line in screen.getvalue().splitlines() if line.startswith("WARNING")]
    assert warnings == (["WARNING: Lost atoms: original 2 current 1"] if mode == "warn" else [])


def test_lost_error_is_still_the_default():
    sim = Simulation(screen=False, log=None)
    sim.command("boundary f p p\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1\n"
                "create_particle 1 single 4.9 1 1\nvelocity all set 1 0 0\nfix 1 all nve")
    with pytest.raises(ScriptError, match="particle 1 lost through the fixed x boundary"):
        sim.command("run 100")


# ---- read_data: Pair Coeffs and PairIJ Coeffs -------------------------------------------------------
PAIR_DATA = """two particles

2 atoms
2 atom types

0 10 xlo xhi
0 10 ylo yhi
0 10 zlo zhi

Masses

1 1.0
2 1.0

Pair Coeffs # lj/cut

1 1.0 1.0
2 0.5 1.2
{pairij}
Atoms # atomic

1 1 2 2 2
2 2 3.3 2 2
"""


def test_read_data_applies_pair_coeffs_as_pair_coeff_lines(tmp_path):
    """LAMMPS's write_data writes Pair Coeffs by default: read_data applies them (I I), mixed as usual,
    or as given per pair in PairIJ Coeffs."""
    sigma = math.sqrt(1.0 * 1.2)                # LAMMPS's default geometric mixing of 1 1 and 2 2
    mixed = 4 * math.sqrt(0.5) * ((sigma / 1.3) ** 12 - (sigma / 1.3) ** 6)
    for pairij, expected in (("", mixed), ("\nPairIJ Coeffs\n\n1 2 0.3 0.9\n", 4 * 0.3 * ((0.9 / 1.3) ** 12
                                                                                          - (0.9 / 1.3) ** 6))):
        (tmp_path / "pairs.data").write_text(PAIR_DATA.format(pairij=pairij))
        sim = Simulation(screen=False, log=None)
        sim.command(f"pair_style lj/cut 2.5\nread_data {tmp_path / 'pairs.data'}\n"
                    "thermo_style custom step pe\nthermo_modify norm no\nrun 0")
        assert sim.variables.evaluate("pe") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("setup, text, message", [
    ("", PAIR_DATA.format(pairij=""), "pairs.data:17: the data file has pair coefficients: define the pair_style "
                                      "before read_data"),
    ("pair_style lj/cut 2.5\n", PAIR_DATA.format(pairij="").replace("2 0.5 1.2", "2 0.5"),
     "pairs.data:18: pair coefficients: "),
    ("pair_style lj/cut 2.5\n", PAIR_DATA.format(pairij="\nPairIJ Coeffs\n\n1 3 0.3 0.9\n"),
     "pairs.data:22: pair coefficients for types 1 3 out of range 1..2"),
])
def test_read_data_pair_coeff_errors(tmp_path, setup, text, message):
    (tmp_path / "pairs.data").write_text(text)
    sim = Simulation(screen=False, log=None)
    if setup:
        sim.command(setup)
    with pytest.raises(ScriptError, match=re.escape(message)) as caught:
        sim.command(f"read_data {tmp_path / 'pairs.data'}")
    assert sim.box is None, caught.value


# ---- create_atoms on shrink-wrapped faces -------------------------------------------------------------
@pytest.mark.parametrize("boundary, count", [
    # what LAMMPS 22 Jul 2025 creates for this script: sites on an s face are made (the box then wraps
    # around them), on p, f and m faces not (review: pdps made 108 for s p p)
    ("p p p", 108), ("f p p", 108), ("m p p", 108), ("s p p", 126), ("fs p p", 126), ("sf p p", 108),
    ("p s m", 126), ("s s p", 147), ("s s s", 172),
])
def test_create_atoms_makes_the_sites_on_shrink_wrapped_faces_as_lammps(boundary, count):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"units lj\nboundary {boundary}\nlattice fcc 0.8442\nregion box block 0 3 0 3 0 3\n"
                "create_box 1 box\ncreate_atoms 1 box")
    assert sim.particles.nlocal == count


# ---- issue 30: valid LAMMPS that pdps refused ------------------------------------------------------
# Numbers recorded with LAMMPS 22 Jul 2025 (/work/shared/bench/lmp) on this machine, running each
# script below as it stands; pdps runs the same text.
from pdps_core.testing import thermo_rows  # noqa: E402

GROUP_FUNCTIONS = """units lj
atom_style atomic
boundary p p p
region box block 0 5 0 5 0 5
create_box 2 box
create_atoms 1 single 0.5 0.5 0.5
create_atoms 2 single 4.6 1.0 2.0
create_atoms 1 single 2.0 4.8 3.0
create_atoms 2 single 3.0 3.0 0.3
mass 1 1.0
mass 2 3.0
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
group heavy type 2
velocity all set 0.3 -0.2 0.1
velocity heavy set 2.0 -1.0 0.5
fix 1 all nve
timestep 0.005
thermo 50
variable xa equal xcm(all,x)
variable vz equal vcm(heavy,z)
variable fy equal fcm(heavy,y)
run 100
print "XCM $(v_xa:%.12g) $(xcm(all,y):%.12g) $(xcm(heavy,x):%.12g) $(xcm(heavy,z):%.12g)"
print "VCM $(vcm(all,x):%.12g) $(vcm(all,y):%.12g) $(vcm(heavy,x):%.12g) $(v_vz:%.12g)"
print "FCM $(fcm(all,x):%.12g) $(fcm(heavy,x):%.12g) $(v_fy:%.12g) $(fcm(heavy,z):%.12g)"
"""
# LAMMPS's lines: mass-weighted centres of unwrapped positions (particle 2 of mass 3 crosses x = 5)
# and velocities; fcm the plain sum of forces
GROUP_FUNCTIONS_LAMMPS = {
    "XCM": [3.95, 1.7625, 4.80390515852, 1.39075417795],
    "VCM": [1.575, -0.8, 2.01589355562, 0.457903425671],
    "FCM": [0.0, 0.205486464569, -0.137296989667, -0.604794879709],
}


def printed_numbers(stdout, label):
    [line] = [line for line in stdout.splitlines() if line.startswith(label + " ")]
    return [float(w) for w in line.split()[1:]]


def test_xcm_vcm_fcm_group_functions_as_lammps(pdps_cli):
    done = pdps_cli(GROUP_FUNCTIONS, "-log", "none")
    assert done.returncode == 0, done.stderr
    for label, expected in GROUP_FUNCTIONS_LAMMPS.items():
        assert printed_numbers(done.stdout, label) == pytest.approx(expected, rel=1e-11, abs=1e-12), label


THERMO_COMPUTES = lj_fcc(3) + """mass 1 1.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
fix 1 all nve
variable t equal c_thermo_temp
variable p equal c_thermo_press
variable p1 equal c_thermo_press[1]
variable p4 equal c_thermo_press[4]
variable e equal c_thermo_pe
variable k1 equal c_thermo_temp[1]
variable k6 equal c_thermo_temp[6]
thermo_style custom step temp press pe c_thermo_temp c_thermo_pe c_thermo_press[2] v_t v_p v_p1 v_p4 v_e v_k1 v_k6
thermo_modify format float %.12g
run 50
"""
# step temp press pe c_thermo_temp c_thermo_pe (per atom: thermo normalises it in lj units)
# c_thermo_press[2] v_t v_p v_p1 v_p4 v_e (the total: a variable does not) v_k1 v_k6 (m v v tensor)
THERMO_COMPUTES_LAMMPS = [
    [0, 1.5, -4.98074227009, -6.77336805325, 1.5, -6.77336805325, -4.99703511733, 1.5, -4.98074227009,
     -4.9664363308, -0.0815713391333, -731.523749751, 162.330184131, -6.39418458994],
    [50, 0.738589600044, 0.746711945145, -5.65095491888, 0.738589600044, -5.65095491888, 1.51350975372,
     0.738589600044, 0.746711945145, 0.412241452706, 0.41071212449, -610.303131239, 76.5742981379,
     -10.688287192],
]


def assert_two_rows_as_lammps(done, lammps_rows):
    """A run's two thermo rows against LAMMPS's to 1e-11."""
    assert done.returncode == 0, done.stderr
    rows = thermo_rows(done.stdout)
    assert len(rows) == 2
    for row, expected in zip(rows, lammps_rows):
        assert row == pytest.approx(expected, rel=1e-11)


def test_thermo_computes_every_lammps_run_defines(pdps_cli):
    assert_two_rows_as_lammps(pdps_cli(THERMO_COMPUTES, "-log", "none"), THERMO_COMPUTES_LAMMPS)


REDUCE_ATOM_VARIABLES = lj_fcc(3, 2) + """mass 1 1.0
mass 2 2.0
set group all type/fraction 2 0.5 12345
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
fix 1 all nve
variable ke2 atom mass*(vx*vx+vy*vy+vz*vz)
variable xx atom x+2*y
group heavy type 2
compute s all reduce sum v_ke2
compute m heavy reduce max v_xx
compute a all reduce ave v_ke2 v_xx
thermo_style custom step c_s c_m c_a[1] c_a[2]
thermo_modify format float %.12g norm no
run 20
"""
REDUCE_ATOM_VARIABLES_LAMMPS = [[0, 481.5, 12.5969714354, 4.45833333333, 6.29848571768],
                                [20, 228.554214322, 13.3712237108, 2.1162427252, 7.75375080394]]


def test_compute_reduce_of_atom_style_variables(pdps_cli):
    assert_two_rows_as_lammps(pdps_cli(REDUCE_ATOM_VARIABLES, "-log", "none"), REDUCE_ATOM_VARIABLES_LAMMPS)


@pytest.mark.parametrize("line, message", [
    ("compute r all reduce sum v_nothing", "compute r reduce: variable nothing is not defined (v_nothing)"),
    ("variable q equal 2\ncompute r all reduce sum v_q", "compute r reduce: variable q is equal-style, not "
                                                         "atom-style (v_q)"),
])
def test_compute_reduce_of_a_variable_that_is_not_atom_style(pdps_cli, line, message):
    done = pdps_cli(REDUCE_ATOM_VARIABLES.split("variable ke2")[0] + line + "\nthermo_style custom step c_r\nrun 0\n",
                    "-log", "none")
    assert done.returncode == 1
    [error] = done.stderr.strip().splitlines()
    assert error.endswith(f"run: {message}"), error
