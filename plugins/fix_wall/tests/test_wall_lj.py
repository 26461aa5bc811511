"""Fixes wall/lj93, wall/lj126 and wall/harmonic give LAMMPS's thermo (temp, pe with the walls'
energy, press with their virial, the walls' energy f_ID and the force on each wall f_ID[k]) over 100
steps of a fluid between z walls (data/wall_lj.txt, recorded with LAMMPS by benchmarks/lammps_references/nh.py);
the force is minus the energy's derivative; bad input gets one line.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/wall_lj.cases.json; this file holds the rest."""

import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, total_energy



@pytest.mark.parametrize("style", ["wall/lj93", "wall/lj126"])
def test_force_is_minus_the_energy_gradient(style):
    """One particle at distance d from a zlo wall: F(d) = -(E(d + h) - E(d - h)) / 2h, and E(rc) = 0."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"boundary p p f\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1\n"
                f"create_particle 1 single 5 5 1.3\nfix w all {style} zlo EDGE 1.7 0.9 2.2 units box\n"
                "fix_modify w energy yes\nrun 0")

    def energy_at(z):
        sim.x[0, 2] = z
        sim.command("run 0")
        return total_energy(sim), sim.f[0, 2]

    h = 1e-6
    for d in (0.8, 1.0, 1.6, 2.1):
        (e_plus, _), (e_minus, _), (_, force) = energy_at(d + h), energy_at(d - h), energy_at(d)
        assert force == pytest.approx(-(e_plus - e_minus) / (2 * h), rel=1e-6, abs=1e-9)
    assert energy_at(2.2 - 1e-9)[0] == pytest.approx(0.0, abs=1e-7)


@pytest.mark.parametrize("line, message", [
    ("fix w all wall/lj93 zlo EDGE 1 1", "wall zlo needs coord epsilon sigma cutoff (got EDGE 1 1)"),
    ("fix w all wall/lj93 zlo EDGE 1 1 0", "wall zlo: cutoff must be > 0 (got 0)"),
    ("fix w all wall/lj126 zlo EDGE one 1 2", "wall zlo: epsilon must be a finite number (got one)"),
    ("fix w all wall/lj126 xlo EDGE 1 1 2", "wall xlo stands on the periodic x axis: make it fixed (boundary f) "
                                            "or say pbc yes"),
    ("fix w all wall/lj93 zlo EDGE 1 1 2 zlo 0 1 1 2", "wall zlo is given twice"),
    ("fix w all wall/lj93 zlo EDGE 1 1 2 units metres", "units must be one of 'box' or 'lattice' (got metres)"),
    ("fix w all wall/lj93 floor EDGE 1 1 2", "unknown keyword floor (known: xlo, xhi, ylo, yhi, zlo, zhi, units, pbc)"),
    ("fix w all wall/lj93 units box", "missing argument wall; usage: fix ID GROUP wall/lj93 face coord epsilon "
                                      "sigma cutoff [face ...] [units box|lattice] [pbc yes|no]"),
])
def test_bad_walls(line, message):
    box = "boundary p p f\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1"
    assert script_error(box, line).message == message


def test_a_particle_behind_the_wall_stops_the_run():
    sim = Simulation(screen=False, log=None)
    sim.command("boundary p p f\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1\n"
                "create_particle 1 single 1 1 0.5\nfix w all wall/lj93 zlo 1.0 1 1 2 units box")
    with pytest.raises(Exception) as caught:
        sim.command("run 1")
    assert "fix w (wall/lj93): particle 1 is on or behind wall zlo at step 0" in str(caught.value)
