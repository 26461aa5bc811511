"""Computes ke, msd, com, reduce, property/atom and pair/contact against values worked out in the
tests from the particle state:

    KE = 1/2 sum m v^2,   msd of free flight = (v t)^2 per axis,   x_cm = sum m x_u / sum m,
    overlap = R_i + R_j - r,   contact point x_i - (R_i - overlap/2) n on the segment between centres.
"""

import math

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, Simulation, registry
from pdps_core.testing import make_box, register_styles, run_ranks


def make(setup, boundary="p p p", box="0 10 0 10 0 10", ntypes=1, style="atomic"):
    return make_box(setup, box=box, boundary=boundary, ntypes=ntypes, particle_style=style)


def _mixed(seed=3):
    """Two types of different masses on a lattice, random velocities; group heavy = type 2."""
    rng = np.random.default_rng(seed)
    sim = make("mass 1 1.0\nmass 2 3.0\nlattice spacing x 2 y 2 z 2\ncreate_particle 1 box", ntypes=2)
    sim.type[1::3] = 2
    sim.command("group heavy type 2")
    sim.v[:] = rng.normal(size=sim.v.shape)
    sim.x[:] += rng.uniform(-0.5, 0.5, size=sim.x.shape)
    return sim, np.where(sim.type == 2, 3.0, 1.0)


# ---- ke -----------------------------------------------------------------------------------------
def test_ke_is_the_unnormalised_sum_of_half_m_v_squared_and_per_atom_too():
    sim, m = _mixed()
    sim.command("compute k all ke\ncompute kh heavy ke")
    per_atom = 0.5 * m * (sim.v ** 2).sum(axis=1)
    heavy = sim.type == 2
    assert sim.compute_value("k") == pytest.approx(per_atom.sum(), rel=1e-13)
    assert sim.compute_value("kh") == pytest.approx(per_atom[heavy].sum(), rel=1e-13)
    # the thermo keyword ke is per particle in lj units: the compute is not
    assert sim.compute_value("k") == pytest.approx(len(m) * sim.variables.evaluate("ke"), rel=1e-13)
    np.testing.assert_allclose(sim.computes["k"].peratom(sim), per_atom, rtol=1e-14)
    np.testing.assert_allclose(sim.computes["kh"].peratom(sim), np.where(heavy, per_atom, 0.0), rtol=1e-14)


# ---- msd ----------------------------------------------------------------------------------------
def _ballistic(extra=""):
    """Free particles crossing periodic faces many times (tags 2 and 4 of type 2); returns
    (sim, velocities in tag order)."""
    sim = make(f"""
        mass * 2.0
        create_particle 1 single 0.5 0.5 0.5
        create_particle 2 single 3.5 1.0 2.0
        create_particle 1 single 2.0 3.0 1.0
        create_particle 2 single 1.0 2.0 3.5
        group two type 2
        {extra}
        fix 1 all nve
        timestep 0.01
    """, box="0 4 0 4 0 4", ntypes=2)
    v = np.array([[7.3, -5.1, 3.3], [-2.0, 0.5, 9.0], [0.0, 4.4, -6.1], [1.5, -8.0, 0.25]])
    sim.v[:] = v
    return sim, v


def test_msd_of_free_flight_is_v_t_squared_across_periodic_faces():
    sim, v = _ballistic()
    sim.command("compute m all msd\nrun 300")
    t = 300 * 0.01
    expected = (v * t) ** 2
    assert np.abs(v * t).max() > 5 * 4.0            # many box lengths crossed
    msd = sim.computes["m"].vector(sim)
    np.testing.assert_allclose(msd[:3], expected.mean(axis=0), rtol=1e-10)
    assert msd[3] == pytest.approx(expected.sum(axis=1).mean(), rel=1e-10)
    assert sim.compute_value("m", (3,)) == msd[3]


class Orders(Fix):
    """Every distinct order of the owned particles seen at the end of a step."""
    name = "test/orders"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.seen = set()

    def end_of_step(self, sim):
        self.seen.add(tuple(sim.tag.tolist()))


