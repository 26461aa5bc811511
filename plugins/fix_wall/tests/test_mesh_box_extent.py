"""A shrink-wrapped box encloses the nodes of every fix mesh/surface besides the particles, plus its
margin, as LIGGGHTS's (Fix::box_extent): LIGGGHTS 3.8.0's bounds after ``run 0`` of this scene,
recorded on this machine (thermo_modify format float %.12g), for three boundary settings. The square
mesh spans the box's x and y and is moved 0.02 along x, past the upper x face."""

import pytest

from pdps_core.testing import liggghts_material

FACE = """solid face
facet normal 0 0 1
  outer loop
    vertex -0.1 -0.1 0.3
    vertex 0.1 -0.1 0.3
    vertex 0.1 0.1 0.3
  endloop
endfacet
facet normal 0 0 1
  outer loop
    vertex -0.1 -0.1 0.3
    vertex 0.1 0.1 0.3
    vertex -0.1 0.1 0.3
  endloop
endfacet
endsolid face
"""

SCENE = """atom_style granular
atom_modify map array sort 0 0.0
boundary {boundary}
newton off
communicate single vel yes
units si
region reg block -0.1 0.1 -0.1 0.1 -0.1 0.455 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + liggghts_material(5.e6, 0.45, 0.9, 0.05) + """pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
create_atoms 1 single 0 0 0.2 units box
set atom 1 diameter 0.01 density 2500
fix face all mesh/surface file face.stl type 1 move 0.02 0 0
run 0
"""

# LIGGGHTS 3.8.0: volume, xlo, xhi, ylo, yhi, zlo, zhi
LIGGGHTS = {
    "m m m": (0.024427104444, -0.1, 0.12002, -0.10002, 0.10002, -0.1, 0.455),
    "f s m": (0.02220444, -0.1, 0.1, -0.10002, 0.10002, -0.1, 0.455),
    "m m s": (0.00440616550089, -0.1, 0.12002, -0.10002, 0.10002, 0.1999445, 0.3000555),
}


@pytest.mark.parametrize("boundary", LIGGGHTS)
def test_a_shrink_wrapped_box_takes_in_the_mesh_as_liggghts(make_sim, boundary):
    with open("face.stl", "w") as stl:
        stl.write(FACE)
    sim = make_sim(dialect="liggghts")
    sim.command(SCENE.format(boundary=boundary))
    box = sim.box
    volume = float((box.hi - box.lo).prod())
    bounds = (box.lo[0], box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2])
    assert volume == pytest.approx(LIGGGHTS[boundary][0], rel=1e-11)
    assert bounds == pytest.approx(LIGGGHTS[boundary][1:], rel=1e-11, abs=1e-14)
