"""fix rigid/npt and rigid/nph on a liquid of rigid Lennard-Jones triangles: the barostat brings the mean
pressure, and rigid/npt's chains the bodies' mean temperature, to their targets (block averages with
their error bars); bad settings are one line each. LAMMPS's numbers for these styles are compared in
test_rigid_lammps.py."""

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, registry
from pdps_core.testing import build
from pdps_fix_rigid.rigid import FixRigid

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from rigid import lj_bodies  # noqa: E402  (the LAMMPS scenes' bodies)

T_TARGET, P_TARGET = 1.5, 0.5


class BarostatSampler(Fix):
    """Every 10 steps: fix 1's pressure (what its barostat read this step), its bodies' temperature and
    the volume."""
    name = "test/barostatsampler"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.samples = []

    def end_of_step(self, sim):
        if sim.step % 10 == 0:
            rigid = sim.fixes["1"]
            self.samples.append((rigid.p_current[0], FixRigid.scalar(rigid, sim), sim.box.volume))


def triangles(path, n=4, cell=3.0, seed=11):
    """n^3 rigid triangles (sides 1, 1.2, 1.5) of unit-mass LJ particles, randomly turned, on a grid
    ``cell`` apart, with random velocities."""
    rng = np.random.default_rng(seed)
    shape = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.2, 1.18, 0.0]])
    shape -= shape.mean(axis=0)
    length = n * cell
    atoms, velocities, tag = [], [], 0
    for mol, site in enumerate(np.mgrid[0:n, 0:n, 0:n].reshape(3, -1).T, start=1):
        q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        for point in shape @ q.T + site * cell + 0.5 * cell:
            tag += 1
            v = rng.normal(0.0, 1.2, size=3)
            atoms.append(f"{tag} {mol} 1 {point[0]:.17g} {point[1]:.17g} {point[2]:.17g}")
            velocities.append(f"{tag} {v[0]:.17g} {v[1]:.17g} {v[2]:.17g}")
    lines = ["rigid triangles", "", f"{tag} atoms", "1 atom types", "", f"0 {length} xlo xhi", f"0 {length} ylo yhi",
             f"0 {length} zlo zhi", "", "Masses", "", "1 1.0", "", "Atoms # molecular", "", *atoms, "",
             "Velocities", "", *velocities]
    path.write_text("\n".join(lines) + "\n")