def test_msd_origins_follow_their_particles_through_resorting():
    sim, v = _ballistic("""
        atom_modify sort 1 0.0
        neigh_modify every 1 delay 0 check no
        pair_style dpd 0.0 1.0 5
        pair_coeff * * 0.0 0.0
    """)
    register_styles(Orders)
    sim.command("compute m all msd\nfix o all test/orders\nrun 150")
    assert len(sim.fixes["o"].seen) > 2, "the particles were never re-sorted"
    msd = sim.computes["m"].vector(sim)
    np.testing.assert_allclose(msd[:3], ((v * 1.5) ** 2).mean(axis=0), rtol=1e-10)


def test_msd_of_a_group_counts_from_its_definition_and_survives_a_restart(tmp_path):
    sim, v = _ballistic()
    sim.command("run 50\ncompute m two msd\nrun 100")
    expected = (v[[1, 3]] * 1.0) ** 2                # tags 2 and 4, over the last 100 steps
    msd = sim.computes["m"].vector(sim)
    np.testing.assert_allclose(msd[:3], expected.mean(axis=0), rtol=1e-10)
    sim.command(f"write_restart {tmp_path / 'msd.restart'}")
    again = Simulation(screen=False, log=None)
    again.command(f"read_restart {tmp_path / 'msd.restart'}")
    np.testing.assert_array_equal(again.computes["m"].vector(again), msd)
    again.command("compute fresh all msd")
    assert again.computes["fresh"].vector(again).tolist() == [0.0] * 4


def test_a_particle_created_after_the_msd_counts_from_its_first_reading():
    sim, v = _ballistic("compute m all msd")
    sim.command("create_particle 1 single 2 2 2")
    sim.v[4] = [1.0, 0.0, 0.0]
    assert sim.computes["m"].vector(sim).tolist() == [0.0] * 4
    sim.command("run 100")
    expected = np.vstack([v, [1.0, 0.0, 0.0]]) ** 2
    np.testing.assert_allclose(sim.computes["m"].vector(sim)[:3], expected.mean(axis=0), rtol=1e-10)


# ---- com ----------------------------------------------------------------------------------------
def test_com_of_two_masses_is_mass_weighted_and_unwrapped():
    sim = make("mass 1 1.0\nmass 2 3.0\ncreate_particle 1 single 9.5 1 2\ncreate_particle 2 single 0.5 5 2\n"
               "group two type 2\ncompute cm all com\ncompute c1 two com", ntypes=2)
    # particle 2 has crossed the x face once: its unwrapped x is 10.5, one unit from particle 1
    sim.particles.image[1] = [1, 0, -1]
    expected = (1.0 * np.array([9.5, 1, 2]) + 3.0 * np.array([10.5, 5, 2 - 10])) / 4.0
    np.testing.assert_allclose(sim.computes["cm"].vector(sim), expected, rtol=1e-14)
    assert sim.compute_value("cm", (0,)) == pytest.approx(10.25)
    np.testing.assert_allclose(sim.computes["c1"].vector(sim), [10.5, 5, -8], rtol=1e-14)


# ---- reduce and property/atom -------------------------------------------------------------------
def test_reduce_sum_min_max_ave_of_positions_and_of_property_atom_columns():
    sim, m = _mixed()
    sim.command("compute p all property/atom mass vz\ncompute ph heavy property/atom vz")
    heavy = sim.type == 2
    x, vz = sim.x[:, 0], sim.v[:, 2]
    expected = {"sum": np.sum, "min": np.min, "max": np.max, "ave": np.mean}
    for mode, reduce in expected.items():
        sim.command(f"compute x_{mode} all reduce {mode} x\ncompute h_{mode} heavy reduce {mode} x c_p[0] c_p[1]")
        assert sim.compute_value(f"x_{mode}") == pytest.approx(reduce(x), rel=1e-13)
        np.testing.assert_allclose(sim.computes[f"h_{mode}"].vector(sim),
                                   [reduce(x[heavy]), reduce(m[heavy]), reduce(vz[heavy])], rtol=1e-13)
    assert sim.compute_value("h_max", (1,)) == 3.0 and sim.compute_value("h_min", (1,)) == 3.0
    # a referenced compute's own group applies too: outside it, its values are 0
    sim.command("compute heavy_vz all reduce sum c_ph")
    assert sim.compute_value("heavy_vz") == pytest.approx(vz[heavy].sum(), rel=1e-13)
    # any property/atom attribute is an input too
    sim.command("compute mbar all reduce ave mass")
    assert sim.compute_value("mbar") == pytest.approx(m.mean(), rel=1e-14)


