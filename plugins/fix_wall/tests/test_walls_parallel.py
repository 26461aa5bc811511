"""Mesh and primitive walls give the same run on 1 and 2 ranks: a polydisperse bed settling onto a
wiggling fix mesh/surface/stress floor inside a turning zcylinder (LIGGGHTS's spellings), with the
floor's force (summed over ranks), the kinetic energy, the floor contacts (compute wall/gran/local
with dump local) and the per-face stress (dump mesh/vtk) equal to 1e-9."""

import shutil

import meshio
import numpy as np
import pytest

from pdps_core.testing import liggghts_material, run_ranks, sphere_bed, thermo_rows


def run(tmp_path, data, ranks):
    # polydisperse spheres (d 0.8-1.2) on a loose lattice inside the cylinder, random velocities
    sphere_bed(tmp_path / "bed.data", (6, 6, 3), (-3.25, -3.25, 0.75), (-7, -7, -1), (7, 7, 10), ntypes=2,
               seed=5)
    shutil.copy(f"{data}/square.stl", tmp_path / "square.stl")
    done = run_ranks(f"""\
        atom_style granular
        units lj
        boundary f f f
        comm_modify vel yes
        read_data bed.data
        {liggghts_material((1.0e5, 2.0e5), (0.3, 0.3), (0.5, 0.6, 0.6, 0.5), (0.5, 0.4, 0.4, 0.5))}
        pair_style gran model hertz tangential history
        pair_coeff * *
        timestep 0.0005
        fix floor all mesh/surface/stress file square.stl type 2 scale 6 move 0 0 0.2
        fix shake all move/mesh mesh floor wiggle amplitude 0 0 0.02 period 0.5
        fix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes floor
        fix drum all wall/gran model hertz tangential history primitive type 2 zcylinder 5.5 0 0 shear x 0.5
        fix 1 all nve/sphere
        fix 2 all gravity 10.0 vector 0 0 -1
        compute wl all wall/gran/local id force wall walls
        dump loc all local 2000 contacts.txt c_wl[3] c_wl[4] c_wl[5] c_wl[6]
        dump m all mesh/vtk 2000 mesh*.vtk stress floor
        thermo_style custom step ke f_floor[3] f_floor[4]
        thermo_modify format float %.15g
        thermo 250
        run 2000
        """, ranks, tmp_path)
    lines = (tmp_path / "contacts.txt").read_text().splitlines()
    last = lines[len(lines) - 1 - lines[::-1].index("ITEM: TIMESTEP"):]
    contacts = np.array([line.split() for line in last[9:]], dtype=float)
    stress = meshio.read(tmp_path / "mesh2000.vtk").cell_data["stress"][0]
    return np.array(thermo_rows(done.stdout)), contacts[np.argsort(contacts[:, 0])], stress


def test_same_run_on_1_and_2_ranks(tmp_path, data):
    """Thermo, the floor contacts of compute wall/gran/local (dump local, sorted by particle) and the
    per-face stress of dump mesh/vtk agree."""
    one, contacts_one, stress_one = run(tmp_path, data, 1)
    two, contacts_two, stress_two = run(tmp_path, data, 2)
    assert one[:, 0].tolist() == list(range(0, 2001, 250))
    assert np.all(one[-3:, 2] < 0)                # the bed presses on the floor
    assert two == pytest.approx(one, rel=1e-9, abs=1e-9 * np.abs(one[:, 2]).max())
    assert len(contacts_one) > 10
    np.testing.assert_allclose(contacts_two, contacts_one, rtol=1e-9, atol=1e-9 * np.abs(contacts_one).max())
    np.testing.assert_allclose(stress_two, stress_one, rtol=1e-9, atol=1e-9 * stress_one.max())