def block_mean(values, blocks=12):
    chunks = values[: len(values) // blocks * blocks].reshape(blocks, -1, *values.shape[1:]).mean(axis=1)
    return chunks.mean(axis=0), chunks.std(axis=0, ddof=1) / math.sqrt(blocks)


def liquid_of_triangles(make_sim, tmp_path):
    """The 64 triangles compressed from a gas to a liquid at T_TARGET, P_TARGET by rigid/npt (Tdamp 0.5,
    Pdamp 2, 6000 steps of dt 0.002); fix test/barostatsampler registered."""
    registry.register("fix", BarostatSampler.name, BarostatSampler)
    triangles(tmp_path / "triangles.data")
    sim = make_sim()
    sim.command(lj_bodies(tmp_path / "triangles.data") + f"""timestep 0.002
fix 1 all rigid/npt molecule temp {T_TARGET} {T_TARGET} 0.5 iso {P_TARGET} {P_TARGET} 2.0
thermo_style custom step temp press vol
thermo 100000
run 6000
""")
    return sim


def test_rigid_npt_holds_the_target_pressure_and_temperature(make_sim, tmp_path):
    """64 triangles compressed from a gas to a liquid at T = 1.5, P = 0.5 (Tdamp 0.5, Pdamp 2): after
    6000 steps, 30000 steps of dt 0.002 in 12 blocks of 5 time units (several barostat periods each):
    the mean pressure the barostat reads and the bodies' mean temperature are the targets within 4
    standard errors of the block means."""
    sim = liquid_of_triangles(make_sim, tmp_path)
    sim.command("fix 2 all test/barostatsampler\nrun 30000")
    samples = np.array(sim.fixes["2"].samples)
    mean, error = block_mean(samples)
    print(f"rigid/npt: pressure {mean[0]:.4f} +- {error[0]:.4f} (target {P_TARGET}), bodies' T {mean[1]:.4f} +- "
          f"{error[1]:.4f} (target {T_TARGET}), volume {mean[2]:.1f} +- {error[2]:.1f}")
    assert abs(mean[0] - P_TARGET) < 4 * error[0] and error[0] < 0.1 * P_TARGET
    assert abs(mean[1] - T_TARGET) < 4 * error[1] and error[1] < 0.02 * T_TARGET


def test_rigid_nph_holds_the_target_pressure(make_sim, tmp_path):
    """The same liquid brought to T = 1.5 by rigid/npt, then rigid/nph alone (aniso, so each axis reads
    its own diagonal pressure) for 24000 steps in 12 blocks: each axis's mean pressure is the target
    within 4 standard errors."""
    sim = liquid_of_triangles(make_sim, tmp_path)
    sim.command(f"""unfix 1
fix 1 all rigid/nph molecule aniso {P_TARGET} {P_TARGET} 2.0
fix 2 all test/barostatsampler
run 24000
""")
    rigid = sim.fixes["1"]
    samples = np.array(sim.fixes["2"].samples)
    print(f"rigid/nph: bodies' T {samples[:, 1].mean():.3f}, volume {samples[:, 2].mean():.1f}, lengths "
          f"{sim.box.length.round(2)}")
    assert rigid.iso is False
    mean, error = block_mean(samples[:, 0])
    print(f"rigid/nph: x pressure {mean:.4f} +- {error:.4f} (target {P_TARGET})")
    assert abs(mean - P_TARGET) < 4 * error and error < 0.1 * P_TARGET


@pytest.mark.parametrize("line, message", [
    ("fix 1 all rigid/nph single temp 1 1 1 iso 1 1 1", "keyword temp of fix rigid/nph: fix rigid/nph controls no "
     "temperature"),
    ("fix 1 all rigid/nph single", "fix rigid/nph needs a pressure: iso, aniso, x, y or z PSTART PSTOP PDAMP"),
    ("fix 1 all rigid/npt single iso 1 1 1", "fix rigid/npt needs temp TSTART TSTOP TDAMP and a pressure"),
    ("fix 1 all rigid/npt single temp 1 1 1", "fix rigid/npt needs temp TSTART TSTOP TDAMP and a pressure"),
    ("fix 1 all rigid/nph single iso -1 1 1", r"iso: target pressures of fix rigid/nph cannot be < 0 \(got -1 1; as "
     r"LAMMPS\)"),
    ("fix 1 all rigid/nph single x 1 1 0", r"x: PDAMP must be > 0 \(got 0\)"),
    ("fix 1 all rigid/npt single temp 1 1 0 iso 1 1 1", r"temp: TSTART must be >= 0, TSTOP and TDAMP > 0"),
    ("fix 1 all rigid/nph single x 1 1 1 couple xy", "couple xy: every coupled axis needs a pressure"),
    ("fix 1 all rigid/nph single x 1 1 1 y 2 2 1 couple xy", "couple xy: coupled axes need the same PSTART PSTOP PDAMP"),
    ("fix 1 all rigid/nph single z 1 1 1", "fix rigid/nph cannot change the non-periodic z length"),
    ("fix 1 all rigid/nph single iso 1 1 1 pchain 0", r"pchain: the barostat chain needs 1 to 1000 thermostats"),
    ("fix 1 all rigid/nph single iso 1 1 1 pchain 100000000", r"pchain: the barostat chain needs 1 to 1000"),
    ("fix 1 all rigid/npt single temp 1 1 1 iso 1 1 1 tparam 3 100000000 3", r"tparam: TCHAIN and TITER must be "
     r"from 1 to 1000"),
    ("fix 1 all rigid/nph single iso 1 1 1 langevin 1 1 1 5", "keyword langevin of fix rigid/nph: fix rigid/nph and "
     "rigid/npt take no langevin"),
    ("fix 1 all rigid/nve single iso 1 1 1", r"keyword iso of fix rigid/nve: only fix rigid/nph and rigid/npt take it"),
])
def test_bad_settings_are_one_line(tmp_path, line, message):
    x = [[4.0, 5.0, 5.0], [5.0, 5.0, 5.0], [5.0, 6.0, 5.0]]
    sim = build(tmp_path, x, boundary="p p f")
    with pytest.raises(ScriptError, match=message):
        sim.command(line)


def test_a_missing_dilate_group_is_one_line(tmp_path):
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [5.0, 5.0, 5.0], [5.0, 6.0, 5.0]],
                setup="fix 1 all rigid/nph single iso 0.1 0.1 1.0 dilate nowhere")
    with pytest.raises(ScriptError, match="nowhere"):
        sim.command("run 0")
