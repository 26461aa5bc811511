"""The langevin keyword of fix rigid, rigid/nve, rigid/small and rigid/nve/small: each body feels -M V / Tperiod plus a random force on
its centre of mass and -I_k w_k / Tperiod plus a random torque about each principal axis, so free
bodies come to the target temperature in translation and in rotation separately. Its drag alone (T =
0) is compared with LAMMPS in test_rigid_lammps.py; here the noise: block averages of each part's
temperature against the target, with their error bar."""

import math

import numpy as np
import pytest

from pdps_core.api import Fix, registry

T_TARGET, PERIOD, DT = 1.5, 1.0, 0.001
NBODY = 64


class BodySampler(Fix):
    """Every 10 steps: sum M V^2 and sum_k I_k w_k^2 of fix 1's bodies (twice their kinetic energies; one
    rank: a rigid/small fix holds them all)."""
    name = "test/bodysampler"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.samples = []

    def end_of_step(self, sim):
        if sim.step % 10:
            return
        rigid = sim.fixes["1"]
        n = getattr(rigid, "nlocal_body", len(rigid.masstotal))
        translation = float((rigid.masstotal[:n, None] * rigid.vcm[:n] ** 2).sum())
        body_omega = np.stack([np.einsum("bd,bd->b", axis[:n], rigid.omega[:n])
                               for axis in (rigid.ex, rigid.ey, rigid.ez)], 1)
        rotation = float((rigid.inertia[:n] * body_omega ** 2).sum())
        self.samples.append((translation, rotation))


def triangles(path):
    """NBODY rigid triangles (sides 1, 1.2, 1.5: three distinct moments) of unit-mass particles at rest,
    randomly turned, on a 4 x 4 x 4 grid 4 apart."""
    rng = np.random.default_rng(11)
    shape = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.2, 1.18, 0.0]])
    shape -= shape.mean(axis=0)
    lines = ["langevin bodies", "", f"{3 * NBODY} atoms", "1 atom types", "", "0 16 xlo xhi", "0 16 ylo yhi",
             "0 16 zlo zhi", "", "Masses", "", "1 1.0", "", "Atoms # molecular", ""]
    tag = 0
    for mol, cell in enumerate(np.mgrid[0:4, 0:4, 0:4].reshape(3, -1).T, start=1):
        q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        for point in shape @ q.T + cell * 4.0 + 2.0:
            tag += 1
            lines.append(f"{tag} {mol} 1 {point[0]:.17g} {point[1]:.17g} {point[2]:.17g}")
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("style", ["rigid", "rigid/nve", "rigid/small", "rigid/nve/small"])
def test_free_bodies_come_to_the_target_temperature_in_translation_and_rotation(make_sim, tmp_path, style):
    """64 free triangles from rest, langevin 1.5 1.5 1.0: after 20 Tperiod, 100 time units of samples
    in 10 blocks of 10 (20 times the kinetic energies' correlation time Tperiod/2): each part's mean
    temperature, sum M V^2 / (3 N k_B) and sum I_k w_k^2 / (3 N k_B), is the target within 4 standard
    errors of the block means (about 0.8 % each; the time step's bias, ~dt / (2 Tperiod) = 5e-4, is
    below it)."""
    registry.register("fix", BodySampler.name, BodySampler)
    triangles(tmp_path / "bodies.data")
    sim = make_sim()
    sim.command(f"""units lj
atom_style molecular
read_data {tmp_path / 'bodies.data'}
timestep {DT}
fix 1 all {style} molecule langevin {T_TARGET} {T_TARGET} {PERIOD} 90125
thermo_style custom step f_1
thermo 100000
run 20000
fix 2 all test/bodysampler
run 100000
""")
    samples = np.array(sim.fixes["2"].samples) / (3 * NBODY)
    blocks = samples[: len(samples) // 10 * 10].reshape(10, -1, 2).mean(axis=1)
    mean = blocks.mean(axis=0)
    error = blocks.std(axis=0, ddof=1) / math.sqrt(len(blocks))
    print(f"{style}: translation T = {mean[0]:.4f} +- {error[0]:.4f}, rotation T = {mean[1]:.4f} +- {error[1]:.4f} "
          f"(target {T_TARGET})")
    assert np.all(np.abs(mean - T_TARGET) < 4 * error)
    assert np.all(error < 0.02 * T_TARGET)          # the test can tell a 3 % error
