"""dump image's bonds, against LAMMPS 22 Jul 2025's pictures of the same chains (recorded by
benchmarks/lammps_references/dump_image_bonds.py; LIGGGHTS 3.8.0 has no bond style): the default
(atom 0.5), type colors and widths (bcolor, bdiam), atom widths, a color-mapped attribute, a group
that holds some chains only in part, bond none none and atom no. Tolerance: every pixel is
LAMMPS's (the renderer's operations are its own, in its order), but where two surfaces lie at the
same depth to the last bit: a pixel keeps the first drawn, which is the lowest id's in pdps (on any
number of ranks) and the first in memory in LAMMPS. With atom no, the end spheres two bonds share at
a particle tie so: 3 pixels of that picture (TIES) are the other bond's color."""

import json
import shutil
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import run_ranks

DATA = Path(__file__).parent / "data"
TABLE = json.loads((DATA / "lammps_bonds.json").read_text())
TIES = {"no_atoms": 3}


def assert_pictures_are_lammps(folder):
    with np.load(DATA / "lammps_bonds.npz") as pictures:
        assert sorted(pictures.files) == sorted(TABLE["cases"])
        for name in pictures.files:
            mine = np.asarray(Image.open(Path(folder) / f"{name}.0.ppm").convert("RGB"))
            differ = np.count_nonzero(np.any(mine != pictures[name], axis=2))
            assert differ == TIES.get(name, 0), f"{name}: {differ} pixels differ from LAMMPS's"


def test_bonds_are_drawn_as_lammps_draws_them(tmp_path, monkeypatch):
    shutil.copy(DATA / "bonds.data", tmp_path)
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(TABLE["script"])
    sim.close()
    assert_pictures_are_lammps(tmp_path)


def test_two_ranks_draw_the_bonds_too(tmp_path):
    """Chains split between ranks: each bond is drawn once, whichever rank holds its partner."""
    shutil.copy(DATA / "bonds.data", tmp_path)
    run_ranks(TABLE["script"], 2, tmp_path, name="in.case", dialect="lammps")
    assert_pictures_are_lammps(tmp_path)


def test_the_bonds_show():
    """The references draw bonds: bond none none differs from the default by the bonds alone."""
    with np.load(DATA / "lammps_bonds.npz") as pictures:
        assert np.count_nonzero(np.any(pictures["default"] != pictures["none"], axis=2)) > 300
        assert np.count_nonzero(np.any(pictures["no_atoms"] != 0, axis=2)) > 300


@pytest.mark.parametrize("line, message", [
    ("dump d all image 1 d.*.ppm type type bond atom", "keyword bond needs 2 value(s) (got 1)"),
    ("dump d all image 1 d.*.ppm type type bond both 0.5", "bond color must be atom, type or none (got both)"),
    ("dump d all image 1 d.*.ppm type type bond atom -1", "bond width must be > 0 (got -1)"),
    ("dump d all image 1 d.*.ppm type type bond type thick",
     "bond width must be a number, atom, type or none (got thick)"),
])
def test_bad_bond_keywords_are_refused(tmp_path, monkeypatch, line, message):
    shutil.copy(DATA / "bonds.data", tmp_path)
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style bond\nboundary p p p\nread_data bonds.data")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value).endswith(f"dump: {message}")
