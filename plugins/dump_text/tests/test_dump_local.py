"""Dump local: one file per frame with a ``*`` in its name, and ``c_ID[*]`` for every column of a
compute's local data, as LAMMPS writes them (found in review: the ``*`` was taken literally and all
frames went to one file named ``*``; ``c_ID[*]`` was refused). The rows come from compute rigid/local
on two rigid bodies, whose masses and centres of mass are known."""

import numpy as np
import pytest

from pdps_core.api import Simulation

SCENE = """
units lj
atom_style molecular
region box block 0 10 0 10 0 10
create_box 1 box
mass 1 1.0
create_atoms 1 single 2 2 2
create_atoms 1 single 3 2 2
create_atoms 1 single 6 6 6
create_atoms 1 single 7 6 6
create_atoms 1 single 6.5 7 6
set atom 1*2 mol 1
set atom 3*5 mol 2
velocity all set 0.5 0 0
comm_modify cutoff 3.0
fix 1 all rigid/small molecule
compute r all rigid/local 1 mol mass x y z
"""


def frame(path):
    lines = path.read_text().splitlines()
    assert lines[0] == "ITEM: TIMESTEP" and lines[2] == "ITEM: NUMBER OF ENTRIES"
    return int(lines[1]), lines[8].split()[2:], np.array([[float(w) for w in line.split()] for line in lines[9:]])


def test_a_star_writes_a_file_a_frame_and_c_id_star_every_column(tmp_path):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCENE + f"dump d all local 10 {tmp_path}/bodies.*.local index c_r[*]\nrun 20\n")
    sim.close()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bodies.0.local", "bodies.10.local", "bodies.20.local"]
    for step in (0, 10, 20):
        got_step, names, rows = frame(tmp_path / f"bodies.{step}.local")
        assert got_step == step
        assert names == ["index", "c_r[1]", "c_r[2]", "c_r[3]", "c_r[4]", "c_r[5]"]
        rows = rows[np.argsort(rows[:, 1])]
        assert sorted(rows[:, 0].tolist()) == [1.0, 2.0]
        assert rows[:, 1].tolist() == [1.0, 2.0] and rows[:, 2].tolist() == [2.0, 3.0]
        # centres of mass moving at 0.5 along x, dt 0.005
        shift = 0.5 * 0.005 * step
        assert rows[0, 3:] == pytest.approx([2.5 + shift, 2.0, 2.0], abs=1e-12)
        assert rows[1, 3:] == pytest.approx([6.5 + shift, 19.0 / 3.0, 6.0], abs=1e-12)


def test_per_processor_files_are_refused(tmp_path):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    with pytest.raises(Exception) as info:
        sim.command(SCENE + f"dump d all local 10 {tmp_path}/bodies.%.local c_r[1]\n")
    assert "per-processor dump files (% in" in str(info.value)
