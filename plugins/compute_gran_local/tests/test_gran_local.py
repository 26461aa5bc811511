"""compute pair/gran/local and contact/atom on a chain of spheres: one row per contact with the
pair style's own forces, torques, overlaps and areas; contacts counted per particle."""

import math

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_refused, liggghts_material

D, RHO = 0.01, 2500.0


def spheres(boundary, material, lines):
    """A 0.1 m box in LIGGGHTS syntax and SI units, pair gran hertz with history; ``lines`` create
    the spheres and go on."""
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(f"""
atom_style granular
boundary {boundary}
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 1 reg
{material}
pair_style gran model hertz tangential history
pair_coeff * *
{lines}
""")
    return sim


def chain(extra=""):
    """Spheres 1-2 and 2-3 overlapping by 1e-4 and 2e-4, 3-4 apart; 2 spinning, 3 moving."""
    material = liggghts_material(5.e6, 0.45, 0.5, 0.5, thermalConductivity=5., thermalCapacity=10.)
    return spheres("f f f", material, f"""
create_atoms 1 single 0 0 0 units box
create_atoms 1 single {D - 1e-4!r} 0 0 units box
create_atoms 1 single {2 * D - 3e-4!r} 0.001 0 units box
create_atoms 1 single {3 * D + 0.01!r} 0 0 units box
set type 1 diameter {D} density {RHO}
set atom 2 omega 0 0 30
set atom 3 vy 0.2
{extra}
""")


def test_rows_hold_the_pair_styles_contacts():
    sim = chain("compute c all pair/gran/local pos vel id force torque history contactArea delta\nrun 0")
    rows = sim.computes["c"].local(sim)
    assert rows.shape == (2, 6 + 6 + 3 + 3 + 3 + 3 + 1 + 1)
    p = sim.particles
    ids = rows[:, 12:14].astype(int)
    assert sorted(map(tuple, np.sort(ids, axis=1))) == [(1, 2), (2, 3)]
    assert (rows[:, 14] == 0).all()
    # forces: on each particle, the sum of its contacts' forces is the pair style's force
    force = rows[:, 15:18]
    for tag in (1, 2, 3, 4):
        total = force[ids[:, 0] == tag].sum(axis=0) - force[ids[:, 1] == tag].sum(axis=0)
        np.testing.assert_allclose(total, p.f[p.index_of_tag(tag)], rtol=1e-12, atol=1e-15)
    # positions, velocities, overlap and intersection area of each row
    for row, (a, b) in zip(rows, ids):
        xi, xj = p.x[p.index_of_tag(a)], p.x[p.index_of_tag(b)]
        np.testing.assert_array_equal(row[0:6], np.concatenate([xi, xj]))
        np.testing.assert_array_equal(row[6:12], np.concatenate([p.v[p.index_of_tag(a)], p.v[p.index_of_tag(b)]]))
        r = np.linalg.norm(xi - xj)
        assert row[25] == pytest.approx(D - r, rel=1e-12)
        assert row[24] == pytest.approx(math.pi * ((D / 2) ** 2 - (r / 2) ** 2), rel=1e-9)
    # torque column: the tangential force's torque on i, lever arm R - delta/2, the same on both
    # spheres of equal size; sphere 1 has one contact and no rolling friction: its whole torque
    k = int(np.flatnonzero((ids == 1).any(axis=1))[0])
    torque_1 = sim.particles.torque[p.index_of_tag(1)]
    assert np.abs(torque_1).max() > 0
    np.testing.assert_allclose(rows[k, 18:21], torque_1, rtol=1e-12)


def test_default_columns_and_heat_flux():
    sim = chain("fix heat all heat/gran initial_temperature 300\nset atom 1 property/atom Temp 400\n"
                "compute c all pair/gran/local\ncompute h all pair/gran/local id heatFlux\nrun 0")
    assert sim.computes["c"].local(sim).shape == (2, 6 + 6 + 3 + 3 + 3 + 3 + 1)
    rows = sim.computes["h"].local(sim)
    p = sim.particles
    flux_into_1 = sum(row[3] if row[0] == 1 else -row[3] for row in rows if 1 in row[:2])
    assert flux_into_1 == pytest.approx(p.arrays["heatFlux"][p.index_of_tag(1)], rel=1e-12)
    assert flux_into_1 < 0


def test_contact_atom_counts_touching_neighbors(tmp_path):
    path = tmp_path / "c.dump"
    sim = chain(f"compute c all contact/atom\ngroup few id 1 2\ncompute g few contact/atom\n"
                f"dump d all custom 1 {path} id c_c c_g\nrun 0")
    rows = sorted(tuple(int(float(w)) for w in line.split()) for line in path.read_text().splitlines()[-4:])
    assert rows == [(1, 1, 1), (2, 2, 2), (3, 1, 0), (4, 0, 0)]


