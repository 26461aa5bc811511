"""Compute temp/ramp: the temperature about a velocity ramp against a hand computation (flat beyond
the ends, lattice and box units, fixes' degrees of freedom), bad arguments refused in one line, and
a LAMMPS run of our own (a ramp thermostatted about by temp/rescale) reproduced to 10 digits."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import build, lammps_thermo

X = [[1.0, 0.5, 1.0], [3.0, 2.0, 1.5], [6.0, 5.0, 4.0], [8.0, 9.5, 6.0], [2.5, 8.0, 3.0]]
V = [[0.3, -0.2, 0.1], [-0.5, 0.4, 0.2], [0.1, 0.1, -0.6], [0.7, -0.3, 0.0], [-0.2, 0.5, 0.4]]
MASSES = {1: 1.0, 2: 3.0}
TYPES = [1, 2, 1, 2, 1]


def by_hand(v_dim, v_lo, v_hi, c_dim, c_lo, c_hi, dof):
    x, v = np.array(X), np.array(V)
    m = np.array([MASSES[t] for t in TYPES])
    fraction = np.clip((x[:, c_dim] - c_lo) / (c_hi - c_lo), 0.0, 1.0)
    thermal = v.copy()
    thermal[:, v_dim] -= v_lo + fraction * (v_hi - v_lo)
    return float(np.sum(m * np.sum(thermal * thermal, axis=1))) / dof


def scene(tmp_path, setup):
    return build(tmp_path, X, v=V, types=TYPES, masses=MASSES, setup=setup)


def test_the_temperature_about_the_ramp_is_the_hand_computed_one_flat_beyond_its_ends(tmp_path):
    # y from 1 to 9: particles 1 (y = 0.5) and 4 (y = 9.5) lie beyond the ends
    sim = scene(tmp_path, "compute tilt all temp/ramp vx -0.4 0.8 y 1 9 units box")
    assert sim.compute_value("tilt") == pytest.approx(by_hand(0, -0.4, 0.8, 1, 1.0, 9.0, 3 * 5 - 3), rel=1e-14)
    sim.command("compute_modify tilt extra/dof 0")
    assert sim.compute_value("tilt") == pytest.approx(by_hand(0, -0.4, 0.8, 1, 1.0, 9.0, 3 * 5), rel=1e-14)


def test_the_vector_is_the_kinetic_tensor_about_the_ramp(tmp_path):
    sim = scene(tmp_path, "compute tilt all temp/ramp vy 0.2 -0.6 z 1 5 units box")
    x, v = np.array(X), np.array(V)
    m = np.array([MASSES[t] for t in TYPES])
    u = v.copy()
    u[:, 1] -= 0.2 + np.clip((x[:, 2] - 1.0) / 4.0, 0.0, 1.0) * (-0.8)
    pairs = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
    expected = [float(np.sum(m * u[:, a] * u[:, b])) for a, b in pairs]
    assert list(sim.computes["tilt"].vector(sim)) == pytest.approx(expected, rel=1e-13)


def test_lattice_units_scale_velocities_and_coordinates_by_the_spacing(tmp_path):
    spacing = 2.0          # lattice sc with reduced density 1/8 in lj units: a = 2
    sim = scene(tmp_path, "lattice sc 0.125\ncompute tilt all temp/ramp vz 0.1 0.3 x 0.5 4 units lattice")
    expected = by_hand(2, 0.1 * spacing, 0.3 * spacing, 0, 0.5 * spacing, 4 * spacing, 12)
    assert sim.compute_value("tilt") == pytest.approx(expected, rel=1e-14)


def test_a_thermostat_given_the_ramp_scales_only_the_velocities_about_it(tmp_path):
    sim = scene(tmp_path, "timestep 0.001\ncompute tilt all temp/ramp vx 0 1.0 y 0 10 units box\n"
                          "fix t all temp/rescale 1 0.25 0.25 0.0 1.0\nfix_modify t temp tilt\nrun 1")
    x = np.array(X)
    assert sim.compute_value("tilt") == pytest.approx(0.25, rel=1e-13)
    # the ramp itself survives: the velocities about it scaled by sqrt(T_target / T)
    order = np.argsort(sim.particles.tag[:5])
    v = sim.particles.v[:5][order]
    ramp = np.zeros((5, 3))
    ramp[:, 0] = x[:, 1] / 10.0
    factor = np.sqrt(0.25 / by_hand(0, 0.0, 1.0, 1, 0.0, 10.0, 12))
    assert v - ramp == pytest.approx(factor * (np.array(V) - ramp), rel=1e-13, abs=1e-15)


@pytest.mark.parametrize("line, message", [
    ("compute c all temp/ramp vw 0 1 y 0 4", "compute: vdim must be one of 'vx', 'vy' or 'vz' (got vw)"),
    ("compute c all temp/ramp vx 0 1 q 0 4", "compute: dim must be one of 'x', 'y' or 'z' (got q)"),
    ("compute c all temp/ramp vx 0 1 y 2 2", "compute: CLO and CHI must differ (got 2 and 2)"),
    ("compute c all temp/ramp vx 0 1 y 0", "compute: missing argument chi; usage: compute ID GROUP temp/ramp "
                                           "vx|vy|vz VLO VHI x|y|z CLO CHI [units box|lattice]"),
    ("compute c all temp/ramp vx 0 1 y 0 4 units reduced", "compute: units must be one of 'box' or 'lattice' "
                                                           "(got reduced)"),
    ("compute c all temp/ramp vx 0 1 y 0 4 bias yes", "compute: unknown keyword bias (known: units)"),
])
def test_bad_arguments_are_refused_with_one_line(tmp_path, line, message):
    sim = scene(tmp_path, "")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value) == f"<command>:1: {message}"


# LAMMPS 22 Jul 2025 on this machine, this script (ours), thermo_modify format float %22.16g:
#   step temp c_tilt c_tiltbox pe etotal c_tilt[1] c_tilt[4] c_tiltbox[2] c_tiltbox[6]
LAMMPS_RAMP = {
    0: (1.95513004565968, 1, 1.056300861447864, -6.77336805325309, -3.852128824874857, 1.036894367857467,
        -0.05114606889594828, 1.011628015005971, 0.01945361593281231),
    50: (1.488284299288956, 1.000000000000001, 1.10940606172492, -5.622645862821058, -3.39893982970377,
         1.43461724018193, 0.129399861808242, 0.8733439157821919, 0.1634694004347833),
    100: (1.388098379137674, 1.000000000000001, 1.180221764503836, -5.456852529575037, -3.382838349808785,
          1.481513143651388, 0.02412863486629256, 0.7744638588505991, -0.01819720502625528),
    150: (1.352195147335101, 1.004740091358175, 1.226136248632081, -5.573133706958242, -3.552764004397007,
          1.578599584541028, -0.1779257546759606, 0.7544530396603877, 0.05386936473517553),
    200: (1.356684292044196, 1.017021498040798, 1.257656611225547, -5.607500515859895, -3.580423399817298,
          1.623719610934122, -0.07479013826328849, 0.7398110260668087, 0.02919524768596903),
}

RAMP_SCRIPT = """
units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
region half block 0 2 INF INF INF INF
set region half type 2
mass 1 1.0
mass 2 2.0
velocity all create 1.0 87287 loop geom
velocity all ramp vx 0 1.5 y 0 4 sum yes
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neighbor 0.3 bin
neigh_modify delay 0 every 1 check yes
timestep 0.005
compute tilt all temp/ramp vx 0 1.5 y 0 4
compute tiltbox all temp/ramp vx 0.0 2.5 y 0.5 5.0 units box
fix 1 all nve
fix 2 all temp/rescale 10 1.0 1.0 0.02 1.0
fix_modify 2 temp tilt
thermo_style custom step temp c_tilt c_tiltbox pe etotal c_tilt[1] c_tilt[4] c_tiltbox[2] c_tiltbox[6]
thermo 50
run 200
"""


def test_a_lammps_ramp_thermostatted_about_is_reproduced_to_10_digits(tmp_path, monkeypatch):
    _, rows = lammps_thermo(tmp_path, monkeypatch, RAMP_SCRIPT)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_RAMP)
    for row in rows:
        # the tensor's small off-diagonal sums carry the round-off of its large terms: 1e-12 absolute
        assert [float(v) for v in row[1:]] == pytest.approx(LAMMPS_RAMP[int(row[0])], rel=1e-10, abs=1e-12), row[0]
