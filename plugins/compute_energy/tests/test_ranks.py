"""On 2 ranks pe/atom and stress/atom give the 1-rank values: the halves tallied on ghosts reach
their owners on the other rank."""

import shutil
from pathlib import Path

import numpy as np

from pdps_core.testing import run_ranks, thermo_rows

DATA = Path(__file__).parent / "data"
SCRIPT = """units lj
atom_style atomic
read_data fluid.data
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
pair_coeff 2 2 0.5 1.2 2.0
compute pea all pe/atom
compute s all stress/atom NULL
compute sums all reduce sum c_pea c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
fix 1 all nve
timestep 0.002
thermo 50
thermo_style custom step pe press c_sums[1] c_sums[2] c_sums[3] c_sums[4] c_sums[5] c_sums[6] c_sums[7]
thermo_modify format float %.15g
dump d all custom 100 atoms.dump id c_pea c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
run 100
"""


def dump_rows(path):
    lines = path.read_text().splitlines()
    frames, k = [], 0
    while k < len(lines):
        if lines[k].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[k + 1])
            start = k + 1 + next(i for i, line in enumerate(lines[k + 1:]) if line.startswith("ITEM: ATOMS")) + 1
            rows = np.array([[float(v) for v in line.split()] for line in lines[start:start + n]])
            frames.append(rows[np.argsort(rows[:, 0])])
            k = start + n
        else:
            k += 1
    return frames


def test_two_ranks_tally_as_one(tmp_path):
    results = {}
    for ranks in (1, 2):
        folder = tmp_path / f"n{ranks}"
        folder.mkdir()
        shutil.copy(DATA / "fluid.data", folder / "fluid.data")
        done = run_ranks(SCRIPT, ranks, folder)
        results[ranks] = (np.array(thermo_rows(done.stdout)), dump_rows(folder / "atoms.dump"))
    (thermo1, frames1), (thermo2, frames2) = results[1], results[2]
    assert thermo1.shape == thermo2.shape and len(thermo1) >= 3
    np.testing.assert_allclose(thermo2, thermo1, rtol=1e-10, atol=1e-10)
    assert len(frames1) == len(frames2) == 2
    for a, b in zip(frames1, frames2):
        assert a.shape == (200, 8)
        np.testing.assert_allclose(b, a, rtol=1e-9, atol=1e-9 * np.abs(a).max())