@pytest.mark.parametrize("line, message", [
    ("compute c all pair/gran/local force velocity",
     "compute: columns must be one of 'pos', 'vel', 'id', 'force', 'torque', 'history', 'contactArea', 'delta' or "
     "'heatFlux' (got velocity)"),
])
def test_bad_lines(pdps_cli, line, message):
    assert_refused(pdps_cli(f"atom_style granular\nregion r block 0 1 0 1 0 1\ncreate_box 1 r\n{line}\n"), 4, message)


def test_a_contact_across_a_periodic_boundary():
    """Spheres touching through the periodic x faces: counted once each (the ghost's count summed
    onto its owner), and flagged periodic in the id columns."""
    sim = spheres("p f f", liggghts_material(5.e6, 0.45, 0.5, 0.5), f"""
create_atoms 1 single -0.0451 0 0 units box
create_atoms 1 single 0.0451 0 0 units box
create_atoms 1 single 0 0 0 units box
set type 1 diameter {D} density {RHO}
compute c all contact/atom
compute l all pair/gran/local id delta
run 0
""")
    counts = sim.computes["c"].peratom(sim)[np.argsort(sim.tag)]
    assert list(counts) == [1.0, 1.0, 0.0]
    rows = sim.computes["l"].local(sim)
    assert rows.shape == (1, 4)
    assert rows[0, 2] == 1.0
    assert rows[0, 3] == pytest.approx(D - (0.1 - 2 * 0.0451), rel=1e-9)


def test_no_contacts_is_a_table_of_no_rows_that_dump_local_writes(tmp_path):
    """Before a bed forms no two particles touch: the table has no rows and every column, and dump
    local writes its header with no entries, as LIGGGHTS (it stopped with an internal error at step 0)."""
    dump = tmp_path / "dump.local"
    sim = chain("set atom 2 x 0.02\nset atom 3 x -0.03\n"
                "compute c all pair/gran/local pos vel id force torque history contactArea delta\n"
                f"dump d all local 1 {dump} c_c[1] c_c[13] c_c[26]\nrun 2")
    assert sim.computes["c"].local(sim).shape == (0, 6 + 6 + 3 + 3 + 3 + 3 + 1 + 1)
    text = dump.read_text().split("ITEM: TIMESTEP\n")[1:]
    assert len(text) == 3
    for block in text:
        lines = block.splitlines()
        assert lines[1:3] == ["ITEM: NUMBER OF ENTRIES", "0"]
        assert lines[-1] == "ITEM: ENTRIES c_c[1] c_c[13] c_c[26]"


# LIGGGHTS 3.8.0 on this machine (2026-12-02): four spheres of diameter 1 at x = 1, 1.95, 3.0, 4.2
# (an overlap, a gap of 0.05 inside the skin 0.1, one of 0.2 outside): dump id c_c c_cg
LIGGGHTS_CONTACT_SCENE = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region b block 0 6 0 2 0 2 units box
create_box 1 b
create_atoms 1 single 1 1 1 units box
create_atoms 1 single 1.95 1 1 units box
create_atoms 1 single 3.0 1 1 units box
create_atoms 1 single 4.2 1 1 units box
set group all diameter 1.0 density 2500
neighbor 0.1 bin
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.000001
compute c all contact/atom
compute cg all contact/atom/gran
fix n all nve/sphere


run 0
"""
LIGGGHTS_CONTACTS = [1, 1, 0, 0]


def test_contact_atom_and_contact_atom_gran_as_liggghts(make_sim):
    sim = make_sim(dialect="liggghts")
    sim.command(LIGGGHTS_CONTACT_SCENE)
    order = np.argsort(sim.tag)
    for compute in ("c", "cg"):
        assert sim.computes[compute].peratom(sim)[order].tolist() == LIGGGHTS_CONTACTS


def test_contact_atom_gran_skin_counts_gaps_within_it(make_sim):
    """skin S: a gap of at most S counts (spheres 2 and 3 are 0.05 apart, 3 and 4 0.2)."""
    sim = make_sim(dialect="liggghts")
    sim.command(LIGGGHTS_CONTACT_SCENE.replace("compute cg all contact/atom/gran", "compute cg all contact/atom/gran skin 0.1"))
    order = np.argsort(sim.tag)
    assert sim.computes["cg"].peratom(sim)[order].tolist() == [1, 2, 1, 0]
