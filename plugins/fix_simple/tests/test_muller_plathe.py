"""Fix thermal/conductivity and fix viscosity (Muller-Plathe swaps): one swap conserves total momentum
and kinetic energy exactly (unequal masses too) and moves the particles LAMMPS's rule picks; over
200 steps of a small LJ fluid of two masses, thermo with f_ID as LAMMPS 22 Jul 2025 printed it
(run on this machine 2026-12-07, %.15g); the one-line errors."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import assert_thermo_as_lammps, lammps_thermo, thermo_on_ranks

SCENE = """
units lj
atom_style atomic
region box block 0 4 0 4 0 8
create_box 2 box
mass 1 1.0
mass 2 3.0
"""


def scene(make_sim, rows):
    """Particles (type, x, y, z, vx, vy, vz) in a periodic 4 x 4 x 8 box, no forces."""
    sim = make_sim(dialect="lammps")
    sim.command(SCENE + "".join(f"create_atoms {int(r[0])} single {r[1]} {r[2]} {r[3]}\n" for r in rows))
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    p.v[order] = np.array([r[4:] for r in rows], dtype=float)
    return sim


# slabs of 8 / 4 = 2 along z: the lowest 0-2, the middle 4-6
PARTICLES = [
    (1, 1, 1, 0.5, 0.3, -2.0, 0.1),     # lowest slab, hottest (KE 2.05)
    (2, 2, 1, 1.5, 0.1, 0.2, 0.9),      # lowest slab, vx 0.1 (KE 1.29)
    (1, 3, 3, 1.0, 1.2, 0.0, 0.0),      # lowest slab, fastest +vx (KE 0.72)
    (2, 1, 2, 4.5, -0.1, 0.1, 0.0),     # middle slab, coldest (KE 0.03)
    (1, 2, 2, 5.0, -1.5, 0.5, 0.5),     # middle slab, fastest -vx (KE 1.375)
    (1, 3, 1, 7.0, 2.0, 2.0, 2.0),      # neither slab
]


def totals(sim):
    p = sim.particles
    m = sim.mass[p.type[:p.nlocal]]
    v = p.v[:p.nlocal]
    return (m[:, None] * v).sum(axis=0), 0.5 * (m * (v * v).sum(axis=1)).sum()


def velocities(sim):
    p = sim.particles
    return p.v[np.argsort(p.tag[:p.nlocal])]


def test_a_heat_swap_is_an_elastic_collision_of_the_hottest_and_the_coldest(make_sim):
    sim = scene(make_sim, PARTICLES)
    momentum, energy = totals(sim)
    before = velocities(sim).copy()
    sim.command("fix 1 all thermal/conductivity 1 z 4\nrun 1")
    after = velocities(sim)
    moved = np.flatnonzero(np.any(after != before, axis=1))
    assert moved.tolist() == [0, 3]
    m0, m3 = 1.0, 3.0
    vcm = (m0 * before[0] + m3 * before[3]) / (m0 + m3)
    np.testing.assert_allclose(after[0], 2 * vcm - before[0], rtol=1e-15)
    np.testing.assert_allclose(after[3], 2 * vcm - before[3], rtol=1e-15)
    got_momentum, got_energy = totals(sim)
    np.testing.assert_allclose(got_momentum, momentum, rtol=0, atol=1e-15)
    assert got_energy == pytest.approx(energy, rel=1e-15)
    # the energy moved: what the hot particle lost
    lost = 0.5 * m0 * (before[0] @ before[0] - after[0] @ after[0])
    assert sim.fixes["1"].scalar(sim) == pytest.approx(lost, rel=1e-14)


def test_a_momentum_swap_pairs_the_fastest_each_way_and_conserves_momentum_and_energy(make_sim):
    sim = scene(make_sim, PARTICLES)
    momentum, energy = totals(sim)
    before = velocities(sim).copy()
    sim.command("fix 1 all viscosity 1 x z 4\nrun 1")
    after = velocities(sim)
    moved = np.flatnonzero(np.any(after != before, axis=1))
    assert moved.tolist() == [2, 4]
    vcm = (before[2, 0] + before[4, 0]) / 2
    assert after[2, 0] == 2 * vcm - before[2, 0] and after[4, 0] == 2 * vcm - before[4, 0]
    np.testing.assert_array_equal(after[:, 1:], before[:, 1:])
    got_momentum, got_energy = totals(sim)
    np.testing.assert_allclose(got_momentum, momentum, rtol=0, atol=1e-15)
    assert got_energy == pytest.approx(energy, rel=1e-15)
    # LAMMPS's sign: the momentum the lowest slab gains
    assert sim.fixes["1"].scalar(sim) == pytest.approx(after[2, 0] - before[2, 0], rel=1e-14)


def test_vtarget_and_swap_pick_the_closest_and_unequal_masses_keep_the_totals(make_sim):
    """vtarget 0.15: the lowest slab's +vx closest to it are 0.1 then 0.3, the middle's -vx closest to
    -0.15 are -0.1 then -1.5 (here of mass 3): swap 2 pairs them in that order."""
    rows = [r if k != 4 else (2, *r[1:]) for k, r in enumerate(PARTICLES)]
    sim = scene(make_sim, rows)
    momentum, energy = totals(sim)
    before = velocities(sim).copy()
    sim.command("fix 1 all viscosity 1 x z 4 vtarget 0.15 swap 2\nrun 1")
    after = velocities(sim)
    assert np.flatnonzero(np.any(after != before, axis=1)).tolist() == [0, 1, 3, 4]
    np.testing.assert_allclose(after[[1, 3], 0], [-0.1, 0.1], rtol=1e-15)
    vcm = (0.3 * 1.0 + 3.0 * -1.5) / 4.0
    np.testing.assert_allclose(after[[0, 4], 0], [2 * vcm - 0.3, 2 * vcm + 1.5], rtol=1e-15)
    got_momentum, got_energy = totals(sim)
    np.testing.assert_allclose(got_momentum, momentum, rtol=0, atol=1e-15)
    assert got_energy == pytest.approx(energy, rel=1e-15)


FLUID = """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 3 0 3 0 6
create_box 2 box
create_atoms 1 box
mass 1 1.0
mass 2 2.0
set group all type/fraction 2 0.25 555
velocity all create 1.4 4711 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0 2.5
fix 1 all nve
fix 3 all thermal/conductivity 5 z 10 swap 2
fix 4 all viscosity 10 x z 12 swap 3 vtarget 1.5
thermo_style custom step temp pe etotal f_3 f_4
thermo_modify format float %.15g
thermo 20
run 200
"""
# LAMMPS 22 Jul 2025's thermo of FLUID: step temp pe etotal f_3 f_4, with swap 2 and swap 3 vtarget 1.5
LAMMPS_SWAPS = [
    ['0', '1.4', '-6.77336805325301', '-4.68309027547523', '0', '0'],
    ['20', '0.619618771659557', '-5.61009664106506', '-4.68497139171225', '20.9424635435997', '-15.2804886256556'],
    ['40', '0.700876968960709', '-5.73685718327122', '-4.69040893100349', '36.3284654279686', '-27.9411065257945'],
    ['60', '0.771495451866652', '-5.84476885176025', '-4.6928832812649', '47.7973741184592', '-40.2448489711529'],
    ['80', '0.766183198701391', '-5.83461419000944', '-4.690660108615', '57.6496181068068', '-52.0257529606558'],
    ['100', '0.747655618680156', '-5.80491169830194', '-4.68862032318921', '64.671161413034', '-61.4535655293323'],
    ['120', '0.785206916503588', '-5.86253844161604', '-4.69018089266971', '75.5009521384642', '-73.3685202558046'],
    ['140', '0.785772846407375', '-5.86566602394718', '-4.69246351021394', '83.1272575958776', '-84.945958183376'],
    ['160', '0.720757015414331', '-5.76582108317227', '-4.68969081710226', '92.0593490759744', '-94.9239753933118'],
    ['180', '0.741825877150928', '-5.79727563930353', '-4.68968839216847', '101.171149264502', '-102.74229301888'],
    ['200', '0.753951264123339', '-5.81723479357928', '-4.6915436700618', '108.429085920341', '-111.943746203974'],
]
# and with one swap each, vtarget INF
LAMMPS_ONE_SWAP = [
    ['0', '1.4', '-6.77336805325301', '-4.68309027547523', '0', '0'],
    ['20', '0.583018639460532', '-5.55594709600841', '-4.68546787736942', '10.9786546436888', '-5.11708138136831'],
    ['40', '0.703565934187631', '-5.74126865436152', '-4.69080562762305', '20.3446422144182', '-11.1159508757944'],
    ['60', '0.795178467890028', '-5.88021117693179', '-4.69296554779043', '32.2273388009436', '-17.4232445685586'],
    ['80', '0.754524413437848', '-5.81975915524355', '-4.69321228795787', '44.0712978117383', '-24.1324395778848'],
    ['100', '0.77004376251226', '-5.83980827899014', '-4.69009016135031', '51.5096252053388', '-29.5262515051238'],
    ['120', '0.794450530149187', '-5.88002345604467', '-4.69386467839137', '58.9792865567585', '-34.1553974181981'],
    ['140', '0.740328532988176', '-5.79612438489491', '-4.69077275578062', '64.0759845317374', '-38.6781922379903'],
    ['160', '0.780272584431723', '-5.85780384680711', '-4.69281352977363', '69.9847138196725', '-44.5443128572189'],
    ['180', '0.728717080124591', '-5.77939695892167', '-4.69138187401343', '74.7702695572855', '-49.526396482596'],
    ['200', '0.780535660607511', '-5.85746981836918', '-4.69208671398991', '80.4075415416598', '-55.6268229502602'],
]


@pytest.mark.parametrize("options, reference", [
    ((" swap 2", " swap 3 vtarget 1.5"), LAMMPS_SWAPS), (("", ""), LAMMPS_ONE_SWAP)])
def test_thermo_as_lammps(tmp_path, monkeypatch, options, reference):
    script = (FLUID.replace("thermal/conductivity 5 z 10 swap 2", "thermal/conductivity 5 z 10" + options[0])
              .replace("viscosity 10 x z 12 swap 3 vtarget 1.5", "viscosity 10 x z 12" + options[1]))
    _, rows = lammps_thermo(tmp_path, monkeypatch, script)
    assert_thermo_as_lammps(rows, reference, steps=range(0, 201, 20), rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize("line, message", [
    ("fix 1 all thermal/conductivity 10 z 5", "fix: thermal/conductivity: nbin must be even and > 2 (got 5)"),
    ("fix 1 all thermal/conductivity 10 z 2", "fix: thermal/conductivity: nbin must be even and > 2 (got 2)"),
    ("fix 1 all thermal/conductivity 10 w 20", "fix: edim must be one of 'x', 'y' or 'z' (got w)"),
    ("fix 1 all thermal/conductivity 10 z 20 swap 0", "fix: swap must be >= 1 (got 0)"),
    ("fix 1 all viscosity 100 x y 11", "fix: viscosity: nbin must be even and > 2 (got 11)"),
    ("fix 1 all viscosity 100 x y 20 vtarget -1", "fix: vtarget must be > 0 or INF (got -1)"),
    ("fix 1 all viscosity 0 x y 20", "fix: every must be >= 1 (got 0)"),
])
def test_bad_input_is_one_line(make_sim, line, message):
    sim = scene(make_sim, PARTICLES)
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert str(error.value) == f"<command>:1: {message}"


def test_swaps_across_ranks_are_those_of_one(tmp_path):
    """On 2 ranks the two slabs lie on different ranks: the same particles swap, the same f_ID."""
    one, two = thermo_on_ranks(FLUID, tmp_path)
    assert one.shape == (11, 6) and one[-1, 4] != 0 and one[-1, 5] != 0
    np.testing.assert_allclose(two, one, rtol=1e-11, atol=1e-12)