def test_reduce_of_an_empty_group_is_lammps_s():
    sim = make("mass 1 1\ncreate_particle 1 single 1 1 1\nregion far block 5 6 5 6 5 6\n"
               "group none region far\ncompute r none reduce max x vx\ncompute s none reduce min x\n"
               "compute a none reduce ave x\ncompute t none reduce sum x")
    assert sim.computes["r"].vector(sim).tolist() == [-1e20, -1e20]
    assert [sim.computes[c].vector(sim).tolist() for c in "sat"] == [[1e20], [0.0], [0.0]]


def test_property_atom_values_and_their_dump_read_back(tmp_path):
    sim = make("""
        create_particle 1 single 1.0 2.0 3.0 diameter 1.0 density 2
        create_particle 2 single 9.6 5.0 5.0 diameter 0.6 density 1
        create_particle 1 single 4.0 8.0 0.5 diameter 0.8 density 3
        group big type 1
    """, ntypes=2, style="sphere")
    rng = np.random.default_rng(1)
    sim.v[:] = rng.normal(size=(3, 3))
    sim.particles.omega[:3] = rng.normal(size=(3, 3))
    sim.particles.image[2] = [0, -2, 1]
    sim.command(f"""
        compute p all property/atom id type mass xu yu zu vz radius diameter omegaz iy
        compute r big property/atom radius
        dump 1 all custom 1 {tmp_path / 'p.dump'} id c_p[0] c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6] c_p[7] c_p[8] c_p[9] c_p[10] c_r
        run 0
    """)
    p = sim.particles
    unwrapped = sim.x + p.image[:3] * 10.0
    expected = np.column_stack([sim.tag, sim.type, p.rmass[:3], unwrapped, sim.v[:, 2], p.radius[:3],
                                2 * p.radius[:3], p.omega[:3, 2], p.image[:3, 1]])
    np.testing.assert_array_equal(sim.computes["p"].peratom(sim), expected)
    assert expected[2, 4] == 8.0 - 20.0 and expected[1, 2] == pytest.approx(math.pi / 6 * 0.6 ** 3)
    np.testing.assert_array_equal(sim.computes["r"].peratom(sim), np.where(sim.type == 1, p.radius[:3], 0))
    lines = (tmp_path / "p.dump").read_text().splitlines()
    assert lines[8].split()[2:] == ["id"] + [f"c_p[{k}]" for k in range(11)] + ["c_r"]
    table = np.array([[float(w) for w in line.split()] for line in lines[9:]])
    order = np.argsort(sim.tag)
    np.testing.assert_allclose(table[:, 1:12], expected[order], rtol=1e-9)
    assert (table[:, 0] == table[:, 1]).all()


# ---- pair/contact -------------------------------------------------------------------------------
KN = 1000.0


class ReportingLsd:
    """dem/lsd whose contact table (what pair/contact reads) is written here, for spheres 1 and 2
    touching and no other contact: the contact force on each is its total force. It lists the
    larger tag first, so pair/contact must turn the reaction round."""
    name = "test/dem/lsd_reporting"

    def contacts(self, sim, group="all"):
        first, second = sim.particles.index_of_tag(1), sim.particles.index_of_tag(2)
        return {"i": np.array([second]), "j": np.array([first]), "force": sim.f[[second]]}


