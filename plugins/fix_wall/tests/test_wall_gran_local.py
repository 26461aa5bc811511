"""compute wall/gran/local and dump local: the rows of a sphere resting on a primitive wall and on a
mesh (positions, velocities, ids, force = m g, no tangential torque, overlap and contact area of
the geometry), LIGGGHTS's column order whatever the keywords' order, the text frame of dump local
in the LIGGGHTS dialect (columns from 1), and errors.
"""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import liggghts_material, make_box

MASS = math.pi / 6.0
G = 10.0
MATERIAL = liggghts_material(1.0e5, 0.3, 0.5, 0.5, characteristicVelocity=1.0)


def resting(wall, extra="", keywords=""):
    sim = make_box(f"""
        create_particle 1 single 0.3 -0.2 0.49 diameter 1 density 1
        create_particle 1 single -0.5 0.6 2.0 diameter 1 density 1
        group one id 1
        {MATERIAL}
        {extra}
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix w all wall/gran model hooke tangential history {wall}
        compute walls one wall/gran/local {keywords}
        timestep 0.0005
    """, box="-4 4 -4 4 -4 4", particle_style="sphere", boundary="f f f")
    sim.command("run 4000")       # both settled on the wall; the compute's group holds the first
    return sim


@pytest.mark.parametrize("wall, extra, ids", [
    ("primitive type 1 zplane 0.0", "", (0, 0)),
    # (0.3, -0.2) lies on the square's triangle 0, (-1, -1) (1, -1) (1, 1)
    ("mesh n_meshes 1 meshes cad", "fix cad all mesh/surface file {data}/square.stl type 1", (0, 0)),
], ids=["primitive", "mesh"])
def test_a_resting_sphere_gives_one_row(data, wall, extra, ids):
    """One contact of the compute's group (sphere 1; sphere 2 rests on the wall too): pos =
    (contact point below it, particle), vel = (wall 0, ~0), id = (mesh 0, triangle, particle 1),
    force = (0, 0, m g), no tangential torque, contactArea = pi (R^2 - d^2) for the settled height
    d; pos and vel give the wall's side first (LIGGGHTS's order)."""
    sim = resting(wall, extra.format(data=data))
    rows = sim.computes["walls"].local(sim)
    assert rows.shape == (1, 6 + 6 + 3 + 3 + 3 + 3 + 1)
    row = rows[0]
    x = sim.x[0]
    np.testing.assert_allclose(row[3:6], x, atol=1e-12)
    np.testing.assert_allclose(row[0:3], [x[0], x[1], 0.0], atol=1e-12)
    np.testing.assert_allclose(row[6:12], 0.0, atol=1e-6)
    assert row[12:15].tolist() == [ids[0], ids[1], 1.0]
    np.testing.assert_allclose(row[15:18], [0, 0, MASS * G], rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(row[18:21], 0.0, atol=1e-9)
    d = x[2]
    assert row[24] == pytest.approx(math.pi * (0.25 - d * d), rel=1e-12)


def test_keywords_come_in_liggghts_order_and_dump_local_writes_them(tmp_path, liggghts_granular):
    """'delta force id' gives id (3), force (3), delta (1) in that order; dump local in the LIGGGHTS
    dialect writes index and c_walls[1..7] (1-based) as LAMMPS's text frame."""
    sim = liggghts_granular(f"""
        region box block -4 4 -4 4 -4 4
        create_box 1 box
        create_atoms 1 single 0.3 -0.2 0.49
        set atom 1 diameter 1 density 1
        {MATERIAL}
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix w all wall/gran model hooke tangential history primitive type 1 zplane 0.0
        compute walls all wall/gran/local delta force id
        timestep 0.0005
        dump contacts all local 100 {tmp_path}/contacts.txt index c_walls[1] c_walls[3] c_walls[6] c_walls[7]
    """)
    sim.command("run 4000")
    row = sim.computes["walls"].local(sim)[0]
    assert row[0:3].tolist() == [0.0, 0.0, 1.0]
    assert row[5] == pytest.approx(MASS * G, rel=1e-6)
    assert row[6] == pytest.approx(0.5 - sim.x[0, 2], rel=1e-12)
    lines = (tmp_path / "contacts.txt").read_text().splitlines()
    last = lines[lines.index("ITEM: TIMESTEP", len(lines) - 12):]
    assert last[1] == "4000" and last[2:4] == ["ITEM: NUMBER OF ENTRIES", "1"]
    assert last[8] == "ITEM: ENTRIES index c_walls[1] c_walls[3] c_walls[6] c_walls[7]"
    values = [float(v) for v in last[9].split()]
    assert values[:3] == [1.0, 0.0, 1.0]
    assert values[3] == pytest.approx(row[5], rel=1e-15)
    assert values[4] == pytest.approx(row[6], rel=1e-15)


@pytest.mark.parametrize("line, message", [
    ("compute bad all wall/gran/local speed", "columns must be one of 'pos', 'vel', 'id', 'force', 'torque', "
     "'history', 'contactArea', 'delta' or 'heatFlux' (got speed)"),
    ("dump d all local 10 {tmp}/x.txt", "dump local needs at least one attribute"),
    ("dump d all local 10 {tmp}/x.txt v_a", "attribute must be index, c_ID, c_ID[k] or c_ID[*] (got v_a)"),
])
def test_bad_words(tmp_path, line, message):
    sim = make_box(MATERIAL, box="-4 4 -4 4 -4 4", particle_style="sphere", boundary="f f f")
    with pytest.raises(ScriptError) as info:
        sim.command(line.format(tmp=tmp_path))
    assert message in str(info.value)


def test_no_wall_and_a_column_out_of_range_are_named_at_the_run(tmp_path):
    sim = make_box(f"""
        create_particle 1 single 0 0 0.49 diameter 1 density 1
        {MATERIAL}
        compute walls all wall/gran/local force
        dump d all local 10 {tmp_path}/x.txt c_walls[1]
    """, box="-4 4 -4 4 -4 4", particle_style="sphere", boundary="f f f")
    with pytest.raises(ScriptError, match=r"needs exactly one fix wall/gran model \.\.\. \(found none\)"):
        sim.command("run 0")
    sim.command("fix w all wall/gran model hooke tangential history primitive type 1 zplane 0.0")
    sim.command(f"undump d\ndump d all local 10 {tmp_path}/y.txt c_walls[3]")
    with pytest.raises(ScriptError, match=r"c_walls\[3\] is out of range \(compute walls has 3 columns\)"):
        sim.command("run 0")
