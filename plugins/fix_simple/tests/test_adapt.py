"""Fix adapt: radii and masses as LAMMPS 22 Jul 2025 and LIGGGHTS 3.8.0 leave them (recorded on this
machine, 2026-12-02, from the two-particle scenes below run in each program with write_dump), the
contacts of growing spheres all seen, and the refusals.

Two spheres, radius 0.5 density 2 and radius 1 density 1; ``variable d equal EXPR`` and
``fix a all adapt N atom diameter v_d KEYWORDS`` then ``run STEPS``; radius and mass of each after."""

import io

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import assert_prints_as_lammps

LAMMPS_SCENE = """
units lj
atom_style sphere 1
atom_modify map array
region b block 0 5 0 5 0 5
create_box 1 b
create_atoms 1 single 1 1 1
create_atoms 1 single 3 3 3
set atom 1 diameter 1.0 density 2.0
set atom 2 diameter 2.0 density 1.0
variable d equal {expr}
fix a all adapt {every} atom diameter v_d {keywords}
fix n all nve
pair_style zero 3.0
pair_coeff * *
run {steps}
"""

# (expr, N, keywords, steps) -> (radius 1, mass 1, radius 2, mass 2), LAMMPS's write_dump
LAMMPS = {
    ("1.5", 0, "scale yes", 0): (0.75, 3.53429173528852, 1.5, 14.1371669411541),
    ("1.5", 0, "scale no", 0): (0.75, 3.53429173528852, 0.75, 1.76714586764426),
    ("1.5", 0, "scale no mass no", 0): (0.75, 1.0471975511966, 0.75, 4.18879020478639),
    ("1.5", 0, "scale no reset yes", 0): (0.5, 1.0471975511966, 1.0, 4.18879020478639),
    ("1.5", 0, "scale no reset yes", 1): (0.5, 1.0471975511966, 1.0, 4.18879020478639),
    ("1+step", 1, "scale yes", 3): (2.0, 67.0206432765822, 4.0, 268.082573106329),
    ("1+step", 1, "scale no", 3): (2.0, 67.0206432765822, 2.0, 33.5103216382911),
    ("1+step", 2, "scale no", 3): (1.5, 28.2743338823081, 1.5, 14.1371669411541),
}