def _two_spheres(x1, x2, d1=1.0, d2=1.4, pair="dem/lsd 0.5 1.0", group="all", box="0 10 0 10 0 10"):
    sim = make(f"""
        create_particle 1 single {x1[0]} {x1[1]} {x1[2]} diameter {d1} density 1
        create_particle 1 single {x2[0]} {x2[1]} {x2[2]} diameter {d2} density 1
        create_particle 1 single 5 5 5 diameter 1 density 1
        region left block 0 2 INF INF INF INF
        group left region left
        pair_style {pair}
        pair_coeff * * {KN} 0 300 0 0.5
        compute c {group} pair/contact
        run 0
    """, box=box, style="sphere")
    return sim


@pytest.mark.parametrize("x1, x2", [
    ([2.0, 3.0, 4.0], [3.1, 3.2, 4.1]),
    ([9.7, 0.2, 4.0], [0.6, 9.9, 4.3]),         # across the x and y faces
])
def test_pair_contact_rows_of_two_touching_spheres(x1, x2):
    sim = _two_spheres(x1, x2)
    rows = sim.computes["c"].array(sim)
    assert rows.shape == (1, 9)
    x1, x2 = np.array(x1), np.array(x2)
    delta = (x1 - x2 + 5.0) % 10.0 - 5.0            # nearest image, from 2 to 1
    r = np.linalg.norm(delta)
    assert rows[0, :2].tolist() == [1.0, 2.0]
    assert rows[0, 2] == pytest.approx(0.5 + 0.7 - r, rel=1e-13)
    assert sim.compute_value("c") == 1.0
    assert sim.compute_value("c", (0, 2)) == rows[0, 2]
    # the contact point lies between the centres, R_i - overlap/2 from particle 1
    point = rows[0, 6:]
    from_1 = (point - x1 + 5.0) % 10.0 - 5.0
    from_2 = (point - x2 + 5.0) % 10.0 - 5.0
    overlap = rows[0, 2]
    assert np.linalg.norm(from_1) == pytest.approx(0.5 - overlap / 2, rel=1e-12)
    assert np.linalg.norm(from_2) == pytest.approx(0.7 - overlap / 2, rel=1e-12)
    np.testing.assert_allclose(np.cross(from_1, delta), 0.0, atol=1e-13)
    assert ((point >= 0.0) & (point < 10.0)).all()
    # resting spheres, no spring yet: the force on 1 is kn * overlap along the normal from 2 to 1,
    # as dem/lsd computed it (its contact table)
    np.testing.assert_allclose(rows[0, 3:6], KN * overlap * delta / r, rtol=1e-12)
    assert not any("pair/contact" in w for w in sim.warnings)


def test_pair_contact_force_from_a_pair_that_reports_it():
    lsd = registry.lookup("pair", "dem/lsd")
    register_styles(type("Reporting", (ReportingLsd, lsd), {}))
    sim = _two_spheres([3.0, 3.0, 3.0], [3.9, 3.3, 3.0], pair=f"{ReportingLsd.name} 0.5 1.0")
    rows = sim.computes["c"].array(sim)
    delta = np.array([-0.9, -0.3, 0.0])
    r = np.linalg.norm(delta)
    # at rest, no damping: F on 1 = kn * overlap * n, n from 2 to 1
    np.testing.assert_allclose(rows[0, 3:6], KN * (1.2 - r) * delta / r, rtol=1e-12)
    assert not sim.warnings


def test_pair_contact_counts_pairs_inside_its_group_only():
    sim = _two_spheres([1.0, 3.0, 3.0], [2.1, 3.0, 3.0], group="left")
    assert sim.computes["c"].array(sim).shape == (0, 9)
    assert sim.compute_value("c") == 0.0
    sim = _two_spheres([1.0, 3.0, 3.0], [1.9, 3.0, 3.0], group="left")
    assert sim.compute_value("c") == 1.0


