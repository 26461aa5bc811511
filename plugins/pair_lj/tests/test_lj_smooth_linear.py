"""pair_style lj/smooth/linear (lj/sf): force and energy against the shifted-force formula, both zero
at the cutoff, forces against the energy's gradient, LAMMPS's mixing, the refused tail correction,
and a small LAMMPS run of our own reproduced to 10 significant digits."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import (assert_force_is_minus_gradient, build, forces_by_tag, lammps_thermo, total_force,
                               two_type_cluster)


def phi(r, eps=1.0, sigma=1.0):
    return 4 * eps * ((sigma / r) ** 12 - (sigma / r) ** 6)


def dphi(r, eps=1.0, sigma=1.0):
    return -24 * eps / r * (2 * (sigma / r) ** 12 - (sigma / r) ** 6)


def sf_energy(r, rc, eps=1.0, sigma=1.0):
    return phi(r, eps, sigma) - phi(rc, eps, sigma) - (r - rc) * dphi(rc, eps, sigma)


def sf_force(r, rc, eps=1.0, sigma=1.0):
    """-dE/dr."""
    return -dphi(r, eps, sigma) + dphi(rc, eps, sigma)


@pytest.mark.parametrize("style", ["lj/sf", "lj/smooth/linear"])
@pytest.mark.parametrize("r", [0.95, 1.12, 1.5, 2.4])
def test_two_particles_force_and_energy_match_the_shifted_force_formula(tmp_path, style, r):
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]],
                setup=f"pair_style {style} 2.5\npair_coeff * * 1.0 1.0\nrun 0")
    f = forces_by_tag(sim)
    assert f[1, 0] == pytest.approx(sf_force(r, 2.5), rel=1e-12)
    assert f[0, 0] == -f[1, 0]
    assert sim.pe == pytest.approx(sf_energy(r, 2.5), rel=1e-12)


def test_force_and_energy_go_continuously_to_zero_at_the_pair_cutoff(tmp_path):
    rc = 2.2
    for r, scale in ((rc - 1e-6, 1e-6), (rc - 1e-3, 1e-3)):
        sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]],
                    setup=f"pair_style lj/sf 2.5\npair_coeff * * 0.7 1.1 {rc}\nrun 0")
        # E ~ E''(rc) (rc - r)^2 / 2 and F ~ E''(rc) (rc - r): both vanish at rc
        assert abs(forces_by_tag(sim)[1, 0]) < 0.5 * scale and abs(sim.pe) < 0.5 * scale ** 2
        assert forces_by_tag(sim)[1, 0] == pytest.approx(sf_force(r, rc, 0.7, 1.1), rel=1e-5)
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + rc + 1e-9, 5.0, 5.0]],
                setup=f"pair_style lj/sf 2.5\npair_coeff * * 0.7 1.1 {rc}\nrun 0")
    assert sim.pe == 0.0 and not sim.f.any()


def test_forces_are_minus_the_gradient_of_the_energy_with_two_types_and_a_pair_cutoff(tmp_path):
    sim = two_type_cluster(tmp_path, "pair_style lj/sf 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2\n"
                                     "pair_coeff 1 2 0.8 1.1 2.0")
    assert_force_is_minus_gradient(sim, rel=1e-6, abs=1e-6, largest=1.0)
    assert total_force(sim) == pytest.approx(np.zeros(3), abs=1e-12)


@pytest.mark.parametrize("rule, sigma, rc", [("geometric", math.sqrt(1.0 * 1.3), math.sqrt(2.5 * 2.0)),
                                             ("arithmetic", 1.15, 2.25)])
def test_unset_pairs_mix_epsilon_sigma_and_the_cutoff_as_lammps(tmp_path, rule, sigma, rc):
    eps = math.sqrt(1.0 * 0.6)
    r = 1.4
    modify = "" if rule == "geometric" else "pair_modify mix arithmetic\n"
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]], types=[1, 2],
                setup=f"pair_style lj/sf 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.6 1.3 2.0\n{modify}run 0")
    assert sim.pe == pytest.approx(sf_energy(r, rc, eps, sigma), rel=1e-12)


def test_shift_changes_nothing_and_the_tail_correction_is_refused(tmp_path):
    r = 1.3
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]],
                setup="pair_style lj/sf 2.5\npair_coeff * * 1.0 1.0\npair_modify shift yes\nrun 0")
    assert sim.pe == pytest.approx(sf_energy(r, 2.5), rel=1e-12)
    with pytest.raises(ScriptError, match=r"^<command>:1: pair_modify: pair style lj/sf has no tail correction$"):
        sim.command("pair_modify tail yes")


def test_bad_coefficients_are_refused_with_one_line(tmp_path):
    sim = build(tmp_path, [[4.0, 5.0, 5.0]], setup="pair_style lj/sf 2.5")
    with pytest.raises(ScriptError, match=r"^<command>:1: pair_coeff: sigma must be > 0 \(got -1\)"):
        sim.command("pair_coeff 1 1 1.0 -1")
    with pytest.raises(ScriptError, match=r"^<command>:1: pair_style: cutoff must be > 0 \(got 0\)"):
        sim.command("pair_style lj/sf 0")


# LAMMPS 22 Jul 2025 on this machine, this script (ours): 256 atoms of two types and masses, mixed
# 1-2 coefficients, the 2-2 pair with a cutoff of its own; thermo_modify format float %22.16g.
#   step temp epair etotal press
LAMMPS_LJ_SF = {
    0: (1.44, -4.573531111658466, -2.421968611658467, 1.44886045152013),
    50: (0.7977751784639959, -3.613458383207304, -2.421470079447622, 5.626148811916599),
    100: (0.8138863454197872, -3.637368365209146, -2.421307712384659, 5.877131456869833),
    150: (0.8184205595584063, -3.644240851167699, -2.421405444796252, 5.744303110402532),
    200: (0.838151942157358, -3.673795503998858, -2.421478637298899, 5.308557035413705),
}

LJ_SF_SCRIPT = """
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
velocity all create 1.44 87287 loop geom
pair_style lj/sf 2.5
pair_coeff 1 1 1.0 1.0
pair_coeff 2 2 0.8 1.1 2.2
neighbor 0.3 bin
neigh_modify delay 0 every 1 check yes
timestep 0.005
fix 1 all nve
thermo_style custom step temp epair etotal press
thermo 50
run 200
"""


def test_a_lammps_run_of_two_types_is_reproduced_to_10_digits(tmp_path, monkeypatch):
    _, rows = lammps_thermo(tmp_path, monkeypatch, LJ_SF_SCRIPT)
    assert [int(row[0]) for row in rows] == sorted(LAMMPS_LJ_SF)
    for row in rows:
        assert [float(v) for v in row[1:]] == pytest.approx(LAMMPS_LJ_SF[int(row[0])], rel=1e-10), row[0]