LIGGGHTS_SCENE = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region b block 0 5 0 5 0 5 units box
create_box 1 b
create_atoms 1 single 1 1 1 units box
create_atoms 1 single 3 3 3 units box
set atom 1 diameter 1.0 density 2.0
set atom 2 diameter 2.0 density 1.0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.001
variable d equal {expr}
compute rad all property/atom radius
variable da atom 1.1*2*c_rad
fix a all adapt {every} atom diameter {variable} {keywords}
fix n all nve/sphere
run {steps}
"""

# (expr, N, variable and keywords, steps) -> (radius 1, mass 1, radius 2, mass 2), LIGGGHTS's write_dump
# (the masses as its equal-style mass[i] printed them)
LIGGGHTS = {
    ("1.5", 0, "v_d scale no", 0): (0.75, 3.53429173528852, 0.75, 1.76714586764426),
    ("1.5", 0, "v_d reset yes", 1): (0.75, 3.53429173528852, 0.75, 1.76714586764426),
    ("1+step", 2, "v_d", 3): (1.5, 28.2743338823081, 1.5, 14.1371669411541),
    ("1", 1, "v_da", 3): (0.73205, 3.28655451070815, 1.4641, 13.1462180428326),
    ("1", 0, "v_da", 3): (0.55, 1.39381994064267, 1.1, 5.57527976257069),
    ("1", 1, "v_da scale yes", 0): (0.55, 1.39381994064267, 2.2, 44.6022381005655),
}


def radii_and_masses(sim):
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    r, m = p.radius[:p.nlocal][order], p.rmass[:p.nlocal][order]
    return float(r[0]), float(m[0]), float(r[1]), float(m[1])


@pytest.mark.parametrize("case", list(LAMMPS), ids=lambda c: " ".join(map(str, c)))
def test_radii_and_masses_as_lammps(make_sim, case):
    expr, every, keywords, steps = case
    sim = make_sim(dialect="lammps")
    sim.command(LAMMPS_SCENE.format(expr=expr, every=every, keywords=keywords, steps=steps))
    np.testing.assert_allclose(radii_and_masses(sim), LAMMPS[case], rtol=1e-13)


@pytest.mark.parametrize("case", list(LIGGGHTS), ids=lambda c: " ".join(map(str, c)))
def test_radii_and_masses_as_liggghts(make_sim, case):
    """LIGGGHTS's scale yes with an atom-style variable multiplies the current diameter by the value
    (here 1.1 x 2 r: r' = 2.2 r^2, again at every adaptation); its dump writes radii to 6 digits."""
    expr, every, words, steps = case
    variable, _, keywords = words.partition(" ")
    sim = make_sim(dialect="liggghts")
    sim.command(LIGGGHTS_SCENE.format(expr=expr, every=every, variable=variable, keywords=keywords, steps=steps))
    got = radii_and_masses(sim)
    want = LIGGGHTS[case]
    for g, w, what in zip(got, want, ("radius 1", "mass 1", "radius 2", "mass 2")):
        assert g == pytest.approx(w, rel=1e-5 if what.startswith("radius") else 1e-12), what


def test_growing_spheres_find_every_contact(tmp_path, monkeypatch):
    """Spheres at rest on a periodic lattice 1 apart grow from radius 0.3 to 0.6 in one run (every 10
    steps): the lists, sized for 0.3 (cutoff 0.6 + skin 0.1 reaches no neighbour), must follow them.
    The lattice's 3 x 64 bonds touch from the adaptation at step 670 on (2 r = 0.6 + 0.6 x 670/1000
    > 1), no diagonal ever does (2 r < 1.414), and nothing moves by symmetry: the pair's contacts,
    printed every 10 steps, are 0 up to step 660 and 192 from 670 on."""
    monkeypatch.chdir(tmp_path)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="liggghts")
    sim.command("""
        atom_style granular
        atom_modify map array
        boundary p p p
        newton off
        communicate single vel yes
        units si
        lattice sc 1.0
        region b block 0 4 0 4 0 4
        create_box 1 b
        create_atoms 1 box
        set group all diameter 0.6 density 1000
        neighbor 0.1 bin
        fix m1 all property/global youngsModulus peratomtype 5.e6
        fix m2 all property/global poissonsRatio peratomtype 0.45
        fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
        fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
        pair_style gran model hertz tangential history
        pair_coeff * *
        timestep 0.00001
        variable d equal 0.6+0.6*step/1000
        fix grow all adapt 10 atom diameter v_d
        fix n all nve/sphere
        compute c all pair/contact
        thermo_style custom step c_c
        thermo 10
        run 1000
    """)
    rows = [line.split() for line in screen.getvalue().splitlines()]
    contacts = {int(r[0]): float(r[1]) for r in rows if len(r) == 2 and r[0].isdigit()}
    assert len(contacts) == 101
    assert all(c == (192 if step >= 670 else 0) for step, c in contacts.items()), contacts
    assert sim.particles.radius[:64] == pytest.approx(0.6)


@pytest.mark.parametrize("dialect, script, message", [
    ("lammps", "variable d atom 2*radius\nfix a all adapt 1 atom diameter v_d\nrun 0",
     "fix a (adapt): variable d is atom-style; fix adapt takes equal-style variables (LAMMPS)"),
    ("liggghts", "variable d equal 1.1\nfix a all adapt 1 atom diameter v_d scale yes\nrun 0",
     "fix a (adapt): scale yes with equal-style variable d: LIGGGHTS 3.8.0 multiplies each particle's value "
     "into the next one's, so its result depends on the particle order; use an atom-style variable (v x 2*c_rad)"),
    ("lammps", "variable d equal 1\nfix a all adapt 1 pair lj/cut epsilon 1 1 v_d",
     "fix adapt pair lj/cut: the pair style is zero, not lj/cut"),
    ("lammps", "variable d equal 1\npair_style soft 1.0\npair_coeff * * 1.0\nfix a all adapt 1 pair soft b 1 1 v_d",
     "fix adapt pair soft: b is not a coefficient fix adapt can change (it can: a)"),
    ("lammps", "variable d atom x\npair_style soft 1.0\npair_coeff * * 1.0\nfix a all adapt 1 pair soft a * * v_d\n"
               "run 0", "fix a (adapt): variable d is atom-style; fix adapt pair takes equal-style variables"),
    ("liggghts", "variable d equal 1\nfix a all adapt 1 pair gran kn 1 1 v_d",
     "fix adapt pair (a pair coefficient changed in time) is not in pdps for LIGGGHTS: set the coefficient between "
     "runs instead"),
    ("liggghts", "variable d equal 1\nfix a all adapt 1 atom diameter v_d mass no",
     "fix adapt mass is LAMMPS's keyword; LIGGGHTS always keeps the density"),
    ("lammps", "variable d equal 1\nfix a all adapt 1 atom diameter/disc v_d",
     "fix adapt atom diameter/disc needs a 2-d simulation (as LAMMPS)"),
    ("lammps", "variable d equal 1\nfix a all adapt 1 v_d", "unknown keyword v_d (known: scale, reset, mass, atom, pair, bond, kspace)"),
    ("lammps", "fix a all adapt 1", "fix adapt needs an attribute to change"),
])
def test_refused(make_sim, dialect, script, message):
    sim = make_sim(dialect=dialect)
    scene = LAMMPS_SCENE if dialect == "lammps" else LIGGGHTS_SCENE
    setup = scene.split("variable d equal")[0]
    sim.command(setup + ("pair_style zero 3.0\npair_coeff * *\n" if dialect == "lammps" else ""))
    with pytest.raises(ScriptError) as error:
        sim.command(script)
    assert message in str(error.value)