# ---- thermo, variables, ave/time ----------------------------------------------------------------
def test_values_read_from_thermo_variables_and_ave_time(tmp_path):
    sim, v = _ballistic()
    sim.command(f"""
        compute k all ke
        compute m all msd
        compute cm all com
        compute r all reduce max vx vy
        variable e equal c_k*2
        thermo_style custom step c_k c_m[3] c_cm[0] c_r[1] v_e
        analyze a all ave/time 10 1 10 c_k c_m[3] c_r[0] file {tmp_path / 'ave.txt'}
        run 20
    """)
    ke = 0.5 * 2.0 * (v ** 2).sum()
    thermo = sim.output.thermo.values()
    # thermo prints the extensive c_k per particle in lj units, as LAMMPS; the variable reads the total
    assert thermo[1] == pytest.approx(ke / sim.nlocal, rel=1e-13)
    assert thermo[2] == pytest.approx(((v * 0.2) ** 2).sum(axis=1).mean(), rel=1e-10)
    assert thermo[4] == v[:, 1].max() and thermo[5] == pytest.approx(2 * ke, rel=1e-13)
    last = (tmp_path / "ave.txt").read_text().splitlines()[-1].split()
    assert int(last[0]) == 20
    np.testing.assert_allclose([float(w) for w in last[1:]],
                               [ke, ((v * 0.2) ** 2).sum(axis=1).mean(), v[:, 0].max()], rtol=1e-5)


# ---- one-line errors ----------------------------------------------------------------------------
@pytest.mark.parametrize("line, words", [
    ("compute r all reduce sum q", ("unknown input q",)),
    ("compute r all reduce median x", ("mode must be one of",)),
    ("compute r all reduce sum c_nope", ("compute nope is not defined",)),
    ("compute t all temp\ncompute r all reduce sum c_t", ("compute t (temp) has no per-atom values",)),
    ("compute r all reduce sum f_none[0]", ("fix none is not defined",)),
    ("compute p all property/atom x charge", ("unknown attribute charge",)),
    ("compute p all property/atom radius", ("needs per-particle radius",)),
    ("compute p all property/atom", ("attributes",)),
    ("compute c all pair/contact\nrun 0", ("needs a granular pair style",)),
])
def test_bad_inputs_give_one_line_errors(line, words):
    sim = make("mass 1 1\ncreate_particle 1 single 1 1 1\nfix 1 all nve")
    with pytest.raises(ScriptError) as error:
        sim.command(line)
        sim.compute_value("c")
    message = str(error.value)
    assert "\n" not in message
    for word in words:
        assert word in message


@pytest.mark.parametrize("read, words", [
    (lambda sim: sim.compute_value("p"), ("per-atom values only", "dump custom")),
    (lambda sim: sim.compute_value("r2"), ("reduces 2 inputs", "c_r2[k]")),
    (lambda sim: sim.compute_value("r2", (2,)), ("out of range",)),
    (lambda sim: sim.compute_value("r1"), ("c_p", "has 2 values per particle")),
    (lambda sim: sim.compute_value("k1"), ("c_k[0]", "one value per particle")),
    (lambda sim: sim.compute_value("c"), ("run first",)),
])
def test_bad_readings_give_one_line_errors(read, words):
    sim = make("""
        mass 1 1
        create_particle 1 single 1 1 1
        compute p all property/atom x y
        compute k all ke
        compute r2 all reduce sum x y
        compute r1 all reduce sum c_p
        compute k1 all reduce sum c_k[0]
        pair_style dem/lsd 0.5 1.0
        compute c all pair/contact
    """)
    with pytest.raises(ScriptError) as error:
        read(sim)
    assert "\n" not in str(error.value)
    for word in words:
        assert word in str(error.value)


