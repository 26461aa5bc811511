"""Region mesh/tet (LIGGGHTS's): the lattice sites strictly inside a tetrahedral mesh, placed by
move, scale and rotate in LIGGGHTS's order. data/cube_six_tets.vtk is the unit cube cut into six
tetrahedra along its diagonal (x <= y <= z and the other five orders), with one triangle cell that
is left out. LIGGGHTS 3.8.0 on this machine (the script SCRIPT below, with this file) created 1001
atoms in the moved, scaled and rotated cube and 504 in the plain half-size cube: the counts the
tests expect, and the formulas (inside one tetrahedron strictly: not on the cube's faces, nor on
the planes x = y, y = z, x = z that the six share)."""

import itertools
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

DATA = Path(__file__).parent / "data"
SCRIPT = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -1 1 -1 1 -1 1 units box
create_box 1 reg
lattice sc 0.05
"""
PLACED = "region mesh mesh/tet file cube_six_tets.vtk scale 0.5 move 0.1 0.2 0.3 rotate 10. 20. 30. units box"
PLAIN = "region mesh mesh/tet file cube_six_tets.vtk scale 0.5 move 0. 0. 0. rotate 0. 0. 0. units box"
LIGGGHTS_COUNTS = {PLACED: 1001, PLAIN: 504}


def rotation(ax, ay, az):
    ax, ay, az = map(math.radians, (ax, ay, az))
    rx = np.array([[1, 0, 0], [0, math.cos(ax), -math.sin(ax)], [0, math.sin(ax), math.cos(ax)]])
    ry = np.array([[math.cos(ay), 0, math.sin(ay)], [0, 1, 0], [-math.sin(ay), 0, math.cos(ay)]])
    rz = np.array([[math.cos(az), -math.sin(az), 0], [math.sin(az), math.cos(az), 0], [0, 0, 1]])
    return rz @ ry @ rx


def expected(move, scale, angles):
    """The sites of the sc 0.05 lattice in the box strictly inside one of the six tetrahedra."""
    sites = np.array(list(itertools.product(np.arange(-20, 21) * 0.05, repeat=3)))
    cube = (sites @ rotation(*angles)) / scale - np.asarray(move)      # R^T p / S - d
    strict = (cube > 1e-12).all(axis=1) & (cube < 1 - 1e-12).all(axis=1)
    apart = ((np.abs(cube[:, 0] - cube[:, 1]) > 1e-12) & (np.abs(cube[:, 1] - cube[:, 2]) > 1e-12)
             & (np.abs(cube[:, 0] - cube[:, 2]) > 1e-12))
    return int((strict & apart).sum())


@pytest.fixture
def folder(tmp_path, monkeypatch):
    shutil.copy(DATA / "cube_six_tets.vtk", tmp_path)
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize("region, placement", [(PLACED, ((0.1, 0.2, 0.3), 0.5, (10, 20, 30))),
                                               (PLAIN, ((0, 0, 0), 0.5, (0, 0, 0)))], ids=["placed", "plain"])
def test_create_atoms_fills_the_sites_liggghts_fills(folder, region, placement):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SCRIPT + region + "\ncreate_atoms 1 region mesh")
    assert sim.nlocal == LIGGGHTS_COUNTS[region] == expected(*placement)
    assert sim.system.regions["mesh"].volume == pytest.approx(0.125, rel=1e-12)


def test_side_out_and_the_warning_for_other_cells(folder):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SCRIPT + PLAIN + " side out")
    region = sim.system.regions["mesh"]
    assert list(region.match(np.array([[0.25, 0.2, 0.1], [0.9, 0.9, 0.9], [0.2, 0.2, 0.1]]))) == [False, True, True]
    assert "cells other than tetrahedra are left out" in sim.output.warnings[-1]


@pytest.mark.parametrize("line, message", [
    (PLAIN.replace(" units box", " units lattice"),
     "give units box (lattice units are not defined for a tetrahedral mesh"),
    (PLAIN.replace("cube_six_tets", "none"), "mesh file none.vtk does not exist"),
    (PLAIN.replace("scale 0.5", "scale 5"), "the mesh of cube_six_tets.vtk reaches outside the simulation box"),
    (PLAIN.replace("scale 0.5", "scale -1"), "scale"),
])
def test_bad_regions(folder, line, message):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SCRIPT)
    with pytest.raises(ScriptError) as info:
        sim.command(line)
    assert message in str(info.value)