def test_a_diameter_that_is_not_positive_is_an_error(make_sim):
    sim = make_sim(dialect="lammps")
    with pytest.raises(Exception) as error:
        sim.command(LAMMPS_SCENE.format(expr="1-step", every=1, keywords="", steps=3))
    assert "fix a (adapt) at step 1: particle 1 gets diameter 0; a diameter must be a finite number > 0" \
        in str(error.value)


# fix adapt pair: LAMMPS 22 Jul 2025's thermo on this machine for PAIR_SOFT (an explicit pair ramped
# every step, a diagonal one scaled every 5, reset no: the values stay for the next run) and PAIR_LJ
# (epsilon of every pair, mixed ones too, scaled every 2 steps with reset yes; sigma ramped, reset no)
PAIR_SOFT = """units lj
atom_style atomic
lattice fcc 0.9
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
region half block 0 2 INF INF INF INF
set region half type 2
mass * 1.0
velocity all create 1.0 87287 loop geom
pair_style soft 1.12246
pair_coeff 1 1 1.0
pair_coeff 2 2 2.0
pair_coeff 1 2 0.5 1.0
variable prefactor equal ramp(1.0,20.0)
fix 1 all nve
fix 3 all adapt 1 pair soft a 1 2 v_prefactor
fix 4 all adapt 5 pair soft a 2 2 v_prefactor scale yes
thermo_style custom step temp pe press v_prefactor
thermo 20
run 100
unfix 3
unfix 4
run 20
"""
PAIR_SOFT_LAMMPS = [
    [0, 1, 0, 0.89648438, 1],
    [20, 0.78080599, 0.46801507, 2.9422226, 4.8],
    [40, 0.69707895, 1.0653386, 5.3867587, 8.6],
    [60, 0.8808257, 1.1423534, 6.2181527, 12.4],
    [80, 1.0751548, 1.0855603, 6.6551012, 16.2],
    [100, 1.281341, 0.93266661, 6.1417393, 20],
    [100, 1.281341, 0.93266661, 6.1417393, 1],
    [120, 1.2585258, 0.96733245, 5.6213161, 20],
]
PAIR_LJ = """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
region half block 0 2 INF INF INF INF
set region half type 2
mass * 1.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_modify shift yes
pair_coeff 1 1 1.0 1.0
pair_coeff 2 2 0.8 1.05
variable eps equal 1.0+0.5*sin(2*PI*elapsed/60)
variable sig equal ramp(1.0,0.95)
fix 1 all nve
fix 3 all adapt 2 pair lj/cut epsilon * * v_eps scale yes reset yes
fix 4 all adapt 1 pair lj/cut sigma 1 1 v_sig
thermo_style custom step temp pe press v_eps v_sig
thermo 20
run 100
unfix 3
unfix 4
run 20
"""
PAIR_LJ_LAMMPS = [
    [0, 1.5, -5.9256701, -2.916936, 1, 1],
    [20, 0.64726867, -7.0779901, 1.2292975, 1.4330127, 0.99],
    [40, 0.62372368, -2.7208149, 0.94089518, 0.5669873, 0.98],
    [60, 0.57098772, -4.595335, 1.9583493, 1, 0.97],
    [80, 0.8797208, -7.1134197, -0.15852162, 1.4330127, 0.96],
    [100, 0.71786498, -2.6581939, 0.80077206, 0.5669873, 0.95],
    [100, 0.71786498, -4.6882777, 0.95131243, 1, 1],
    [120, 0.75036974, -4.7369289, 0.87943969, 1.4330127, 0.95],
]


@pytest.mark.parametrize("script, lammps", [(PAIR_SOFT, PAIR_SOFT_LAMMPS), (PAIR_LJ, PAIR_LJ_LAMMPS)],
                         ids=["soft", "lj_cut"])
def test_adapted_pair_coefficients_give_lammps_thermo(tmp_path, script, lammps):
    assert_prints_as_lammps(tmp_path, script, lammps)