# ---- the same numbers on any number of ranks ----------------------------------------------------
def test_values_agree_on_1_and_3_ranks(tmp_path):
    script = """
        particle_style sphere
        region box block 0 6 0 6 0 6
        create_box 1 box
        lattice spacing x 0.95 y 0.95 z 0.95
        region inner block 0.5 5.5 0.5 5.5 0.5 5.5
        create_particle 1 region inner diameter 1.0 density 1
        velocity all create 0.5 4
        pair_style dem/lsd 0.5 1.0
        pair_coeff * * 1000 5 300 2 0.5
        fix 1 all nve/sphere
        timestep 0.001
        compute k all ke
        compute m all msd
        compute cm all com
        compute p all property/atom vx radius
        compute r all reduce max c_p[0] x
        compute c all pair/contact
        variable n equal c_c
        thermo 20
        thermo_style custom step c_k c_m[3] c_cm[0] c_r[0] c_r[1] c_c v_n
        dump 1 all custom 40 dump.txt id c_k c_p[0] v_n
        run 40
    """
    outputs = {}
    for ranks in (1, 3):
        result = run_ranks(script, ranks, tmp_path)
        outputs[ranks] = ([line for line in result.stdout.splitlines() if line.strip()[:1].isdigit()],
                          (tmp_path / "dump.txt").read_text())
    lines = outputs[1][0]
    assert len(lines) == 3 and float(lines[-1].split()[6]) > 10     # contacts were made
    assert outputs[1] == outputs[3]



# LAMMPS 22 Jul 2025 on this machine (2026-12-02): three particles in free flight through the
# periodic box, write_dump id c_d[1] c_d[2] c_d[3] c_d[4] after 300 steps (%.17g)
DISPLACE_SCENE = """
units lj
atom_style atomic
atom_modify map array
region b block 0 4 0 4 0 4
create_box 2 b
create_atoms 1 single 0.5 0.5 0.5
create_atoms 1 single 3.5 2 1
create_atoms 2 single 2 3.9 2
mass * 1.0
velocity all set 1.5 -0.5 0.25
set atom 2 vx -2.0
group one type 1
compute d one displace/atom
pair_style zero 1.0
pair_coeff * *
fix n all nve
timestep 0.01
run 300
"""
LAMMPS_DISPLACE = [[4.5000000000000089, -1.4999999999999796, 0.74999999999998401, 4.8023431780746364],
                   [-6.0000000000000053, -1.4999999999999791, 0.74999999999998401, 6.2299678971885548],
                   [0.0, 0.0, 0.0, 0.0]]


def test_displace_atom_as_lammps(make_sim):
    """Displacements through periodic faces (particle 2 crosses x's twice), 0 outside the group."""
    sim = make_sim(dialect="lammps")
    sim.command(DISPLACE_SCENE)
    got = sim.computes["d"].peratom(sim)[np.argsort(sim.tag)]
    np.testing.assert_allclose(got, LAMMPS_DISPLACE, rtol=1e-12, atol=1e-12)


# LAMMPS 22 Jul 2025 on this machine (2026-12-02): the 200-particle LJ fluid (data/fluid.data, a copy of
# pair_simple's),
# thermo c_g c_g[1..6] c_gh at steps 0, 50 and 100 (%.15g)
LAMMPS_GYRATION = {
    0: [3.43603972084366, 4.0684047361253, 3.95757061726004, 3.78039360983005, 0.121844168354014,
        0.0712035743977002, 0.215614937840547, 3.39337125328323],
    50: [3.4383627119583, 4.00837515620234, 3.96676588054066, 3.84719710224223, 0.109760555200372,
         0.0901221015121369, 0.197428893487648, 3.37435721594893],
    100: [3.47460686210146, 3.95325828923053, 4.07919668360248, 4.04043787332957, 0.099482293157871,
          0.118436058349414, 0.152977887274755, 3.39396981966377],
}


