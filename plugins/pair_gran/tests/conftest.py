"""Running the reference cases (tests/data/NAME.in, NAME.data, NAME.ref, recorded with LAMMPS by
benchmarks/lammps_references/gran.py) in pdps, and the spheres of small hand-made scenes."""

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import recorded_case

DATA = Path(__file__).parent / "data"


def reference(folder, name):
    """{step: (ids, x, v, omega)} of LAMMPS's dump."""
    rows = [line.split() for line in (folder / f"{name}.ref").read_text().splitlines()
            if not line.startswith("#")]
    table = {}
    for row in rows:
        table.setdefault(int(row[0]), []).append([float(w) for w in row[1:]])
    out = {}
    for step, values in table.items():
        values = np.array(values)
        out[step] = (values[:, 0].astype(int), values[:, 1:4], values[:, 4:7], values[:, 7:10])
    return out


def compare_with_lammps(folder, name, tmp_path, replace=(), rtol=1e-12):
    """Every dumped step of LAMMPS against pdps's state after that step: x, v and omega of every
    particle to ``rtol`` of the quantity's scale (positions: the box, velocities and spins: their
    largest magnitude over the run)."""
    record = recorded_case(folder, name, tmp_path, replace)
    table = reference(folder, name)
    steps = sorted(step for step in table if step > 0)
    assert steps and len(record.x) == steps[-1]
    scales = {key: max(np.abs(table[s][k]).max() for s in table) for k, key in ((1, "x"), (2, "v"), (3, "omega"))}
    for step in steps:
        ids, *expected = table[step]
        assert list(ids) == list(range(1, len(ids) + 1))
        for key, want in zip(("x", "v", "omega"), expected):
            got = getattr(record, key)[step - 1]
            np.testing.assert_allclose(got, want, rtol=0, atol=rtol * scales[key],
                                       err_msg=f"{name}: {key} at step {step}")
    return record, table


def data_file(path, particles, box):
    """A sphere data file of particles (type, diameter, density, x, v, omega); the spins are set by
    ``scene`` (pdps reads only vx vy vz of Velocities)."""
    ntypes = max(p[0] for p in particles)
    lo_hi = [float(w) for w in box.split()]
    lines = ["hand-made", "", f"{len(particles)} atoms", f"{ntypes} atom types", ""]
    lines += [f"{lo_hi[2 * d]} {lo_hi[2 * d + 1]} {a}lo {a}hi" for d, a in enumerate("xyz")]
    lines += ["", "Atoms # sphere", ""]
    lines += [f"{tag} {t} {d!r} {rho!r} {x[0]!r} {x[1]!r} {x[2]!r}"
              for tag, (t, d, rho, x, _, _) in enumerate(particles, 1)]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.fixture
def scene(tmp_path):
    """scene(pair_words, particles, extra=...) -> Simulation, the particles' v and omega set."""
    def make(pair, particles, *, box="0 10 0 10 0 10", boundary="p p p", extra="", setup=""):
        path = data_file(tmp_path / "scene.data", particles, box)
        sim = Simulation(screen=False, log=None, dialect="lammps")
        sim.command(textwrap.dedent(f"""\
            units lj
            atom_style sphere
            boundary {boundary}
            {setup}
            read_data {path}
            pair_style {pair}
            pair_coeff * *
            timestep 0.0001
            """) + textwrap.dedent(extra))
        for tag, (_, _, _, _, v, w) in enumerate(particles, 1):
            i = sim.particles.index_of_tag(tag)
            sim.particles.v[i] = v
            sim.particles.omega[i] = w
        return sim
    return make


@pytest.fixture
def lammps_case(tmp_path):
    """lammps_case(name): the reference case run in pdps and compared with LAMMPS's dump."""
    return lambda name, **kwargs: compare_with_lammps(DATA, name, tmp_path, **kwargs)


@pytest.fixture
def granular_case(tmp_path):
    """granular_case(name): a pair granular reference case (data/granular) run in pdps and compared
    with LAMMPS's dump."""
    return lambda name, **kwargs: compare_with_lammps(DATA / "granular", name, tmp_path, **kwargs)