def test_gyration_as_lammps(make_sim, tmp_path):
    import shutil
    from pathlib import Path
    shutil.copy(Path(__file__).parent / "data" / "fluid.data", tmp_path)        # pair_simple's fluid
    sim = make_sim(dialect="lammps")
    sim.command("""
        units lj
        atom_style atomic
        read_data fluid.data
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0
        pair_coeff 2 2 0.5 1.2
        fix 1 all nve
        timestep 0.002
        group heavy type 2
        compute g all gyration
        compute gh heavy gyration
    """)
    for step, want in LAMMPS_GYRATION.items():
        sim.command(f"run {step - sim.step}")
        got = [sim.computes["g"].scalar(sim), *sim.computes["g"].vector(sim), sim.computes["gh"].scalar(sim)]
        np.testing.assert_allclose(got, want, rtol=1e-11, atol=1e-14)


# LAMMPS 22 Jul 2025 on this machine (2026-12-02): the LJ fluid, thermo c_r[1] c_r[2] c_rh c_ra (%.15g;
# sums normalised by the particle count, lj units)
LAMMPS_REDUCE_REGION = {
    0: [0.0361733642655205, 0.820157565259583, 6.78316123266861, 0.0306519397266706],
    50: [-0.0303736445555825, 2.18599421684209, 6.70444412453224, -0.407478846060602],
    100: [-0.0570353952912507, 2.18885201438692, 6.84880433045804, -0.435564762743085],
}


def test_reduce_region_as_lammps(pdps_cli, tmp_path):
    import shutil
    from pathlib import Path
    shutil.copy(Path(__file__).parent / "data" / "fluid.data", tmp_path)
    done = pdps_cli("""
        units lj
        atom_style atomic
        read_data fluid.data
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0
        pair_coeff 2 2 0.5 1.2
        fix 1 all nve
        timestep 0.002
        group heavy type 2
        region low block INF INF INF INF INF 3 units box
        compute k all ke/atom
        compute r all reduce/region low sum vx c_k
        compute rh heavy reduce/region low max x
        compute ra all reduce/region low ave vz
        thermo 50
        thermo_style custom step c_r[1] c_r[2] c_rh c_ra
        thermo_modify format float %.15g
        run 100
    """, "-log", "none")
    assert done.returncode == 0, done.stderr
    rows = {int(w[0]): [float(v) for v in w[1:]] for w in (line.split() for line in done.stdout.splitlines())
            if len(w) == 5 and w[0].isdigit()}
    for step, want in LAMMPS_REDUCE_REGION.items():
        np.testing.assert_allclose(rows[step], want, rtol=1e-12, atol=1e-15)


# LAMMPS 22 Jul 2025 on this machine (2026-12-02): the LJ fluid, thermo c_ng[1] c_ng[2] c_ng[3] c_nh[1]
# c_nh[3] (%.15g); at step 0 LAMMPS prints -nan for c_ng[3] (0/0), pdps 0
LAMMPS_NONGAUSS = {
    50: [0.051451283509984, 0.00458766259040931, 0.0398011496309532, 0.057269180484046, -0.0311300241808271],
    100: [0.170571305438585, 0.0467089258173342, -0.0367496319704574, 0.187492911406334, -0.020961884618936],
}


def test_msd_nongauss_as_lammps(make_sim, tmp_path):
    import shutil
    from pathlib import Path
    shutil.copy(Path(__file__).parent / "data" / "fluid.data", tmp_path)
    sim = make_sim(dialect="lammps")
    sim.command("""
        units lj
        atom_style atomic
        read_data fluid.data
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0
        pair_coeff 2 2 0.5 1.2
        fix 1 all nve
        timestep 0.002
        group heavy type 2
        compute ng all msd/nongauss
        compute nh heavy msd/nongauss com yes
    """)
    assert sim.computes["ng"].vector(sim).tolist() == [0.0, 0.0, 0.0]
    for step, want in LAMMPS_NONGAUSS.items():
        sim.command(f"run {step - sim.step}")
        ng, nh = sim.computes["ng"].vector(sim), sim.computes["nh"].vector(sim)
        np.testing.assert_allclose([*ng, nh[0], nh[2]], want, rtol=1e-11, atol=1e-12)
